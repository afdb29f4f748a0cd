// The rows of the joint one-step least squares (joint_ls.h): a combined trial's log made ready
// (each DOF's velocity smoothed, its thrust held between log rows, knots one Savitzky–Golay
// window apart, a fine grid between them), and the integral rows of the model's equations along
// given velocities.
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <string>
#include <vector>

#include "uuvplan/ident/estimators/joint_ls.h"
#include "uuvplan/ident/prepare/velocity_estimation.h"
#include "uuvplan/model/excitation.h"
#include "uuvplan/model/multi_dof_model.h"
#include "uuvplan/model/trial_log.h"

namespace uuvplan::ident::internal {

/// One trial, per DOF of the model (its index).
struct JointTrialData {
  std::vector<SmoothedSignal> velocity;             ///< smoothed ξ_i
  std::vector<std::vector<double>> force_t, force;  ///< the logged rows (NaN dropped)
  std::vector<double> grid;       ///< knots and the integration sub-steps between them
  std::vector<std::size_t> knot;  ///< grid index of each knot
  int window = 0;                 ///< Savitzky–Golay points used
};

/// "" when the trial is ready in *out; else what the log lacks ("trial 2: no vel_sway column").
std::string PrepareJointTrial(const model::TrialLog& log, int index,
                              const model::MultiDofModel& model, const JointLsOptions& options,
                              JointTrialData* out);

/// The smoothed velocities at the grid times: row k, column i = ξ_i(grid[k]).
Eigen::MatrixXd MeasuredVelocities(const JointTrialData& trial);

/// The velocities the model simulates at θ under the logged thrust from the smoothed ξ at the
/// first knot, at the grid times (an instrument: free of the sensor noise).
Eigen::MatrixXd SimulatedVelocities(const JointTrialData& trial, const model::MultiDofModel& model,
                                    const Eigen::VectorXd& theta, double step_s);

struct JointRows {
  Eigen::MatrixXd H;          ///< rows × np (global θ)
  Eigen::VectorXd y;          ///< ∫φ_i over the row
  std::vector<int> equation;  ///< the DOF index of the row's equation
  std::vector<int> group;     ///< num_dofs·trial + equation: rows of a group share endpoints
};

/// The rows of every trial along the velocities `nu` (one matrix per trial, on its grid): per
/// trial, equation by equation, one row per knot interval.
JointRows BuildJointRows(const model::MultiDofModel& model,
                         const std::vector<JointTrialData>& trials,
                         const std::vector<Eigen::MatrixXd>& nu);

}  // namespace uuvplan::ident::internal
