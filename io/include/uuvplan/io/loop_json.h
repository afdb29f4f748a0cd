// Reading back what `uuvplan loop --json` wrote (docs/cli.md): the history of the loop as
// series over accumulated pool time — per DOF and parameter, the estimate and its achieved σ
// after each trial, and the σ the planner predicted for the DOF whose trial it was.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"

namespace uuvplan::io {

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
  double duration = 0.0, pool_time = 0.0;  ///< s
};

struct LoopHistory {
  std::string path;
  std::string status, message;
  double target_percent = 0.0;  ///< percentile error 100·σ/|θ| every parameter must reach
  double pool_time = 0.0;       ///< s
  /// What the predicted σ rest on: the last iteration's "predicted" assumption (or
  /// planner::kUnrecordedSigmaAssumption for a file written before it was recorded).
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
