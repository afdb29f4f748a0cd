// Numbers in the planner's messages and notes: `precision` significant digits, as an
// std::ostream prints them by default ("0.0523", "1.2e+03").
#pragma once

#include <sstream>
#include <string>

namespace uuvplan::planner::internal {

inline std::string Fmt(double v, int precision = 3) {
  std::ostringstream os;
  os.precision(precision);
  os << v;
  return os.str();
}

}  // namespace uuvplan::planner::internal
