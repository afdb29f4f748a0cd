// Aligned tables (text_table.h).
#include "uuvplan/text/text_table.h"

#include <algorithm>

namespace uuvplan::text {

std::size_t TextWidth(const std::string& text) {
  return static_cast<std::size_t>(std::count_if(text.begin(), text.end(), [](char c) {
    return (static_cast<unsigned char>(c) & 0xC0) != 0x80;
  }));
}

std::string FixedRow(const std::vector<FixedColumn>& columns,
                     const std::vector<std::string>& cells) {
  std::string line;
  for (std::size_t c = 0; c < cells.size(); ++c) {
    const std::size_t width = c < columns.size() ? columns[c].width : 0;
    const std::string pad(width > cells[c].size() ? width - cells[c].size() : 0, ' ');
    const bool right = c < columns.size() && columns[c].right;
    line += right ? pad + cells[c] : cells[c] + pad;
  }
  return line;
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

}  // namespace uuvplan::text
