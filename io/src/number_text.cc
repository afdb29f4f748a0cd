#include "uuvplan/io/number_text.h"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace uuvplan::io {

void AppendGeneral(double value, int digits, std::string* out) {
  char buffer[32];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
  out->append(buffer, end);
}

std::string FileNumber(double value) {
  std::string text = ShortestNumber(value);
  int digits = 0;
  for (char c : text.substr(0, text.find_first_of("eE"))) {
    if (c >= '0' && c <= '9' && (digits > 0 || c != '0')) ++digits;
  }
  if (digits <= kFileDigits) return text;
  text.clear();
  AppendGeneral(value, kFileDigits, &text);
  return text;
}

std::string SigmaNumber(double sigma) {
  if (!(sigma > 0) || !std::isfinite(sigma)) return FileNumber(sigma);
  std::string text;
  AppendGeneral(sigma, 2, &text);
  return text;
}

std::string EstimateNumber(double value, double sigma) {
  if (!(sigma > 0) || !std::isfinite(sigma) || !std::isfinite(value)) return FileNumber(value);
  const int place = static_cast<int>(std::floor(std::log10(sigma))) - 2;  // past σ's 2nd digit
  const double unit = std::pow(10.0, place);
  if (std::abs(value) < 0.5 * unit) return "0";
  const int leading = static_cast<int>(std::floor(std::log10(std::abs(value))));
  const int digits = std::clamp(leading - place + 1, 1, kFileDigits);
  std::string text;
  AppendGeneral(value, digits, &text);
  return text;
}

}  // namespace uuvplan::io
