// Points of the a priori box as vehicles (the three-valued pool verdict): a vehicle
// whose a priori box on a DOF is one point — its inertia bounds and drag prior shrunk to that
// point (added-mass fraction m/rigid − 1 both ways, drag k, kq with rel_sigma 0) — so the
// planner's own schedule and checks, unchanged, say whether a pool hosts that vehicle. The
// verdict judges the box's centre and its (m, drag) corners this way; the loop's validation
// judges the true vehicle (a degenerate box at the truth).
#pragma once

#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/truth.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/parameter_box.h"

namespace uuvplan::planner {

/// One point of a DOF's a priori box: the inertia and the drag (k, kq), a multiple of the
/// drag prior (text::BoxPointLabel words it).
struct BoxPoint {
  double m = 0.0;            ///< kg (kg·m²)
  double k = 0.0;            ///< N·s/m (N·m·s/rad)
  double kq = 0.0;           ///< N·s²/m² (N·m·s²/rad²)
  double drag_factor = 1.0;  ///< k and kq / the prior's (NaN: a point not of the box)
};

/// The centre, then the four (m, drag) corners of the a priori box of `dof` (APrioriBox's
/// m and drag axes with `options`).
std::vector<BoxPoint> VerdictPoints(const model::Vehicle& vehicle, model::Dof dof,
                                    const BoxOptions& options);

/// `vehicle` with the a priori box of `dof` shrunk to `point`.
model::Vehicle VehicleAt(const model::Vehicle& vehicle, model::Dof dof, const BoxPoint& point);

/// The truth's vehicle with the a priori box of every DOF the truth gives m, k and kq for
/// shrunk to the true values: what the verdict says of the pool for that very vehicle.
model::Vehicle VehicleOfTruth(const model::Truth& truth);

}  // namespace uuvplan::planner
