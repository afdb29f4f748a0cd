#include "uuvplan/ident/estimators/least_squares.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "options_check.h"
#include "uuvplan/ident/stats/chi_square.h"
#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::ident {

namespace {

constexpr model::EnumNames<FitStatus, 4> kFitStatusNames{{{
    {FitStatus::kOk, "ok"},
    {FitStatus::kIllConditioned, "ill_conditioned"},
    {FitStatus::kTooFewData, "too_few_data"},
    {FitStatus::kNoData, "no_data"},
}}};

}  // namespace

bool LeastSquaresOptions::IsValid(std::string* error) const {
  return Require(max_condition > 1,
                 "LeastSquaresOptions::max_condition = " + std::to_string(max_condition) +
                     ". Violated constraint: max_condition > 1",
                 error) &&
         Require(null_component > 0 && null_component < 1,
                 "LeastSquaresOptions::null_component must lie in (0, 1)", error);
}

std::string_view FitStatusName(FitStatus status) { return kFitStatusNames.Name(status); }

int DefaultNeweyWestLags(int n) {
  return std::max(1, static_cast<int>(std::floor(4.0 * std::pow(n / 100.0, 2.0 / 9.0))));
}

std::string JoinNames(const std::vector<int>& columns, const std::vector<std::string>& names) {
  std::string out;
  for (int c : columns) {
    if (!out.empty()) out += ", ";
    out += c >= 0 && c < static_cast<int>(names.size()) ? names[c] : std::to_string(c);
  }
  return out;
}

Eigen::MatrixXd NeweyWestCovariance(const Eigen::MatrixXd& H, const Eigen::VectorXd& r,
                                    const Eigen::VectorXd* w, int lags,
                                    const std::vector<int>* groups, bool truncated) {
  const Eigen::Index n = H.rows(), p = H.cols();
  // Scores g_i = w_i·h_i·r_i; bread A = Hᵀ W H.
  Eigen::MatrixXd G(n, p);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(p, p);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double wi = w ? (*w)[i] : 1.0;
    G.row(i) = wi * r[i] * H.row(i);
  }
  if (w) {
    A.noalias() = H.transpose() * w->asDiagonal() * H;
  } else {
    A.noalias() = H.transpose() * H;
  }
  Eigen::MatrixXd S = G.transpose() * G;
  for (int l = 1; l <= lags; ++l) {
    const double kappa = truncated ? 1.0 : 1.0 - static_cast<double>(l) / (lags + 1);
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(p, p);
    for (Eigen::Index i = l; i < n; ++i) {
      if (groups && (*groups)[i] != (*groups)[i - l]) continue;
      C.noalias() += G.row(i).transpose() * G.row(i - l);
    }
    S += kappa * (C + C.transpose());
  }
  if (truncated) {
    Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(S);
    S = es.eigenvectors() * es.eigenvalues().cwiseMax(0.0).asDiagonal() *
        es.eigenvectors().transpose();
  }
  const Eigen::MatrixXd Ainv = A.ldlt().solve(Eigen::MatrixXd::Identity(p, p));
  const double correction = n > p ? static_cast<double>(n) / (n - p) : 1.0;
  return correction * Ainv * S * Ainv;
}

Eigen::MatrixXd DifferencedCovariance(const Eigen::MatrixXd& H, const Eigen::VectorXd& r,
                                      const std::vector<int>& groups) {
  return Ma1Covariance(H, H, r, groups);
}

