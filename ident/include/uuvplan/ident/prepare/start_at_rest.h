// Whether a trial starts at rest: the output error then fixes its initial velocity at 0, else it
// estimates it with θ (ref 000 eqs. 16-19 fit m·ξ0 with the parameters).
#pragma once

#include <limits>

#include "uuvplan/ident/prepare/trial_data.h"

namespace uuvplan::ident {

/// With a velocity sensor: the mean of the first velocity samples (at least 0.2 s) is within 3σ
/// of zero. From positions: the initial velocity of a quadratic through the filter's window of
/// first positions (at least 7 samples) is within 3σ of zero. That resolves only what those few
/// samples can (5 cm/s at 1 cm and 100 Hz); the output error tests the starts it was told are at
/// rest against the whole fit (output_error.h, InitialVelocity::kAuto).
/// `velocity` (m/s or rad/s), for a trial that starts moving, is the initial velocity of a cubic
/// through the longest window of first positions, doubling from the filter's, where a quartic
/// term is not significant (3σ) and no command step has come: far less noisy than the filter's
/// edge value (NaN when that window is the filter's). Reads position, position_sigma,
/// sg_window, force_jumps, velocity and velocity_sigma of `d`.
struct TrialStart {
  bool at_rest = true;
  double velocity = std::numeric_limits<double>::quiet_NaN();
};
TrialStart JudgeStart(const TrialData& d);

}  // namespace uuvplan::ident
