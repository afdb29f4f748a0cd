// Covariance of an estimator whose errors are coloured (docs/identification.md, "σ with
// coloured residuals"): AR(1)-prewhitened sandwiches and the AR(1) noise of a sensor.
//
// An M-estimator linearised at its solution, θ̂ − θ ≈ A⁻¹ Σ_i J_iᵀ e_i (A = JᵀJ, J the rows'
// derivatives, e the errors), has Cov(θ̂) = A⁻¹·Var(Σ_i J_iᵀ e_i)·A⁻¹. With AR(1) errors within a
// group, e_i = ρ·e_{i−1} + u_i (u_0 = e_0), the score sum is rewritten on the innovations:
//
//   Σ_i J_iᵀ e_i = Σ_j Z_jᵀ u_j,   Z_j = J_j + ρ·Z_{j+1}   (backward recursion within the group)
//
// and the u_j are nearly independent: Var(Σ Z_jᵀ u_j) is estimated by batch means of the
// whitened scores Z_jᵀ û_j over blocks of twice the correlation length of û (1 when û is white:
// White's HC), which keeps what the AR(1) does not describe (model error, heteroscedasticity).
// Prewhitening before a HAC sum is Andrews & Monahan (1992); without it a Newey–West or batch-
// means sum over few, long blocks underestimates the long-run variance of ρ = 0.9 errors
// (Σ_l ρ^|l| = 19 needs lags of ~50 samples per block, more than short trials hold).
#pragma once

#include <Eigen/Dense>
#include <memory>
#include <utility>
#include <vector>

namespace uuvplan::ident {

struct PrewhitenedCovariance {
  Eigen::MatrixXd covariance;  ///< A⁻¹ S A⁻¹
  double mean_rho = 0.0;       ///< of the groups, weighted by their rows
  int block = 1;               ///< batch length of the whitened scores
  int blocks = 0;
};

/// Cov(θ̂) of a (weighted) least-squares or output-error solution: `J` the rows' derivatives
/// with respect to the estimated vector, `r` the residuals at the solution (same weighting),
/// `groups` a label per row (a trial and sensor: ρ is estimated per group, within which rows
/// are consecutive in time). `bread_inverse` (may be null: (JᵀJ)⁻¹) is A⁻¹.
PrewhitenedCovariance PrewhitenedSandwich(const Eigen::MatrixXd& J, const Eigen::VectorXd& r,
                                          const std::vector<int>& groups,
                                          const Eigen::MatrixXd* bread_inverse = nullptr);

/// The AR(1) prewhitening of residuals r grouped by `groups` (consecutive equal labels form a
/// run): ρ of each run (Ar1Coefficient), the innovations' batch length, the runs themselves.
struct Prewhitening {
  std::vector<std::pair<int, int>> runs;  ///< [begin, end) rows of each run
  std::vector<double> rho;                ///< of each run
  double mean_rho = 0.0;
  int block = 1;
};
Prewhitening PlanPrewhitening(const Eigen::VectorXd& r, const std::vector<int>& groups);

/// The sandwich's middle matrix S = Σ_b g_b g_bᵀ, g_b = Σ_{j∈b} Z_jᵀ û_j (the batch scores of
/// covariance.h's file comment), accumulated row by row in time order, never holding Z or J.
/// Z_j = Σ_{i≥j} ρ^{i−j} J_i is a backward recursion; forward, with q_i = Σ_{j∈b, j≤i} ρ^{i−j} û_j,
///   g_b = A_b + c_b·Z_{e_b},   A_b = Σ_{i∈b} q_i J_i,   c_b = ρ·q_{e_b−1},
///   Z_{e_b} = Σ_{b'>b} ρ^{s_b' − e_b} W_b',   W_b = Σ_{i∈b} ρ^{i−s_b} J_i,
/// and S = Σ_b [A_bA_bᵀ + μ_b W_bW_bᵀ + (m_b + v_b)W_bᵀ + W_b(m_b + v_b)ᵀ] with the forward sums
///   m_{b+1} = ρ^{L_b}·m_b + c_b·A_b,   μ_{b+1} = ρ^{2L_b}·μ_b + c_b²,   v_{b+1} = ρ^{L_b}·(v_b +
///   μ_b·W_b)
/// (L_b the batch length; all zero at the start of a group). Memory O(columns²), whatever the rows.
class WhitenedScoreSum {
 public:
  WhitenedScoreSum(int columns, int block);
  /// A new group (run) of rows with AR(1) coefficient ρ.
  void StartGroup(double rho);
  /// The next row of the group: its derivatives J_i and residual r_i.
  void Add(const double* jacobian_row, double residual);
  /// S so far (closes the open batch), and the number of batches (closed ones).
  const Eigen::MatrixXd& Sum();
  int batches() const { return batches_; }