Eigen::MatrixXd Ma1Covariance(const Eigen::MatrixXd& H, const Eigen::MatrixXd& Z,
                              const Eigen::VectorXd& r, const std::vector<int>& groups) {
  const Eigen::Index n = H.rows(), p = H.cols();
  // Residual autocovariances at lags 0 and 1 within groups: Ω = γ0·I + γ1·(L + Lᵀ), with
  // |γ1| <= γ0/2 so that Ω stays positive semi-definite (an MA(1)).
  double g0 = r.squaredNorm() / std::max<Eigen::Index>(1, n);
  double g1 = 0.0;
  int pairs = 0;
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(p, p);
  for (Eigen::Index i = 1; i < n; ++i) {
    if (groups[i] != groups[i - 1]) continue;
    g1 += r[i] * r[i - 1];
    ++pairs;
    C.noalias() += Z.row(i).transpose() * Z.row(i - 1);
  }
  // Mean over the pairs that exist (n − number of groups): dividing by n would shrink γ1
  // towards 0 by the share of group boundaries and overstate σ for short runs.
  g1 = pairs > 0 ? g1 / pairs : 0.0;
  g1 = std::clamp(g1, -0.5 * g0, 0.5 * g0);
  const double dof = n > p ? static_cast<double>(n) / (n - p) : 1.0;
  const Eigen::MatrixXd ZOZ = dof * (g0 * (Z.transpose() * Z) + g1 * (C + C.transpose()));
  const Eigen::MatrixXd A = Z.transpose() * H;
  const Eigen::MatrixXd Ainv = A.fullPivLu().inverse();
  return Ainv * ZOZ * Ainv.transpose();
}

Eigen::MatrixXd Ma1VarianceModelCovariance(const Eigen::MatrixXd& H, const Eigen::MatrixXd& Z,
                                           const Eigen::VectorXd& r, const std::vector<int>& groups,
                                           const Eigen::MatrixXd& features,
                                           Eigen::VectorXd* variance_out) {
  const Eigen::Index n = H.rows(), p = H.cols();
  const Eigen::MatrixXd A = Z.transpose() * H;
  const Eigen::MatrixXd Ainv = A.fullPivLu().inverse();
  // 1. Leverage-corrected squared residuals (HC2): E[r_i²] ≈ (1 − h_ii)·σ_i², h_ii the diagonal
  //    of the (IV) hat matrix H·A⁻¹·Zᵀ.
  Eigen::VectorXd u(n), u2(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    const double h = H.row(i).dot(Ainv * Z.row(i).transpose());
    u[i] = r[i] / std::sqrt(std::max(0.05, 1.0 - h));  // guard: a single row of leverage > 0.95
    u2[i] = u[i] * u[i];
  }
  // 2. Variance model σ_i² = c·[1, x_i] (x_i: the row's features) fitted to ũ_i² by least
  //    squares — a few pooled coefficients instead of one noisy ũ_i² per row (White's HC with
  //    ~50 rows and 4 unknowns scatters σ by a factor 2 between repetitions). Collinear
  //    features (e.g. equal rows) reduce to the homoscedastic mean through the truncated SVD.
  const Eigen::Index q = 1 + features.cols();
  Eigen::MatrixXd X(n, q);
  X.col(0).setOnes();
  if (q > 1) X.rightCols(q - 1) = features;
  LeastSquaresOptions lo;
  lo.max_condition = 1e6;
  const LinearFit vf = SolveLeastSquares(X, u2, nullptr, lo);
  const double mean_u2 = u2.mean();
  Eigen::VectorXd v = Eigen::VectorXd::Constant(n, mean_u2);
  if (vf.theta.size() == q && vf.theta.allFinite()) v = X * vf.theta;
  // A fitted variance is never below 5% of the mean one (a linear model can cross zero at the
  // edge of its data; 5% keeps every row's weight in the sandwich finite but small).
  v = v.cwiseMax(0.05 * mean_u2);
  // 3. Lag-1 correlation pooled over the adjacent pairs within groups, on the standardised
  //    residuals, |ρ| <= 1/2 (the MA(1) bound that keeps Ω positive semi-definite for any run).
  double num = 0.0, den = 0.0;
  for (Eigen::Index i = 1; i < n; ++i) {
    if (groups[i] != groups[i - 1]) continue;
    num += u[i] * u[i - 1];
    den += std::sqrt(v[i] * v[i - 1]);
  }
  const double rho = den > 0 ? std::clamp(num / den, -0.5, 0.5) : 0.0;
  // 4. Sandwich A⁻¹·ZᵀΩZ·A⁻ᵀ, Ω_ii = v_i, Ω_{i,i−1} = ρ·√(v_i v_{i−1}) within groups.
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(p, p);
  for (Eigen::Index i = 0; i < n; ++i) {
    S.noalias() += v[i] * Z.row(i).transpose() * Z.row(i);
    if (i > 0 && groups[i] == groups[i - 1]) {
      const Eigen::MatrixXd C =
          (rho * std::sqrt(v[i] * v[i - 1])) * Z.row(i).transpose() * Z.row(i - 1);
      S += C + C.transpose();
    }
  }
  if (variance_out) *variance_out = v;
  return Ainv * S * Ainv.transpose();
}

