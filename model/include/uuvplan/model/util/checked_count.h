// Checked conversion of a computed count (samples = duration·rate, steps = duration/step,
// pieces of an interval) to an integer: a double that is NaN, infinite, negative or beyond
// the limit would make the cast undefined behaviour (UBSan float-cast-overflow) and the
// allocation that follows a std::bad_alloc or a hang. Readers bound their inputs first with
// the key in the message (planner/io plausibility); this is the last line, for any path they
// did not foresee.
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/model/work_limits.h"

namespace uuvplan::model {

/// ⌈x⌉ (rounding down what is within 1e-9 of an integer below) as an `Int`, when finite and in
/// [0, limit]; else InputError "<what>: needs <x> (at most <limit>): <hint>".
template <typename Int = long>
Int CheckedCount(double x, const char* what, double limit, const char* hint) {
  // Every integer up to 2^53 is a double: the comparison below is exact.
  const double max_exact =
      std::min({limit, 9007199254740992.0, static_cast<double>(std::numeric_limits<Int>::max())});
  const double n = std::ceil(x - 1e-9);
  if (!(n >= 0 && n <= max_exact)) {
    throw InputError(what, "needs " + Significant(x, 3) + " (at most " + Significant(max_exact, 3) +
                               "): " + hint);
  }
  return static_cast<Int>(n);
}

/// ⌊x⌋ as an `Int`, checked as CheckedCount.
template <typename Int = long>
Int CheckedFloor(double x, const char* what, double limit, const char* hint) {
  return CheckedCount<Int>(std::floor(x + 1e-9), what, limit, hint);
}

}  // namespace uuvplan::model
