// Linear least squares y = H·theta + e with weights, the covariance of the estimate, and the
// diagnosis of ill-posed regressions (ref 000 eqs. 11–12, ref 002 eq. 35, ref 004 eq. 12).
//
//   theta = (Hᵀ W H)⁻¹ Hᵀ W y                                  (ref 002 eq. 35, W = diag(w))
//   eq. 11/12 ("residual"):  Cov = s²·(Hᵀ W H)⁻¹,  s² = rᵀ W r / (n − p)
//   known noise:             Cov = (Hᵀ W H)⁻¹          (w_i = 1/σ_i², the noise is known)
//   conservative:            Cov = (Hᵀ W H)⁻¹, times s² when s²·(n − p) exceeds the 99% point of
//                            χ²(n − p) (known noise unless the residuals say it is larger)
//   known noise at least:    Cov = max(1, s²)·(Hᵀ W H)⁻¹
//   Newey–West (HAC):        Cov = (HᵀWH)⁻¹ S (HᵀWH)⁻¹·n/(n − p),
//                            S = Σ_l κ_l Σ_i (w_i h_i r_i)(w_{i-l} h_{i-l} r_{i-l})ᵀ + transpose,
//                            Bartlett κ_l = 1 − l/(L + 1); lags never cross a group boundary.
// The last guards against the overconfident σ of autocorrelated residuals
// (notes/pitfalls.md: "m = 767 ± 2 kg for a true 900 kg").
//
// The regression is solved by Householder QR of the column-scaled √W·H; the condition number
// is that of the column-scaled matrix (so units do not matter), and the parameters that the
// near-null right singular vectors involve are named as not identifiable.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

namespace uuvplan::ident {

enum class CovarianceKind {
  kResidual,      ///< ref 000 eqs. 11–12: noise variance estimated from the residuals
  kKnownNoise,    ///< weights are 1/σ² of a known noise
  kConservative,  ///< known noise, inflated by s² when the residuals are significantly larger
  /// Known noise, inflated by s² whenever s² > 1: Cov = max(1, s²)·(HᵀWH)⁻¹. For weights whose
  /// σ may be too small (coloured noise under-resolved by a short segment's lag-1), with few
  /// degrees of freedom to test s² against χ².
  kKnownNoiseAtLeast,
  kNeweyWest,  ///< autocorrelation-robust sandwich (Bartlett kernel)
  /// Consecutive rows of a group share a noise term (e.g. y_k = … + e_k − e_{k−1}, and white
  /// errors besides): the residual is MA(1) within groups, Ω = γ0·I + γ1·(L + Lᵀ) with γ0, γ1
  /// the residual autocovariances at lags 0 and 1 (|γ1| <= γ0/2), Cov(θ) = A⁻¹HᵀΩHA⁻¹·n/(n−p).
  kDifferenced,
};

struct LeastSquaresOptions {
  CovarianceKind covariance = CovarianceKind::kResidual;
  /// Newey–West lags L; negative: automatic, floor(4·(n/100)^(2/9)).
  int newey_west_lags = -1;
  /// Uniform (truncated) instead of Bartlett weights for the Newey–West lags: exact for an
  /// MA(L) residual such as the shared endpoints of consecutive integral rows (negative
  /// eigenvalues of the middle matrix are clipped at zero).
  bool truncated_kernel = false;
  /// Column-scaled condition number above which the regression is reported ill-conditioned
  /// (the estimate is still computed, by a truncated SVD).
  double max_condition = 1e8;
  /// A right singular vector's component above this magnitude names its parameter as part of
  /// a non-identifiable combination.
  double null_component = 0.3;

  bool IsValid(std::string* error) const;
};

enum class FitStatus {
  kOk,
  kIllConditioned,  ///< condition number above the limit: some combination is not identifiable
  kTooFewData,      ///< fewer rows than unknowns
  kNoData,
};
std::string_view FitStatusName(FitStatus status);

struct LinearFit {
  FitStatus status = FitStatus::kNoData;
  std::string message;
  Eigen::VectorXd theta;
  Eigen::MatrixXd covariance;
  Eigen::VectorXd residuals;          ///< y − H·theta (unweighted)
  double sigma2 = 0.0;                ///< s² = rᵀWr/(n − p) (eq. 12 with weights)
  int dof = 0;                        ///< n − p
  double condition_number = 0.0;      ///< of the column-scaled √W·H
  std::vector<int> not_identifiable;  ///< column indices in a near-null combination
  Eigen::VectorXd singular_values;    ///< of the column-scaled √W·H, descending

