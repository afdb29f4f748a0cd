// Numbers in messages: four significant digits unless told otherwise (one formatter for the
// identification's notes and warnings).
#pragma once

#include <sstream>
#include <string>

namespace uuvplan::ident {

inline std::string Fmt(double v, int precision = 4) {
  std::ostringstream os;
  os.precision(precision);
  os << v;
  return os.str();
}

}  // namespace uuvplan::ident
