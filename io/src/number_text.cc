#include "uuvplan/io/number_text.h"

#include <charconv>

namespace uuvplan::io {

void AppendGeneral(double value, int digits, std::string* out) {
  char buffer[32];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::general, digits);
  out->append(buffer, end);
}

}  // namespace uuvplan::io
