#include "design/speed_limit.h"

#include <cmath>
#include <sstream>

#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/seed_rules.h"

namespace uuvplan::planner {

double SpeedLimitOf(const model::Vehicle& vehicle, model::Dof dof, const PlannerOptions& options) {
  if (model::IsRotational(dof)) {
    return vehicle.speed_limits.rotation.value_or(options.max_rotation_rate);
  }
  return vehicle.speed_limits.translation.value_or(options.max_translation_speed);
}

std::string_view SpeedLimitKey(model::Dof dof) {
  return model::IsRotational(dof) ? "max_rotation_rate" : "max_translation_speed";
}

std::string SpeedLimitRefusal(const std::string& mapping, int sign, model::Dof dof, double min_abs,
                              double limit, const LowestDrag& drag, bool dead_band_floor) {
  const std::string unit = model::IsRotational(dof) ? "rad/s" : "m/s";
  // The steady speed of min_thrust's least force at the lowest drag (ref 000 eq. 3 at rest:
  // k·v + kq·v² = phi); the limit must exceed it for any force range to remain: 1% above,
  // rounded to 3 digits.
  const double needed = SteadySpeed(drag.k, drag.kq, min_abs);
  std::ostringstream s;
  s << "mapping '" << mapping << "' " << (sign > 0 ? "positive" : "negative") << ": "
    << (dead_band_floor ? "the thrusters' dead band edge" : "min_thrust")
    << " needs |phi| >= " << min_abs << ", which drives " << model::DofName(dof)
    << " beyond the speed limit " << limit << " " << unit << " (" << SpeedLimitKey(dof)
    << ") at the lowest a priori drag (k = " << drag.k << ", kq = " << drag.kq
    << "; the limit is reached at |phi| = " << drag.phi_at_limit << "): ";
  if (std::isfinite(needed) && needed > 0) {
    s << "'" << SpeedLimitKey(dof) << ": " << model::Significant(1.01 * needed, 3) << "' (" << unit
      << ") in the vehicle file, ";
  }
  s << (dead_band_floor ? "a narrower thrust.dead_band" : "a lower min_thrust")
    << " or an a priori drag fit for " << model::DofName(dof) << " would lift it";
  return s.str();
}

}  // namespace uuvplan::planner
