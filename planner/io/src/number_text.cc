#include "uuvplan/io/number_text.h"

#include <charconv>
#include <cmath>
#include <system_error>

namespace uuvplan::io {

std::string_view TrimBlanks(std::string_view s) {
  while (!s.empty() && (s.front() == ' ' || s.front() == '\t')) s.remove_prefix(1);
  while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r')) {
    s.remove_suffix(1);
  }
  return s;
}

bool ParseNumber(std::string_view text, double* value) {
  const char* first = text.data();
  const char* last = first + text.size();
  if (first != last && *first == '+') {
    ++first;
    if (first != last && *first == '-') return false;
  }
  const auto [end, ec] = std::from_chars(first, last, *value);
  return ec == std::errc() && end == last && first != last && std::isfinite(*value);
}

void AppendGeneral(double value, int digits, std::string* out) {
  char buffer[32];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
  out->append(buffer, end);
}

}  // namespace uuvplan::io