ScaledFactor AnalyseScaledFactor(const Eigen::MatrixXd& R, const LeastSquaresOptions& options) {
  ScaledFactor f;
  const Eigen::Index p = R.cols();
  // Divide and conquer (Jacobi below 16 columns, Eigen's switch): 17 against 89 ms at 204
  // columns, an output error's θ and 100 trials' initial states (docs/performance.md).
  Eigen::BDCSVD<Eigen::MatrixXd> svd(R, Eigen::ComputeFullU | Eigen::ComputeFullV);
  f.singular_values = svd.singularValues();
  const double smax = f.singular_values[0];
  const double smin = f.singular_values[p - 1];
  f.condition_number = smin > 0 ? smax / smin : std::numeric_limits<double>::infinity();
  // Truncated pseudo-inverse of R: directions with s < smax/max_condition are left out.
  const double cut = smax / options.max_condition;
  f.pseudo_inverse = Eigen::MatrixXd::Zero(p, p);
  for (Eigen::Index k = 0; k < p; ++k) {
    const double s = f.singular_values[k];
    if (s > cut && s > 0) {
      f.pseudo_inverse.noalias() += svd.matrixV().col(k) * svd.matrixU().col(k).transpose() / s;
      continue;
    }
    for (Eigen::Index j = 0; j < p; ++j) {
      if (std::abs(svd.matrixV()(j, k)) > options.null_component &&
          std::find(f.not_identifiable.begin(), f.not_identifiable.end(), j) ==
              f.not_identifiable.end()) {
        f.not_identifiable.push_back(static_cast<int>(j));
      }
    }
  }
  std::sort(f.not_identifiable.begin(), f.not_identifiable.end());
  return f;
}

namespace {

// The covariance of θ that options.covariance names, from the unit covariance D·(BᵀB)⁻¹·D, the
// fit's s² and residuals, and the row weights' square roots `sw` (wr = sw·residuals).
Eigen::MatrixXd CovarianceOfKind(const LeastSquaresOptions& options, const LinearFit& fit,
                                 const Eigen::MatrixXd& unit, const Eigen::MatrixXd& H,
                                 const Eigen::VectorXd& sw, const Eigen::VectorXd& wr,
                                 const Eigen::VectorXd* weights, const std::vector<int>* groups) {
  const Eigen::Index n = H.rows();
  switch (options.covariance) {
    case CovarianceKind::kResidual:
      return (fit.dof > 0 ? fit.sigma2 : 1.0) * unit;
    case CovarianceKind::kKnownNoise:
      return unit;
    case CovarianceKind::kConservative: {
      // Inflate the known-noise covariance by s² only when the residuals say the noise is
      // larger than known: s²·dof beyond the 99% point of χ²(dof) (P < 1%).
      const bool larger = fit.dof > 0 && ChiSquareSurvival(fit.sigma2 * fit.dof, fit.dof) < 0.01;
      return (larger ? fit.sigma2 : 1.0) * unit;
    }
    case CovarianceKind::kKnownNoiseAtLeast:
      return (fit.dof > 0 ? std::max(1.0, fit.sigma2) : 1.0) * unit;
    case CovarianceKind::kDifferenced: {
      std::vector<int> g(n, 0);
      if (groups) g = *groups;
      return DifferencedCovariance(sw.asDiagonal() * H, wr, g);
    }
    case CovarianceKind::kNeweyWest: {
      const int lags =
          options.newey_west_lags >= 0 ? options.newey_west_lags : DefaultNeweyWestLags(int(n));
      return NeweyWestCovariance(H, fit.residuals, weights, lags, groups, options.truncated_kernel);
    }
  }
  return Eigen::MatrixXd();
}

}  // namespace

