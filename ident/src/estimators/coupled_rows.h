// The rows of the coupled one-step least squares (coupled_ls.h): a combined-mode trial log made
// ready (smoothed u, v, r, held thrust, knots one Savitzky–Golay window apart, a fine grid
// between them), and the integral rows of its three equations along given velocities.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "uuvplan/ident/estimators/coupled_ls.h"
#include "uuvplan/ident/prepare/velocity_estimation.h"
#include "uuvplan/model/coupled_model.h"
#include "uuvplan/model/excitation.h"
#include "uuvplan/model/trial_log.h"

namespace uuvplan::ident::internal {

struct CoupledTrialData {
  std::array<SmoothedSignal, 3> velocity;              ///< smoothed u, v, r
  std::array<std::unique_ptr<model::Excitation>, 3> thrust;  ///< τ_i held between log rows
  std::array<std::vector<double>, 3> force_t, force;  ///< the logged rows (NaN dropped)
  std::vector<double> grid;      ///< knots and the integration sub-steps between them
  std::vector<std::size_t> knot; ///< grid index of each knot
  int window = 0;                ///< Savitzky–Golay points used
};

/// "" when the trial is ready in *out; else what the log lacks ("trial 2: no vel_sway column").
std::string PrepareCoupledTrial(const model::TrialLog& log, int index,
                                const CoupledLsOptions& options, CoupledTrialData* out);

/// The smoothed velocities at the grid times.
std::vector<model::Horizontal> MeasuredVelocities(const CoupledTrialData& trial);

/// The velocities `model` simulates under the logged thrust from the smoothed ν at the first
/// knot, at the grid times (an instrument: free of the sensor noise).
std::vector<model::Horizontal> SimulatedVelocities(const CoupledTrialData& trial,
                                                   const model::CoupledHorizontalModel& model,
                                                   double step_s);

struct CoupledRows {
  Eigen::MatrixXd H;          ///< rows × 12 (θ layout of coupled_model.h)
  Eigen::VectorXd y;          ///< ∫τ_i over the row
  std::vector<int> equation;  ///< 0 surge, 1 sway, 2 yaw
  std::vector<int> group;     ///< 3·trial + equation: rows of a group share endpoints
};

/// The rows of every trial along the velocities `nu` (one vector per trial, on its grid):
/// per trial, equation by equation, one row per knot interval.
CoupledRows BuildCoupledRows(const std::vector<CoupledTrialData>& trials,
                             const std::vector<std::vector<model::Horizontal>>& nu);

}  // namespace uuvplan::ident::internal
