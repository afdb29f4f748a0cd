// Internal to the output error (output_error.h): the least-squares problem over
// z = [θ_free, each trial's estimated initial state], its residuals and their Jacobian.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <vector>

#include "estimators/output_error_trial.h"
#include "uuvplan/ident/estimators/block_least_squares.h"
#include "uuvplan/ident/estimators/output_error.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/simulator.h"

namespace uuvplan::ident::internal {

// Every parameter within the range its family allows a fit (model/parameter.h).
bool Admissible(const model::DofModel& model, const Eigen::VectorXd& theta);

class Problem {
 public:
  // The trials' problems (MakeTrialProblem; trials without a used sensor are left out) at
  // `theta`, with the parameters `free` and the initial states estimated; each trial's force
  // averaged over pieces `average_input_s` long when > 0 (the coarse stage).
  Problem(const model::DofModel& model, const std::vector<const TrialData*>& trials,
          const Eigen::VectorXd& theta, const std::vector<int>& free,
          const std::vector<TrialInitialState>* initial, const OutputErrorOptions& o,
          double average_input_s = 0.0);

  int num_z() const { return num_z_; }
  int num_free() const { return static_cast<int>(free_.size()); }
  int num_r() const { return num_r_; }
  /// Measurements left out (gross errors found after a first fit): residual and Jacobian 0.
  void Exclude(const std::vector<char>& mask) { excluded_ = mask; }
  const std::vector<char>& excluded() const { return excluded_; }
  int num_excluded() const {
    return static_cast<int>(std::count(excluded_.begin(), excluded_.end(), 1));
  }
  const std::vector<TrialProblem>& trials() const { return trials_; }

  Eigen::VectorXd InitialZ() const;
  Eigen::VectorXd Theta(const Eigen::VectorXd& z) const;
  std::vector<TrialInitialState> Initial(const Eigen::VectorXd& z) const;

  /// Residuals r = w·(y − ŷ) (when `r` is given), their cost ½‖r‖² (when `cost` is), and, when
  /// `rows` is given, the rows of J = ∂r/∂z, trial by trial (a block of its own initial-state
  /// columns and the free parameters', block_least_squares.h): the Jacobian of the campaign is
  /// never stored, nor, for a trial of one sensor on a grid, its simulation. False if a
  /// simulation fails.
  bool Evaluate(const Eigen::VectorXd& z, Eigen::VectorXd* r, BlockRowSink* rows,
                double* cost = nullptr) const;

 private:
  struct RowWriter;  // where Evaluate's rows go (output_error_problem.cc)

  // One trial's residuals and rows (Evaluate). False if its simulation fails.
  bool EvaluateTrial(const TrialProblem& tp, const Eigen::VectorXd& z, const Eigen::VectorXd& theta,
                     const model::SimulationOptions& so, BlockRowSink* rows, RowWriter* out) const;

  const model::DofModel& model_;
  Eigen::VectorXd theta_;
  std::vector<int> free_;
  OutputErrorOptions o_;
  std::vector<TrialProblem> trials_;
  int num_z_ = 0, num_r_ = 0;
  std::vector<char> excluded_;
};

}  // namespace uuvplan::ident::internal
