// Numbers in the planner's messages and notes: `precision` significant digits, as an
// std::ostream prints them by default ("0.0523", "1.2e+03").
#pragma once

#include <string>

#include "uuvplan/model/util/text.h"

namespace uuvplan::planner::internal {

inline std::string Fmt(double v, int precision = 3) { return model::Significant(v, precision); }

}  // namespace uuvplan::planner::internal
