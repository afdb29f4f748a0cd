// What `next` and `loop` print of the loop's progress (planner/loop/design_loop.h): the
// parameters of interest of each DOF against the target, in a line or a table per DOF.
#pragma once

#include <ostream>
#include <string>
#include <vector>

#include "uuvplan/model/truth.h"
#include "uuvplan/planner/loop/design_loop.h"

namespace uuvplan::text {

/// "m 912.6 kg ± 31.2 (3.42%)" with the parameter's unit, flags for held and non-physical.
std::string InterestText(model::Dof dof, const planner::InterestParameter& q, double target);

/// "thruster_lag added to the yaw model: lag 0.148 ± 0.012 s; velocity MAE 21% lower on
/// cross-validation" (`loop --diagnose`).
std::string EffectEnteredText(model::Dof dof, const planner::EffectEntered& e);

/// "sensor_delay removed from the yaw model: the diagnosis of every trial so far no longer
/// finds it".
std::string EffectLeftText(model::Dof dof, const std::string& effect);

/// What the estimates of `loop --diagnose` rest on: the model is the one the diagnosis of the
/// loop's trials found, and effects alike on slow responses may be taken for each other.
std::string_view DiagnosedModelAssumption();

/// Per DOF: each parameter of interest with value ± σ and percentile error against the target;
/// with `truth`, also the true value and the error of the estimate.
void PrintProgress(const std::vector<planner::DofProgress>& progress, double target_percent,
                   std::ostream& out, const model::Truth* truth = nullptr);

}  // namespace uuvplan::text
