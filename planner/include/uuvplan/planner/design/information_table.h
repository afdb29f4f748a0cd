// The information a schedule carries, for people checking a plan: per trial
// and per DOF for the whole schedule, the Fisher information matrix (fisher_information.h) at
// the nominal parameters (the centre of the a priori box, parameter_box.h), the D, A and E
// criteria on its relative form (criteria.h), the predicted 1σ per parameter and the condition
// number, with the parameter names. The DOFs are identified independently, so the whole
// schedule's information is block-diagonal: one block per DOF, each the sum of its trials'.
#pragma once

#include <Eigen/Dense>
#include <map>
#include <string>
#include <vector>

#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::planner {

struct InformationSummary {
  model::Dof dof = model::Dof::kSurge;
  std::vector<std::string> names;  ///< parameters, DofModel::parameter_names() order
  Eigen::VectorXd theta;           ///< the nominal values the information is taken at
  Eigen::MatrixXd fisher;          ///< absolute units: (i, j) in 1/(unit_i·unit_j)
  /// log det M_rel, −log tr M_rel⁻¹, log λ_min(M_rel) on the informed parameters (criteria.h).
  double d = 0.0, a = 0.0, e = 0.0;
  bool singular = false;
  /// Predicted 1σ (absolute units), NaN for a parameter no trial reaches, +inf when the
  /// informed ones cannot be told apart (criteria.h PredictedSigma).
  Eigen::VectorXd sigma;
  /// λ_max/λ_min of M_rel over the informed parameters; +inf when singular.
  double condition_number = 0.0;
};

struct ScheduleInformation {
  std::vector<InformationSummary> trials;         ///< one per schedule trial, in schedule order
  std::map<model::Dof, InformationSummary> dofs;  ///< each DOF's trials together
};

/// The summary of information `M` (absolute) at `theta` for parameters `names`.
InformationSummary SummariseInformation(model::Dof dof, const std::vector<std::string>& names,
                                        const Eigen::VectorXd& theta, const Eigen::MatrixXd& M);

/// The information of every trial of `schedule` and of each DOF's trials together, at the
/// centre of the a priori box that `options` plans with.
ScheduleInformation InformationOf(const model::Vehicle& vehicle, const model::Pool& pool,
                                  const Schedule& schedule, const ScheduleOptions& options);

}  // namespace uuvplan::planner
