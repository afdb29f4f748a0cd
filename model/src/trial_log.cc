// Trial logs in memory: undoing the wrapping of measured angles.
#include "uuvplan/model/trial_log.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace uuvplan::model {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Undoes the wrapping of an angle to a `period` (2·pi: (-pi, pi]): wherever two consecutive
// samples (empty cells skipped) differ by more than half the period, this and all later
// samples are shifted by the multiple of the period that brings the step back within half of
// it. Returns the number of such jumps.
int Unwrap(std::vector<double>* angle, double period) {
  double previous = std::numeric_limits<double>::quiet_NaN();
  double offset = 0.0;
  int jumps = 0;
  for (double& x : *angle) {
    if (std::isnan(x)) continue;
    const double raw = x;
    const double step = raw - previous;
    if (std::abs(step) > 0.5 * period) {  // false while `previous` is NaN
      offset -= period * std::round(step / period);
      ++jumps;
    }
    previous = raw;
    x = raw + offset;
  }
  return jumps;
}

// The smallest and largest value of a column (NaN skipped; lo > hi when it has none).
struct Range {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  bool Within(double a, double b) const { return lo >= a && hi <= b; }
};
Range RangeOf(const std::vector<double>& x) {
  Range r;
  for (double v : x) {
    if (!std::isnan(v)) r.lo = std::min(r.lo, v), r.hi = std::max(r.hi, v);
  }
  return r;
}

// Whether a column's values lie where an angle wrapped to one turn (`turn`: 2·pi or 360) does,
// (−turn/2, turn/2] or [0, turn), with `slack` for printed rounding (±3.1416 of a 4-decimal
// log is past pi).
bool WrappedTo(const Range& r, double turn, double slack) {
  return r.Within(-0.5 * turn - slack, 0.5 * turn + slack) || r.Within(-slack, turn + slack);
}

// Jumps of more than `size` between consecutive values (NaN skipped).
int JumpsOver(const std::vector<double>& x, double size) {
  double previous = std::numeric_limits<double>::quiet_NaN();
  int jumps = 0;
  for (double v : x) {
    if (std::isnan(v)) continue;
    jumps += std::abs(v - previous) > size ? 1 : 0;
    previous = v;
  }
  return jumps;
}

}  // namespace

void UnwrapAngles(TrialLog* log) {
  for (Dof dof : {Dof::kRoll, Dof::kPitch, Dof::kYaw}) {
    std::vector<double>& angle = log->position[Index(dof)];
    // An angle wrapped to one turn lies in (-pi, pi] or [0, 2pi). A column outside both is
    // continuous already, or not in radians: a heading in degrees, whose noise alone can step
    // by more than pi (unwrapping it by 2pi would add 2pi at random), is unwrapped by 360 when
    // it lies in (-180, 180] or [0, 360) and jumps by more than 180 (input_sanity then names
    // degrees); anything else is left as logged.
    const std::string name = "pos_" + std::string(DofName(dof));
    const Range range = RangeOf(angle);
    if (!WrappedTo(range, 2.0 * kPi, 1e-3)) {
      if (WrappedTo(range, 360.0, 0.05) && JumpsOver(angle, 180.0) > 0) {
        const int jumps = Unwrap(&angle, 360.0);
        log->notes.push_back("unwrapped " + name +
                             " as degrees (its values lie outside one "
                             "turn in rad and wrap at 360): " +
                             std::to_string(jumps) + " jump(s) of more than 180");
      }
      continue;
    }
    const int jumps = Unwrap(&angle, 2.0 * kPi);
    if (jumps > 0) {
      log->notes.push_back("unwrapped " + name + ": " + std::to_string(jumps) +
                           " jump(s) of more than pi rad");
    }
  }
}

}  // namespace uuvplan::model
