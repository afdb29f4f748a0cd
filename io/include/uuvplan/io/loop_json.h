// The loop's JSON (docs/cli.md): what `uuvplan loop --json` writes, the parts of it `next
// --json` shares (progress, candidates, predicted σ), and reading it back as the history of
// the loop — series over accumulated pool time: per DOF and parameter, the estimate and its
// achieved σ after each trial, and the σ the planner predicted for the DOF whose trial it was.
#pragma once

#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/planner/loop/design_loop.h"
#include "uuvplan/planner/pool/pool_verdict.h"

namespace uuvplan::io {

/// [{"dof", "trial", "parameter", "sigma_now", "sigma_after", "gain", "trials_to_target",
///   "first_estimate", "negligible"}] (SI; null for +inf).
nlohmann::json CandidatesJson(const std::vector<planner::CandidateGain>& candidates);

/// {<dof>: {"converged", "worst", "worst_percent", "trials", "usable", "status", "precise",
///          "trusted", "doubts", "refusal", "consistency", "interest": {<name>: {"value",
///          "sigma", "percent", "unit", "held", "physical", "flag"}}}} (null: not estimated).
nlohmann::json ProgressJson(const std::vector<planner::DofProgress>& progress);

/// {<dof>: {"sigma": {<name>: s}, "criterion", "value", "assumption"}} as in a schedule's
/// "predicted".
nlohmann::json PredictedJson(model::Dof dof, const planner::PredictedPrecision& predicted);

/// `uuvplan loop --json`: {"iterations": [{"trial", "params", "dof", "source", "start",
/// "pool_time", "predicted", "sigma", "candidates", "new_information", "effects_entered":
/// [{"effect", "detail", "params": {<name>: {"value", "sigma", "unit"}}, "gain"}],
/// "effects_left": [name], "progress",
/// "notes"}], "converged", "pool_time", "status", "exit_status", "message" (read against the
/// verdict, text::LoopEndMessage), "target", "budget", "seed", "diagnose", "diagnose_assumption"
/// (text::DiagnosedModelAssumption, null without diagnosis), "dof_pool_time",
/// "progress", "estimates", "verdict"}.
nlohmann::json LoopResultJson(const planner::LoopResult& result,
                              const planner::LoopOptions& options,
                              const planner::PoolVerdict& verdict, const model::Pool& pool,
                              int exit_status);

/// A loop the pool verdict refused before any trial: no iterations, status "infeasible", the
/// verdict's sentence as its message, and the verdict.
nlohmann::json RefusedLoopJson(const planner::PoolVerdict& verdict, const model::Pool& pool,
                               int exit_status);

struct LoopPoint {
  int iteration = 0;       ///< 1-based
  double pool_time = 0.0;  ///< s, accumulated when the trial ends
  double value = 0.0;      ///< the estimate after the trial (parameter unit)
  double sigma = 0.0;      ///< its achieved σ (NaN when not estimated)
  double predicted = 0.0;  ///< σ the planner predicted for it (NaN: not this DOF's trial)
};

struct LoopTrialRow {
  int iteration = 0;
  std::string id, kind, mapping;
  model::Dof dof = model::Dof::kSurge;
  double duration = 0.0, pool_time = 0.0;    ///< s
  std::vector<std::string> effects_entered;  ///< added to the DOF's model after this trial
  std::vector<std::string> effects_left;     ///< removed from it (loop --diagnose)
};

struct LoopHistory {
  std::string path;
  std::string status, message;
  double target_percent = 0.0;  ///< percentile error 100·σ/|θ| every parameter must reach
  double pool_time = 0.0;       ///< s
  /// What the predicted σ rest on: the last iteration's "predicted" assumption (or
  /// kUnrecordedSigmaAssumption, schedule_json.h, for a file without one).
  std::string predicted_assumption;
  std::vector<LoopTrialRow> trials;
  /// Per DOF, per parameter name: one point per iteration that estimated it.
  std::map<model::Dof, std::map<std::string, std::vector<LoopPoint>>> series;
};

/// Whether the JSON document is a loop's (it has "iterations").
bool IsLoopJson(const std::string& path);

/// Reads a loop JSON; model::InputError naming the file and key when it is not one.
LoopHistory ReadLoopJson(const std::string& path);

}  // namespace uuvplan::io
