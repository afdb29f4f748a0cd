// The special values every layer writes as constants: a missing number (NaN) and an unbounded
// one (infinity).
#pragma once

#include <limits>

namespace uuvplan::model {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

}  // namespace uuvplan::model
