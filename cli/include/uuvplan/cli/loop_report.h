// Printing and JSON shared by `next` and `loop` (planner/loop/design_loop.h): one trial on one line,
// the parameters of interest of each DOF against the target, and their JSON forms.
#pragma once

#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <vector>

#include "uuvplan/model/truth.h"
#include "uuvplan/planner/loop/design_loop.h"
#include "uuvplan/planner/schedule.h"

namespace uuvplan::cli {

/// Exit statuses of `next` and `loop` beyond the common 0/1/2 (docs/cli.md): the budget ran
/// out, the DOFs left are stuck (no trial adds information), convergence refused (estimates
/// inconsistent, non-physical or failing validation).
inline constexpr int kExitBudgetSpent = 4;
inline constexpr int kExitStuck = 5;
inline constexpr int kExitRefused = 6;
int ExitStatus(planner::LoopStatus s);
int ExitStatus(planner::NextStatus s);

/// "m 912.6 kg ± 31.2 (3.42%)" with the parameter's unit, flags for held and non-physical.
std::string InterestText(model::Dof dof, const planner::InterestParameter& q, double target);

/// [{"dof", "trial", "parameter", "sigma_now", "sigma_after", "gain", "trials_to_target",
///   "negligible"}] (SI; null for +inf).
nlohmann::json CandidatesJson(const std::vector<planner::CandidateGain>& candidates);

/// "sine  surge-front  120.0 s  35.0 ± 25.0 N, T 26.0 s" — kind, mapping, duration, force.
std::string TrialLine(const model::TrialDesign& d);

/// Per DOF: each parameter of interest with value ± σ and percentile error against the target;
/// with `truth`, also the true value and the error of the estimate.
void PrintProgress(const std::vector<planner::DofProgress>& progress, double target_percent,
                   std::ostream& out, const model::Truth* truth = nullptr);

/// {<dof>: {"converged", "worst", "worst_percent", "trials", "usable", "status",
///          "interest": {<name>: {"value", "sigma", "percent"}}}} (null for not estimated).
nlohmann::json ProgressJson(const std::vector<planner::DofProgress>& progress);

/// {<dof>: {"sigma": {<name>: s}, "criterion", "value", "assumption"}} as in a schedule's
/// "predicted".
nlohmann::json PredictedJson(model::Dof dof, const planner::PredictedPrecision& p);

}  // namespace uuvplan::cli