LinearFit SolveLeastSquares(const Eigen::MatrixXd& H, const Eigen::VectorXd& y,
                            const Eigen::VectorXd* weights, const LeastSquaresOptions& options,
                            const std::vector<int>* groups) {
  LinearFit fit;
  const Eigen::Index n = H.rows(), p = H.cols();
  if (n == 0 || p == 0) {
    fit.status = FitStatus::kNoData;
    fit.message = "no data rows or no unknowns";
    return fit;
  }
  if (n < p) {
    fit.status = FitStatus::kTooFewData;
    fit.message = std::to_string(n) + " equations for " + std::to_string(p) + " unknowns";
    return fit;
  }
  // Column-scaled, row-weighted system B·z = c, theta = D·z, D = diag(1/‖column‖).
  Eigen::VectorXd sw = Eigen::VectorXd::Ones(n);
  if (weights) sw = weights->cwiseSqrt();
  Eigen::MatrixXd B = sw.asDiagonal() * H;
  Eigen::VectorXd c = sw.cwiseProduct(y);
  Eigen::VectorXd D(p);
  for (Eigen::Index j = 0; j < p; ++j) {
    const double norm = B.col(j).norm();
    D[j] = norm > 0 ? 1.0 / norm : 1.0;
    B.col(j) *= D[j];
  }
  // QR, then the SVD of the small R gives the singular values of B.
  Eigen::HouseholderQR<Eigen::MatrixXd> qr(B);
  const Eigen::MatrixXd R = qr.matrixQR().topRows(p).triangularView<Eigen::Upper>();
  const Eigen::VectorXd qtc = (qr.householderQ().transpose() * c).head(p);
  const ScaledFactor f = AnalyseScaledFactor(R, options);
  fit.singular_values = f.singular_values;
  fit.condition_number = f.condition_number;
  fit.not_identifiable = f.not_identifiable;
  const Eigen::MatrixXd& Rpinv = f.pseudo_inverse;
  const Eigen::VectorXd z = Rpinv * qtc;
  fit.theta = D.cwiseProduct(z);
  fit.residuals = y - H * fit.theta;
  fit.dof = static_cast<int>(n - p);
  const Eigen::VectorXd wr = sw.cwiseProduct(fit.residuals);
  fit.sigma2 = fit.dof > 0 ? wr.squaredNorm() / fit.dof : std::numeric_limits<double>::quiet_NaN();
  // (BᵀB)⁻¹ = R⁻¹R⁻ᵀ (pseudo-inverse); Cov of theta = D (BᵀB)⁻¹ D.
  const Eigen::MatrixXd unit = D.asDiagonal() * (Rpinv * Rpinv.transpose()) * D.asDiagonal();
  fit.covariance = CovarianceOfKind(options, fit, unit, H, sw, wr, weights, groups);
  if (fit.condition_number > options.max_condition || !fit.not_identifiable.empty()) {
    fit.status = FitStatus::kIllConditioned;
    std::ostringstream os;
    os << "ill-conditioned regression (condition number " << fit.condition_number << " > "
       << options.max_condition << ")";
    fit.message = os.str();
  } else {
    fit.status = FitStatus::kOk;
  }
  return fit;
}

}  // namespace uuvplan::ident
