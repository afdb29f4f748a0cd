// The steady speeds a trial may ask of the vehicle (vehicle file keys max_translation_speed,
// max_rotation_rate, docs/formats.md): beyond them the a priori drag fits are extrapolations
// and the tether or the positioning system may not follow. Absent: the planner's defaults
// (PlannerOptions: no translation limit — the pool bounds translations — and 0.35 rad/s).
#pragma once

#include <optional>

namespace uuvplan::model {

struct SpeedLimits {
  std::optional<double> translation;  ///< m/s, > 0
  std::optional<double> rotation;     ///< rad/s, > 0
};

}  // namespace uuvplan::model
