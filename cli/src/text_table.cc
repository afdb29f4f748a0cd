// Aligned tables (text_table.h).
#include "uuvplan/cli/text_table.h"

#include <algorithm>
#include <cmath>

#include "uuvplan/model/util/text.h"

namespace uuvplan::cli {

std::size_t TextWidth(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(
      text.begin(), text.end(), [](char c) { return (static_cast<unsigned char>(c) & 0xC0) != 0x80; }));
}

std::string Quantity(double value, const std::string& unit, int digits) {
  if (!std::isfinite(value)) return "-";
  return model::Significant(value, digits) + (unit == "1" ? " (no unit)" : " " + unit);
}

void TextTable::Print(std::ostream& out, const std::string& indent) const {
  std::vector<std::size_t> width(titles_.size(), 0);
  auto widen = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size() && c < width.size(); ++c) {
      width[c] = std::max(width[c], TextWidth(cells[c]));
    }
  };
  widen(titles_);
  for (const auto& row : rows_) widen(row);
  auto line = [&](const std::vector<std::string>& cells) {
    std::string text = indent;
    for (std::size_t c = 0; c < cells.size() && c < width.size(); ++c) {
      text += cells[c];
      if (c + 1 < cells.size()) text += std::string(width[c] - TextWidth(cells[c]) + 2, ' ');
    }
    out << text << "\n";
  };
  line(titles_);
  for (const auto& row : rows_) line(row);
}

}  // namespace uuvplan::cli
