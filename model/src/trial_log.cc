// Trial logs in memory: undoing the wrapping of measured angles.
#include "uuvplan/model/trial_log.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace uuvplan::model {

namespace {

constexpr double kPi = 3.14159265358979323846;

// Undoes the wrapping of an angle to (-pi, pi]: wherever two consecutive samples (empty cells
// skipped) differ by more than pi, this and all later samples are shifted by the multiple of
// 2·pi that brings the step back within pi. Returns the number of such jumps.
int Unwrap(std::vector<double>* angle) {
  double previous = std::numeric_limits<double>::quiet_NaN();
  double offset = 0.0;
  int jumps = 0;
  for (double& x : *angle) {
    if (std::isnan(x)) continue;
    const double raw = x;
    const double step = raw - previous;
    if (std::abs(step) > kPi) {  // false while `previous` is NaN
      offset -= 2.0 * kPi * std::round(step / (2.0 * kPi));
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

// Jumps of more than pi between consecutive values (NaN skipped).
int JumpsOverPi(const std::vector<double>& x) {
  double previous = std::numeric_limits<double>::quiet_NaN();
  int jumps = 0;
  for (double v : x) {
    if (std::isnan(v)) continue;
    jumps += std::abs(v - previous) > kPi ? 1 : 0;
    previous = v;
  }
  return jumps;
}

}  // namespace

void UnwrapAngles(TrialLog* log) {
  for (Dof dof : {Dof::kRoll, Dof::kPitch, Dof::kYaw}) {
    std::vector<double>& angle = log->position[Index(dof)];
    // An angle wrapped to (-pi, pi] (or [0, 2pi)) spans at most 2pi: a column that spans more
    // is continuous already, or not in radians (a heading in degrees, whose noise alone steps
    // by more than pi), and unwrapping it would add 2pi at random (input_sanity names degrees).
    const double spread = Spread(angle);
    if (spread > 2.0 * kPi * (1.0 + 1e-9)) {
      const int jumps = JumpsOverPi(angle);
      if (jumps > 0) {
        log->notes.push_back("pos_" + std::string(DofName(dof)) + " spans " +
                             std::to_string(spread) + ", more than 2·pi rad, and steps by more "
                             "than pi " + std::to_string(jumps) +
                             " time(s): not a wrapped angle in rad, not unwrapped");
      }
      continue;
    }
    const int jumps = Unwrap(&angle);
    if (jumps > 0) {
      log->notes.push_back("unwrapped pos_" + std::string(DofName(dof)) + ": " +
                           std::to_string(jumps) + " jump(s) of more than pi rad");
    }
  }
}

}  // namespace uuvplan::model