  bool ok() const { return status == FitStatus::kOk; }
};

/// The square upper-triangular factor R of a column-scaled regression matrix B = QR, analysed as
/// SolveLeastSquares does: singular values, condition number, the columns in near-null
/// combinations and the truncated pseudo-inverse R⁺ ((BᵀB)⁺ = R⁺R⁺ᵀ).
struct ScaledFactor {
  Eigen::VectorXd singular_values;  ///< descending
  double condition_number = 0.0;
  std::vector<int> not_identifiable;
  Eigen::MatrixXd pseudo_inverse;
};
ScaledFactor AnalyseScaledFactor(const Eigen::MatrixXd& R, const LeastSquaresOptions& options);

/// Solves y = H·theta (+ e) in the weighted least-squares sense. `weights` (may be null: all 1)
/// are the w_i of the rows; `groups` (may be null) labels rows so that Newey–West lags stay
/// within a group (e.g. a trial).
LinearFit SolveLeastSquares(const Eigen::MatrixXd& H, const Eigen::VectorXd& y,
                            const Eigen::VectorXd* weights, const LeastSquaresOptions& options,
                            const std::vector<int>* groups = nullptr);

/// The Newey–West sandwich covariance for a solved regression (see the file comment).
Eigen::MatrixXd NeweyWestCovariance(const Eigen::MatrixXd& H, const Eigen::VectorXd& residuals,
                                    const Eigen::VectorXd* weights, int lags,
                                    const std::vector<int>* groups, bool truncated = false);

/// The kDifferenced covariance of an unweighted regression (see CovarianceKind).
Eigen::MatrixXd DifferencedCovariance(const Eigen::MatrixXd& H, const Eigen::VectorXd& residuals,
                                      const std::vector<int>& groups);

/// The same for an instrumental-variable estimate θ = (ZᵀH)⁻¹Zᵀy (Z = H: least squares):
/// Cov(θ) = (ZᵀH)⁻¹·ZᵀΩZ·(ZᵀH)⁻ᵀ·n/(n−p), Ω the MA(1) of the residuals within groups.
Eigen::MatrixXd Ma1Covariance(const Eigen::MatrixXd& H, const Eigen::MatrixXd& Z,
                              const Eigen::VectorXd& residuals, const std::vector<int>& groups);

/// Ma1Covariance with a heteroscedastic Ω from a parametric variance model: the leverage-
/// corrected squared residuals ũ_i² = r_i²/(1 − h_ii) are regressed on [1, features_i] (least
/// squares), v_i the fitted values (≥ 5% of their mean); ρ the lag-1 correlation of ũ/√v
/// pooled within groups (|ρ| <= 1/2); Ω_ii = v_i, Ω_{i,i−1} = ρ·√(v_i v_{i−1});
/// Cov(θ) = A⁻¹·ZᵀΩZ·A⁻ᵀ, A = ZᵀH. `features` may have zero columns (homoscedastic MA(1) with
/// the leverage correction). `variance` (may be null) receives v.
Eigen::MatrixXd Ma1VarianceModelCovariance(const Eigen::MatrixXd& H, const Eigen::MatrixXd& Z,
                                           const Eigen::VectorXd& residuals,
                                           const std::vector<int>& groups,
                                           const Eigen::MatrixXd& features,
                                           Eigen::VectorXd* variance = nullptr);

/// Automatic Newey–West lag count floor(4·(n/100)^(2/9)).
int DefaultNeweyWestLags(int n);

/// "k, kq" from column indices and names.
std::string JoinNames(const std::vector<int>& columns, const std::vector<std::string>& names);

}  // namespace uuvplan::ident
