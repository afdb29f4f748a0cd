// The thruster constraints of a trial (ref 000 §III-B): every working thruster's force
// tau_i = share_i·phi_n(t) keeps its sign and stays above the vehicle's min_thrust for the whole
// trial (no propeller reversal, no dead band: Δφ <= φ̂ in eq. 15; the floor is the larger of
// min_thrust and the thrust at a dead band's edge, model::Vehicle::WorkingThrustFloor), and stays
// within what the thruster gives over its command range (thruster models of ref 000 eq. 6 / ref 002
// eq. 1). A thruster idle in a segment (share 0 in that segment's mapping) is not working there; a
// thruster that works in several segments must push the same way in all of them, unless it is
// built to reverse (model::Thruster::reversible): then only min_thrust and its range bind.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/excitation.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::planner {

/// Admissible |phi_n| for a mapping used in one direction (sign +1 or -1) for a whole run.
struct ForceRange {
  bool feasible = false;
  double min_abs = 0.0;  ///< WorkingThrustFloor / min_i |share_i| (no dead band, no reversal)
  double max_abs = 0.0;  ///< min_i thrust limit of i in its direction / |share_i|
  std::string reason;    ///< why infeasible
};

/// What bounds a working thruster's |tau| from below (Vehicle::WorkingThrustFloor): the key
/// "min_thrust", or the dead band that lies above it.
std::string FloorName(const model::Vehicle& vehicle);

ForceRange DirectionForceRange(const model::Vehicle& vehicle, int mapping, int sign);

struct ThrustCheck {
  double thrust_min = 0.0;        ///< smallest |tau| of a working thruster over the trial (N)
  double thrust_max_ratio = 0.0;  ///< largest |tau| / limit of a working thruster
  bool reversal = false;
  bool below_min = false;
  bool overload = false;
  std::vector<std::string> reasons;  ///< one sentence per violated constraint, with figures
  bool ok() const { return reasons.empty(); }
};

/// Checks phi_n(t) of `input` over [0, duration] on a fine grid (4000 points and both sides of
/// every breakpoint) against the thruster constraints.
ThrustCheck CheckThrust(const model::Vehicle& vehicle, const model::Excitation& input,
                        double duration);

}  // namespace uuvplan::planner
