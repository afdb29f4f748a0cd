// The combined trial of ref 003's coupled horizontal model (model/coupled_model.h), planned as
// any multi-DOF model's (combined_design.h) from this model's start: the rotation pushed one way
// harder than all swings together, so that every thruster keeps its sign while X and Y change
// theirs (on the ASV 60 N·m of yaw offset against 36 N of swings a thruster), the vehicle then
// spinning at ~0.6–1 rad/s over the box and turning about a point instead of crossing the pool;
// surge and sway swung well below that (0.24, 0.31 rad/s). The yaw drag sets the spin rate:
// it is the axis swept inside the box (a surge or sway force at the spin rate, seen from the
// pool, has a constant part that drives the vehicle across it).
#pragma once

#include <vector>

#include "uuvplan/model/coupled_model.h"
#include "uuvplan/planner/design/combined_design.h"

namespace uuvplan::planner {

/// The options of the coupled model's combined trial moving `dofs` (a combined mode).
CombinedDesignOptions CoupledDesignOptions(std::vector<model::Dof> dofs = {
                                               model::kHorizontalDofs.begin(),
                                               model::kHorizontalDofs.end()});

/// What the combined trial's Cramér–Rao σ rest on, printed and written beside them.
inline constexpr const char* kCoupledSigmaAssumption =
    "a lower bound: the vehicle file's surge, sway and yaw sensors with white noise, the "
    "trial's initial state known and an efficient estimator; `identify --model coupled` fits "
    "integral least squares with instruments (seed 003), whose σ are larger, and coloured noise "
    "or an unmodelled effect makes them larger still";

}  // namespace uuvplan::planner
