// Recursive least squares with a forgetting factor (ref 004 §3.1, eq. 15), for slowly
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
//
// Covariance (docs/identification.md §5): after update k, θ_k is the exponentially weighted
// least-squares estimate (weights λ^{k−i}; P_k⁻¹ = Σ λ^{k−i}F_iᵀF_i + λ^k P_0⁻¹), so
//
//   Cov θ_k = P_k·(γ0·A_k + γ1·B_k)·P_k,   A_k = Σ λ^{2(k−i)} F_iᵀF_i,
//             B_k = Σ λ^{2k−2i+1} (F_iᵀF_{i−1} + F_{i−1}ᵀF_i)   (consecutive rows of one run)
//
// P_k scaled by the residual variance, with the sandwich the forgetting weights need (s²·P_k
// alone overstates the variance by up to 1 + λ, i.e. twice, once the record is much longer
// than the memory 1/(1 − λ)) and
// the MA(1) of rows that share a knot (one_step_ls.h): γ0, γ1 the lag-0 and lag-1 residual
// autocovariances, forgetting-weighted like the rows, |γ1| <= γ0/2. With λ = 1, white
// residuals and a vague prior it is s²·P_k, the eqs. 11–12 covariance of the batch fit.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/ident/estimators/one_step_ls.h"

namespace uuvplan::ident {

struct RlsOptions {
  double lambda = 0.99;  ///< forgetting factor, (0.9, 1] (ref 004)
  /// Initial P = p0·diag(scale²) where scale is |θ0| (or 1 where θ0 = 0): a vague prior.
  double p0 = 1e4;
  Eigen::VectorXd theta0;  ///< initial estimate (empty: zeros)
  /// Keep the covariance of every update (RlsTrajectory::covariance), not only the last.
  bool keep_covariance = false;
  /// RecursiveOneStep: recursive IV passes after the plain recursion (instruments from the
  /// velocity the estimate simulates, against the errors in variables of the filtered velocity
  /// in the rows; 0: ref 004's plain RLS). VSOR's schedule: m +40%, 2/20 covered without them
  /// (docs/validation.md).
  int instrument_iterations = 3;
  bool IsValid(std::string* error) const;
};

struct RlsTrajectory {
  std::vector<double> t;                    ///< time of each update
  Eigen::MatrixXd theta;                    ///< theta(k, :) after update k
  Eigen::MatrixXd sigma;                    ///< √diag of Cov θ_k (file comment)
  Eigen::MatrixXd P;                        ///< final P
  Eigen::MatrixXd final_covariance;         ///< Cov θ_N
  std::vector<Eigen::MatrixXd> covariance;  ///< Cov θ_k of every update (keep_covariance)
  double gamma0 = 0.0, gamma1 = 0.0;        ///< final residual autocovariances (lags 0, 1)
};

/// Runs eq. 15 over the rows of F (one row per update; `rows_per_update` rows form one F_k
/// for multivariable updates, ref 004: F_k ∈ R^{3×12}). `runs` (may be null; single-row
/// updates only) labels the rows: consecutive rows of one run share a knot (MA(1) residuals).
/// With `instruments` (Z, the shape of F) the update is the recursive instrumental-variable
/// one (Young 1970): Γ_k = P Z_kᵀ(λI + F_k P Z_kᵀ)⁻¹, P_k = (I − Γ_k F_k)P_{k−1}/λ, so that
/// P_k⁻¹ = Σ λ^{k−i}Z_iᵀF_i and, with λ = 1, θ_N is the batch IV estimate (ZᵀF)⁻¹ZᵀY; its
/// covariance is the sandwich above with Z in A_k and B_k and P_kᵀ on the right.
RlsTrajectory RecursiveLeastSquares(const Eigen::MatrixXd& F, const Eigen::VectorXd& Y,
                                    const std::vector<double>& t, const RlsOptions& options,
                                    int rows_per_update = 1, const std::vector<int>* runs = nullptr,
                                    const Eigen::MatrixXd* instruments = nullptr);

struct RlsDofResult {
  FitStatus status = FitStatus::kNoData;
  std::string message;
  double lambda = 1.0;
  std::vector<std::string> coefficient_names;  ///< "gamma", "<name>/m" …
  RlsTrajectory psi;
  bool instrumental = false;  ///< psi is the recursive IV's (RlsOptions::instrument_iterations)
  std::vector<std::string> names;        ///< model parameter names
  std::vector<int> free;                 ///< model indices of ψ[1..] (besides m)
  std::vector<std::string> not_excited;  ///< regressor-linear parameters no row excites
  Eigen::MatrixXd theta;                 ///< physical parameters after each update (model layout)
  Eigen::MatrixXd sigma;  ///< their σ (delta method, m = 1/γ, θ_j = ψ_j/γ; 0: not estimated)
  Eigen::VectorXd final_theta;        ///< after the last update (model layout)
  Eigen::MatrixXd covariance;         ///< of final_theta (model layout; 0 rows for the given ones)
  std::vector<ParameterState> state;  ///< kEstimated for m and `free`, kFixed otherwise
  /// Model selection (identify): the estimates of the reported run and, as kDropped with
  /// their last value, the parameters dropped as insignificant before it.
  std::vector<ParameterEstimate> estimates;
  bool ok() const { return status == FitStatus::kOk; }
};

/// RLS on one DOF's one-step rows, each row scaled by √ of its trial's noise weight (Λ_k of
/// ref 004 eq. 16); the trials' rows follow each other in campaign time. `free` empty: every
/// regressor-linear parameter; those no row excites keep their value in `theta`.
RlsDofResult RecursiveOneStep(const model::DofModel& model,
                              const std::vector<const TrialData*>& trials,
                              const Eigen::VectorXd& theta, const std::vector<int>& free,
                              const OneStepOptions& rows_options, const RlsOptions& options);

}  // namespace uuvplan::ident
