// How the virtual pool logs a trial (virtual_pool.h): sensor sample times at a declared rate,
// noisy samples with drop-outs and multipath outliers (ref 000 Fig. 14), the commands held at
// the controller's rate, and the merge of every grid into the log's rows. Shared by the 1-DOF
// trials and the combined ones of a multi-DOF model (virtual_pool.cc).
#pragma once

#include <Eigen/Dense>
#include <random>
#include <vector>

#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/trial_log.h"
#include "uuvplan/model/truth.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model::internal {

/// k/rate_hz for k = 0, 1, … up to `duration` (checked against the work limits).
std::vector<double> SampleTimes(double rate_hz, double duration);

/// An angle wrapped to (-pi, pi].
double WrapAngle(double a);

/// Noisy samples with drop-outs (NaN) and multipath outliers. The noise is AR(1),
/// e_i = ρ·e_{i−1} + √(1 − ρ²)·σ·n_i with e_0 = σ·n_0 (stationary; ρ = 0: white).
std::vector<double> Corrupt(const Eigen::VectorXd& clean, const SensorSpec& spec,
                            const SensorDefects& defects, std::mt19937_64& rng);

/// The sorted union of time grids (times closer than 1 ns are one row).
std::vector<double> MergeTimes(const std::vector<std::vector<double>>& grids);

/// Values `v` at times `t` placed on `rows` (NaN elsewhere).
std::vector<double> OnRows(const std::vector<double>& rows, const std::vector<double>& t,
                           const std::vector<double>& v);

/// The commands as logged: at the controller rate, held between rows; every change of a
/// segment is a row.
struct Commands {
  std::vector<double> t, force;
  std::vector<int> mapping;
};
Commands HeldCommands(const Vehicle& v, const TrialDesign& design, double rate_hz);

/// The mapping column, only when the commanded mapping changes during the trial.
void LogMappingColumn(const Vehicle& v, const Commands& cmd, TrialLog* log);

}  // namespace uuvplan::model::internal