 private:
  void CloseBatch();
  int block_;
  double rho_ = 0.0, previous_r_ = 0.0, q_ = 0.0, power_ = 1.0, mu_ = 0.0;
  int in_batch_ = 0, batches_ = 0;
  bool first_row_ = true;
  Eigen::VectorXd a_, w_, m_, v_;
  Eigen::MatrixXd s_;
};

/// The first lag at which the autocorrelation of u, pooled within runs of equal `groups`
/// labels, falls below 2/√n (searched up to a twentieth of the longest run; 1 for short u).
int CorrelationLength(const Eigen::VectorXd& u, const std::vector<int>& groups);

/// Lag-1 coefficient of the AR(1) fitted to a group's residuals (least squares of r_i on
/// r_{i−1}, plus its small-sample bias (1 + 3ρ)/n), clamped to [−0.9, 0.99]: an exactly unit
/// root has no stationary variance.
double Ar1Coefficient(const Eigen::VectorXd& r);

/// AR(1) noise of a sensor from its raw samples y and their smoothed values s (same times):
/// with d_i = (y_i − s_i) − (y_{i−1} − s_{i−1}), the differences of the noise (the smoothing
/// removes the signal's differences, which would dominate a gyro's at 50 Hz),
/// γ_d(1)/γ_d(0) = −(1 − ρ)/2 for AR(1) noise, so ρ = 1 + 2·γ_d(1)/γ_d(0) (white: −1/2,
/// ρ = 0). Clamped to [0, 0.99]. NaN samples split the series.
double NoiseAr1FromDifferences(const std::vector<double>& y, const std::vector<double>& s);

/// An orthonormal basis Q of a fit's columns X (OrthonormalBasis, n × q: X itself is not kept),
/// shared by the fit that made it and the AR(1) estimates below (a million-sample record's
/// bases are megabytes).
struct ColumnBasis {
  Eigen::MatrixXd Q;
};

/// Residuals of a least-squares fit of X (n × q, rows consecutive samples) to a series with
/// AR(1) errors, summarised by Σr_i² and Σr_i·r_{i−1}, with the basis of X.
struct FittedResiduals {
  std::shared_ptr<const ColumnBasis> basis;
  double sum_sq = 0.0;
  double sum_lag1 = 0.0;
};

/// An orthonormal basis of the columns of X (the thin Q of its QR decomposition).
Eigen::MatrixXd OrthonormalBasis(const Eigen::Ref<const Eigen::MatrixXd>& X);

/// The AR(1) coefficient of the errors behind several fits' residuals, freed of the fits'
/// bias: r = (I − P)e, P = QQᵀ (Q an orthonormal basis of X), so with Ω_ij = ρ^|i−j|,
/// E Σr² = n − tr(QᵀΩQ) and E Σr_i r_{i−1} = (n−1)ρ − 2tr(QᵀLΩQ) + tr(QᵀLQ·QᵀΩQ) (L the
/// symmetric lag-1 matrix, ½ off the diagonal); ρ solves Σ_k E Σr_i r_{i−1} = ρ̂·Σ_k E Σr²,
/// ρ̂ = Σ_k sum_lag1 / Σ_k sum_sq (bisection; Ωx in O(n)). A mean over n samples leaves
/// ρ̂ ≈ ρ − (1 + 3ρ)/n (Marriott & Pope 1954); a settling fit's exponential column takes less.
/// Clamped to [0, 0.99]; 0 when the pooled ρ̂ is not above 2/√N (N the samples).
double Ar1FromFittedResiduals(const std::vector<FittedResiduals>& fits);

/// The AR(1) coefficient of errors of known marginal sd σ behind several fits' residuals:
/// ρ solves σ²·Σ_k E Σr²(ρ) = Σ_k sum_sq, E Σr² = n − tr(QᵀΩQ) as above (bisection; it falls
/// monotonically with ρ as the fitted columns take more of slower noise). On short fits (the
/// 21-sample windows of a 4th-order filter) the lag-1 ratio is nearly flat near ρ = 0.9 and
/// scatters to the clamp; the residual variance still moves steeply with ρ. 0 unless Σ sum_sq
/// is significantly below white noise's (χ² of Σ(n − q) degrees: more than 2 sd below σ²·dof),
/// 0.99 at most: a ρ̂ clamped at 0 from a symmetric scatter is biased up on white noise.
double Ar1FromResidualVariance(const std::vector<FittedResiduals>& fits, double sigma);

/// Σ_s Σ_t c_s c_t ρ^|s−t| = cᵀΩc/σ² of a stationary AR(1) (O(n): q_s = c_s + ρ·q_{s−1},
/// the sum is 2·Σ c_s q_s − Σ c_s²).
double Ar1QuadraticForm(const std::vector<double>& c, double rho);

}  // namespace uuvplan::ident
