// Trial logs in memory: undoing the wrapping of measured angles.
#include "uuvplan/model/trial_log.h"

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

}  // namespace

void UnwrapAngles(TrialLog* log) {
  for (Dof dof : {Dof::kRoll, Dof::kPitch, Dof::kYaw}) {
    const int jumps = Unwrap(&log->position[Index(dof)]);
    if (jumps > 0) {
      log->notes.push_back("unwrapped pos_" + std::string(DofName(dof)) + ": " +
                           std::to_string(jumps) + " jump(s) of more than pi rad");
    }
  }
}

}  // namespace uuvplan::model
