// Where a model's free-run simulation goes wrong on measured data, sample group by sample
// group: the evidence diagnosis reads before it names an effect (docs/diagnosis.md).
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/dof.h"

namespace uuvplan::model {

/// Relative error of the simulated speed in one group of samples, Σ|ξ_sim| / Σ|ξ_meas| − 1.
struct ErrorGroup {
  std::string label;      ///< e.g. "thrust negative in vertical-all", "speed above 0.30 m/s"
  double relative = 0.0;  ///< +0.38: the simulation overpredicts the speed by 38%
  double mae = 0.0;       ///< velocity MAE in the group (m/s or rad/s)
  int samples = 0;
};

struct ErrorBreakdown {
  Dof dof = Dof::kSurge;
  std::vector<ErrorGroup> by_thrust;   ///< per mapping and direction of the nominal force
  std::vector<ErrorGroup> by_motion;   ///< per direction of motion
  std::vector<ErrorGroup> by_speed;    ///< low / high speed (split at the median |ξ|)
  std::vector<ErrorGroup> by_command;  ///< small commands (|φ| < 20% of the largest) / others
  double lag_s = 0.0;                  ///< measured velocity lags the simulation by this (s)
  double lag_sigma_s = 0.0;            ///< its σ (jackknife over trials; NaN with one trial)
  /// Trend of the relative speed error over campaign time, and the campaign time between the
  /// first and last trial's middle; NaN when a trial has no `start` (campaign clock unknown).
  double drift_per_hour = 0.0;
  double drift_sigma_per_hour = 0.0;  ///< its σ (least squares; NaN with fewer than 3 trials)
  double campaign_span_h = 0.0;
  double velocity_mae = 0.0;  ///< overall

  /// The label of the small-command group of by_command.
  static constexpr const char* kSmallCommands = "small commands (|phi| < 20% of the largest)";
};

/// The group with the largest |relative| error, or nullptr.
const ErrorGroup* Largest(const std::vector<ErrorGroup>& groups);
/// The group labelled `label`, or nullptr.
const ErrorGroup* Labeled(const std::vector<ErrorGroup>& groups, const std::string& label);

}  // namespace uuvplan::model
