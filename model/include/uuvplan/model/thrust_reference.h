// The reference of the thrust_map effect (effects.h): u = u0·(|u0|/R)^p states the same
// dynamics at any reference R' once the other side of the force balance is rescaled, since
// u0·(|u0|/R)^p = c·u0·(|u0|/R')^p with c = (R'/R)^p: dividing m, the drag (k, kq, k_neg,
// kq_neg), bias, bias_step and every coupling coefficient by c, and the advance-speed loss
// (c_a·√|φ|·ξ) by √c, leaves the motion unchanged. η, the thrust-side effects (lag, dead zone,
// drift), the sensor delay and p itself keep their values. A truth and an estimate with different
// references compare only after this change (the diagnosis takes R as the largest force of its
// data).
#pragma once

#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

/// Restates `model` at thrust reference `reference` (> 0). False, and `model` unchanged, when
/// it has no thrust_map (no thrust_exponent or thrust_reference) or already has that reference.
bool RestateThrustReference(double reference, DofParameters* model);

}  // namespace uuvplan::model
