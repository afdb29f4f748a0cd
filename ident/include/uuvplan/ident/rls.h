// Recursive least squares with a forgetting factor (seed 004 §3.1, eq. 15), for slowly
// varying parameters:
//
//   Γ_k = P_{k−1} F_kᵀ (λ·I + F_k P_{k−1} F_kᵀ)⁻¹
//   θ_k = θ_{k−1} + Γ_k (Y_k − F_k θ_{k−1})
//   P_k = (I − Γ_k F_k) P_{k−1} / λ
//
// λ ∈ (0.9, 1] trades robustness to noise (large λ) against tracking (small λ); the memory is
// about 1/(1 − λ) rows. With λ = 1 and a vague prior the final estimate equals the batch
// least-squares one. Rows are those of the one-step integral regression (one_step_ls.h), so
// the parameter trajectory is returned both as ψ and as physical parameters.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/ident/one_step_ls.h"

namespace uuvplan::ident {

struct RlsOptions {
  double lambda = 0.99;  ///< forgetting factor, (0.9, 1] (seed 004)
  /// Initial P = p0·diag(scale²) where scale is |θ0| (or 1 where θ0 = 0): a vague prior.
  double p0 = 1e4;
  Eigen::VectorXd theta0;  ///< initial estimate (empty: zeros)
  bool IsValid(std::string* error) const;
};

struct RlsTrajectory {
  std::vector<double> t;  ///< time of each update
  Eigen::MatrixXd theta;  ///< theta(k, :) after update k
  Eigen::MatrixXd sigma;  ///< √diag(P_k)·s, s² the running weighted residual variance
  Eigen::MatrixXd P;      ///< final P
};

/// Runs eq. 15 over the rows of F (one row per update; `rows_per_update` rows form one F_k
/// for multivariable updates, seed 004: F_k ∈ R^{3×12}).
RlsTrajectory RecursiveLeastSquares(const Eigen::MatrixXd& F, const Eigen::VectorXd& Y,
                                    const std::vector<double>& t, const RlsOptions& options,
                                    int rows_per_update = 1);

struct RlsDofResult {
  std::vector<std::string> coefficient_names;  ///< "gamma", "<name>/m" …
  RlsTrajectory psi;
  std::vector<std::string> names;  ///< model parameter names
  Eigen::MatrixXd theta;           ///< physical parameters after each update (model layout)
};

/// RLS on one DOF's one-step rows (times on the campaign clock when `campaign_clock`).
RlsDofResult RecursiveOneStep(const model::DofModel& model,
                              const std::vector<const TrialData*>& trials,
                              const Eigen::VectorXd& theta, const std::vector<int>& free,
                              const OneStepOptions& rows_options, const RlsOptions& options);

}  // namespace uuvplan::ident
