// The speed limit of a DOF's designs: the vehicle file's max_translation_speed /
// max_rotation_rate (model/speed_limits.h) when given, else PlannerOptions' default; and the
// refusal when min_thrust's least force already exceeds it, naming the key and the value that
// would lift it.
#pragma once

#include <string>
#include <string_view>

#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/dof_planning_problem.h"

namespace uuvplan::planner {

/// The largest steady speed (m/s or rad/s) a design of `dof` may ask for; 0: no limit.
double SpeedLimitOf(const model::Vehicle& vehicle, model::Dof dof, const PlannerOptions& options);

/// "max_rotation_rate" for a rotation, "max_translation_speed" for a translation.
std::string_view SpeedLimitKey(model::Dof dof);

/// The drag at which a force reaches the limit first: the lowest of the a priori box.
struct LowestDrag {
  double k = 0.0, kq = 0.0;
  double phi_at_limit = 0.0;  ///< |phi| = k·v + kq·v² at the limit v
};

/// "mapping 'M' positive: min_thrust needs |phi| >= A, which drives yaw beyond the speed limit
/// 0.35 rad/s (max_rotation_rate) ...: max_rotation_rate: V in the vehicle file ... would lift
/// it", V the steady speed min_thrust's |phi| reaches at the lowest drag, rounded up. With
/// `dead_band_floor` the floor is a thruster's dead band edge (Vehicle::WorkingThrustFloor) and
/// the sentence names thrust.dead_band instead.
std::string SpeedLimitRefusal(const std::string& mapping, int sign, model::Dof dof, double min_abs,
                              double limit, const LowestDrag& drag, bool dead_band_floor);

}  // namespace uuvplan::planner
