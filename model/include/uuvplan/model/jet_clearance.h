// Whether a thruster works in open water (installation coefficient eta = 1, ref 000 §II-A):
// the rule that replaces ref 000 Table I's judgement ("the motion direction where the
// propeller can be assumed to work in open water without remarkable interactions with the
// vehicle hull and other propellers") when mappings are derived from the geometry.
//
// Rule (CHOSEN): a thruster pushing with sign s sends its jet along −s·d from its position r.
// The jet is obstructed when its axis passes downstream (projection > 0) within the clearance c
// of another thruster's position or of the vehicle's centre (the origin, where a closed hull's
// body is). With c the mean half-side of the size box, ROMEO's geometry (thrusters at
// (±0.55, ±0.35) m, 45°) gives Table I's open-water column: a jet across the 0.7 m width passes
// the neighbouring thruster at 0.49 m (obstructed), one along the 1.1 m length at 0.78 m (clear).
#pragma once

#include <array>
#include <vector>

#include "uuvplan/model/mapping.h"
#include "uuvplan/model/thruster.h"

namespace uuvplan::model {

/// The mean half-side of the size box, (length + width + height)/6 (m).
double DefaultJetClearance(const std::array<double, 3>& size);

/// True when thruster `index` pushing with the sign of `thrust_sign` has an unobstructed jet.
/// Thrusters without geometry neither obstruct nor are judged (true).
bool JetIsClear(const std::vector<Thruster>& thrusters, int index, double thrust_sign,
                double clearance);

/// The directions of phi in which every thruster of `shares` (tau_i = share_i·phi) has a clear
/// jet: positive, negative, both or none.
OpenWater OpenWaterOf(const std::vector<std::pair<int, double>>& shares,
                      const std::vector<Thruster>& thrusters, double clearance);

}  // namespace uuvplan::model
