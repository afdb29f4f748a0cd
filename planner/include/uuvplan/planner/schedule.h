// A test schedule (contract §schedule): the planned trials with their predicted excursion and
// smallest working thrust, and the predicted precision of each DOF's parameters.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/trial_design.h"

namespace uuvplan::planner {

/// The nominal input sampled for replay: phi_n (N or N·m) and the mapping in force
/// at times at most 0.1 s apart, plus both sides of every jump.
struct TrialProfile {
  std::vector<double> t;  ///< s from the trial start
  std::vector<double> force;
  std::vector<std::string> mapping;
};

/// Where the trial starts: `value` in `unit` (m, or deg for a rotation) from `from` (a named
/// wall, or for a rotation the heading at the tether's counter-clockwise end of its travel).
struct StartPosition {
  double value = 0.0;
  std::string unit;
  std::string from;  ///< empty: not planned
};

struct PlannedTrial {
  model::TrialDesign design;
  /// Predicted excursion from the start over the whole a priori box (m or rad): [min, max].
  std::array<double, 2> travel = {0.0, 0.0};
  /// Smallest |tau| of a working thruster over the trial and the box (N).
  double thrust_min = 0.0;
  TrialProfile profile;  ///< empty until the planner samples it (SampleProfile)
  StartPosition start;   ///< where the travel over the box is centred in the pool
};

/// What every predicted σ assumes, printed beside it (docs/planning.md, "Fisher information"
/// and "Initial state").
inline constexpr const char* kPredictedSigmaAssumption =
    "predicted σ are the Cramér–Rao bound of the model as given, with white sensor noise of the "
    "vehicle file's σ, each trial's initial position and velocity estimated with the parameters "
    "as `identify` does (the velocity even where `identify` judges the start at rest and fixes "
    "it: there the prediction is cautious; docs/planning.md, \"Initial state\"); coloured noise "
    "or an unmodelled effect makes the achieved σ larger";

struct PredictedPrecision {
  std::map<std::string, double> sigma;  ///< predicted 1σ per parameter name
  std::string criterion = "D";          ///< D, Ds, A or E
  double criterion_value = 0.0;
  /// What the σ rest on: the planner's own, or what a file read back says it rested on.
  std::string assumption = kPredictedSigmaAssumption;
};

struct Schedule {
  std::vector<PlannedTrial> trials;
  std::map<model::Dof, PredictedPrecision> predicted;
  /// Total pool time (s): trial durations plus the pauses between them.
  double pool_time = 0.0;
};

// Read and written as JSON by the io layer (uuvplan/io/schedule_json.h).

}  // namespace uuvplan::planner
