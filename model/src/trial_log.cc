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

// The spread max − min of a column's values (NaN skipped; 0 when empty).
double Spread(const std::vector<double>& x) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (double v : x) {
    if (!std::isnan(v)) lo = std::min(lo, v), hi = std::max(hi, v);
  }
  return hi >= lo ? hi - lo : 0.0;
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

// The largest |value| of a column (NaN skipped).
double Largest(const std::vector<double>& x) {
  double m = 0.0;
  for (double v : x) {
    if (!std::isnan(v)) m = std::max(m, std::abs(v));
  }
  return m;
}

}  // namespace

void UnwrapAngles(TrialLog* log) {
  for (Dof dof : {Dof::kRoll, Dof::kPitch, Dof::kYaw}) {
    std::vector<double>& angle = log->position[Index(dof)];
    // An angle wrapped to (-pi, pi] (or [0, 2pi)) spans at most 2pi. A column that spans more
    // is continuous already, or not in radians: a heading in degrees, whose noise alone can
    // step by more than pi (unwrapping it by 2pi would add 2pi at random), is unwrapped by 360
    // when it stays within ±180 and jumps by more than 180 (input_sanity then names degrees).
    const std::string name = "pos_" + std::string(DofName(dof));
    if (Spread(angle) > 2.0 * kPi * (1.0 + 1e-9)) {
      if (Largest(angle) <= 180.0 * (1.0 + 1e-9) && JumpsOver(angle, 180.0) > 0) {
        const int jumps = Unwrap(&angle, 360.0);
        log->notes.push_back("unwrapped " + name + " as degrees (it spans more than 2·pi and "
                             "wraps at ±180): " + std::to_string(jumps) +
                             " jump(s) of more than 180");
      }
      continue;
    }
    const int jumps = Unwrap(&angle, 2.0 * kPi);
    if (jumps > 0) {
      log->notes.push_back("unwrapped pos_" + std::string(DofName(dof)) + ": " +
                           std::to_string(jumps) + " jump(s) of more than pi rad");
    }
  }
}

}  // namespace uuvplan::model
