#include "uuvplan/ident/stats/covariance.h"

#include <algorithm>
#include <cmath>

namespace uuvplan::ident {
namespace {

// [begin, end) of each run of equal consecutive group labels.
std::vector<std::pair<int, int>> GroupRuns(const std::vector<int>& groups) {
  std::vector<std::pair<int, int>> runs;
  const int n = static_cast<int>(groups.size());
  for (int i = 0; i < n;) {
    int j = i + 1;
    while (j < n && groups[j] == groups[i]) ++j;
    runs.push_back({i, j});
    i = j;
  }
  return runs;
}

// The first lag at which the autocorrelation of u, pooled within runs, falls below 2/√n
// (searched up to a twentieth of the longest run).
int RunCorrelationLength(const Eigen::VectorXd& u, const std::vector<std::pair<int, int>>& runs) {
  const double den = u.squaredNorm();
  const int n = static_cast<int>(u.size());
  if (!(den > 0) || n < 40) return 1;
  int longest = 0;
  for (const auto& [a, b] : runs) longest = std::max(longest, b - a);
  const double bound = 2.0 / std::sqrt(static_cast<double>(n));
  for (int l = 1; l < std::max(2, longest / 20); ++l) {
    double c = 0.0;
    for (const auto& [a, b] : runs) {
      for (int i = a + l; i < b; ++i) c += u[i] * u[i - l];
    }
    if (std::abs(c / den) < bound) return l;
  }
  return std::max(1, longest / 20);
}

// Ωx, Ω_ij = ρ^|i−j|: forward and backward AR(1) recursions, Ωx = f + b − x.
Eigen::VectorXd Ar1Times(const Eigen::VectorXd& x, double rho) {
  const Eigen::Index n = x.size();
  Eigen::VectorXd f(n), b(n);
  for (Eigen::Index i = 0; i < n; ++i) f[i] = x[i] + (i > 0 ? rho * f[i - 1] : 0.0);
  for (Eigen::Index i = n; i-- > 0;) b[i] = x[i] + (i + 1 < n ? rho * b[i + 1] : 0.0);
  return f + b - x;
}

// L x, L the symmetric lag-1 matrix (½ on the first off-diagonals).
Eigen::VectorXd LagTimes(const Eigen::VectorXd& x) {
  const Eigen::Index n = x.size();
  Eigen::VectorXd y = Eigen::VectorXd::Zero(n);
  for (Eigen::Index i = 1; i < n; ++i) {
    y[i] += 0.5 * x[i - 1];
    y[i - 1] += 0.5 * x[i];
  }
  return y;
}

// E Σr² and E Σr_i r_{i−1} (per unit marginal variance) of the residuals of a fit on the
// orthonormal basis Q under AR(1) errors of coefficient ρ.
std::pair<double, double> ExpectedResidualMoments(const Eigen::MatrixXd& Q, double rho) {
  const Eigen::Index n = Q.rows(), q = Q.cols();
  Eigen::MatrixXd OQ(n, q), LQ(n, q);
  for (Eigen::Index c = 0; c < q; ++c) {
    OQ.col(c) = Ar1Times(Q.col(c), rho);
    LQ.col(c) = LagTimes(Q.col(c));
  }
  const Eigen::MatrixXd QOQ = Q.transpose() * OQ, QLQ = Q.transpose() * LQ;
  const double sq = static_cast<double>(n) - QOQ.trace();
  const double lag = (n - 1) * rho - 2.0 * (LQ.transpose() * OQ).trace() + (QLQ * QOQ).trace();
  return {sq, lag};
}

}  // namespace

Eigen::MatrixXd OrthonormalBasis(const Eigen::Ref<const Eigen::MatrixXd>& X) {
  const Eigen::HouseholderQR<Eigen::MatrixXd> qr(X);
  return qr.householderQ() * Eigen::MatrixXd::Identity(X.rows(), X.cols());
}

double Ar1FromFittedResiduals(const std::vector<FittedResiduals>& fits) {
  double num = 0.0, den = 0.0, N = 0.0;
  std::vector<const Eigen::MatrixXd*> bases;
  for (const FittedResiduals& f : fits) {
    if (!f.basis || f.basis->Q.rows() <= f.basis->Q.cols() + 2 || !(f.sum_sq > 0)) continue;
    bases.push_back(&f.basis->Q);
    num += f.sum_lag1;
    den += f.sum_sq;
    N += static_cast<double>(f.basis->Q.rows());
  }
  if (!(den > 0) || num / den <= 2.0 / std::sqrt(N)) return 0.0;
  const double observed = num / den;
  // g(ρ) = Σ E lag − ρ̂·Σ E sq rises with ρ; bisection on [0, 0.99].
  auto g = [&](double rho) {
    double lag = 0.0, sq = 0.0;
    for (const Eigen::MatrixXd* Q : bases) {
      const auto [s, l] = ExpectedResidualMoments(*Q, rho);
      sq += s;
      lag += l;
    }
    return lag - observed * sq;
  };
  double lo = 0.0, hi = 0.99;
  if (g(hi) <= 0) return hi;
  if (g(lo) >= 0) return 0.0;
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    (g(mid) < 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double Ar1FromResidualVariance(const std::vector<FittedResiduals>& fits, double sigma) {
  double observed = 0.0, dof = 0.0;
  std::vector<const Eigen::MatrixXd*> bases;
  for (const FittedResiduals& f : fits) {
    if (!f.basis || f.basis->Q.rows() <= f.basis->Q.cols() + 2) continue;
    bases.push_back(&f.basis->Q);
    observed += f.sum_sq;
    dof += static_cast<double>(f.basis->Q.rows() - f.basis->Q.cols());
  }
  if (bases.empty() || !(sigma > 0)) return 0.0;
  // White Gaussian noise makes Σr²/σ² a χ² of Σ(n − q) degrees (mean dof, sd √(2·dof)): ρ is 0
  // unless the residual variance is significantly (2 sd) below it. Without the test ρ̂ is
  // clamped at 0 from a symmetric scatter (sd ~0.1 on 300 degrees): biased up on white noise,
  // it over-corrected the integral method's errors in variables (URIS yaw m +1.9%, 84% cover).
  if (observed >= sigma * sigma * (dof - 2.0 * std::sqrt(2.0 * dof))) return 0.0;
  // h(ρ) = σ²·Σ E Σr²(ρ) − Σr² falls with ρ (the fitted columns take more of slower noise).
  auto h = [&](double rho) {
    double sq = 0.0;
    for (const Eigen::MatrixXd* Q : bases) sq += ExpectedResidualMoments(*Q, rho).first;
    return sigma * sigma * sq - observed;
  };
  double lo = 0.0, hi = 0.99;
  if (h(lo) <= 0) return 0.0;
  if (h(hi) >= 0) return hi;
  for (int it = 0; it < 40; ++it) {
    const double mid = 0.5 * (lo + hi);
    (h(mid) > 0 ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

int CorrelationLength(const Eigen::VectorXd& u, const std::vector<int>& groups) {
  return RunCorrelationLength(u, GroupRuns(groups));
}

double Ar1Coefficient(const Eigen::VectorXd& r) {
  const Eigen::Index n = r.size();
  if (n < 3) return 0.0;
  const double num = r.head(n - 1).dot(r.tail(n - 1));
  const double den = r.head(n - 1).squaredNorm();
  if (!(den > 0)) return 0.0;
  // Least squares of an AR(1) is biased towards 0 by (1 + 3ρ)/n (Marriott & Pope 1954): for
  // ρ = 0.9 on 100 samples 0.863, a long-run variance (1 + ρ)/(1 − ρ) of 13.6 for 19, σ 18% low.
  const double rho = num / den;
  return std::clamp(rho + (1.0 + 3.0 * rho) / static_cast<double>(n), -0.9, 0.99);
}

double NoiseAr1FromDifferences(const std::vector<double>& y, const std::vector<double>& s) {
  double g0 = 0.0, g1 = 0.0;
  double prev_d = std::nan("");
  for (std::size_t i = 1; i < y.size() && i < s.size(); ++i) {
    const double d = (y[i] - s[i]) - (y[i - 1] - s[i - 1]);  // NaN across a missing sample
    if (std::isnan(d)) {
      prev_d = std::nan("");
      continue;
    }
    g0 += d * d;
    if (!std::isnan(prev_d)) g1 += d * prev_d;
    prev_d = d;
  }
  if (!(g0 > 0)) return 0.0;
  return std::clamp(1.0 + 2.0 * g1 / g0, 0.0, 0.99);
}

double Ar1QuadraticForm(const std::vector<double>& c, double rho) {
  double q = 0.0, sum = 0.0, sq = 0.0;
  for (double cs : c) {
    q = cs + rho * q;
    sum += cs * q;
    sq += cs * cs;
  }
  return 2.0 * sum - sq;
}

Prewhitening PlanPrewhitening(const Eigen::VectorXd& r, const std::vector<int>& groups) {
  Prewhitening p;
  p.runs = GroupRuns(groups);
  const Eigen::Index n = r.size();
  Eigen::VectorXd u(n);  // the innovations û, to choose the batch length
  double rho_sum = 0.0;
  for (const auto& [a, b] : p.runs) {
    const double rho = Ar1Coefficient(r.segment(a, b - a));
    p.rho.push_back(rho);
    rho_sum += rho * (b - a);
    u[a] = r[a];
    for (int i = a + 1; i < b; ++i) u[i] = r[i] - rho * r[i - 1];
  }
  p.mean_rho = n > 0 ? rho_sum / n : 0.0;
  p.block = std::max(1, 2 * RunCorrelationLength(u, p.runs) - 1);
  return p;
}

WhitenedScoreSum::WhitenedScoreSum(int columns, int block)
    : block_(std::max(1, block)),
      a_(Eigen::VectorXd::Zero(columns)),
      w_(Eigen::VectorXd::Zero(columns)),
      m_(Eigen::VectorXd::Zero(columns)),
      v_(Eigen::VectorXd::Zero(columns)),
      s_(Eigen::MatrixXd::Zero(columns, columns)) {}

void WhitenedScoreSum::StartGroup(double rho) {
  CloseBatch();
  rho_ = rho;
  first_row_ = true;
  m_.setZero();
  v_.setZero();
  mu_ = 0.0;
}

void WhitenedScoreSum::Add(const double* jacobian_row, double residual) {
  const Eigen::Map<const Eigen::VectorXd> j(jacobian_row, a_.size());
  const double u = first_row_ ? residual : residual - rho_ * previous_r_;
  first_row_ = false;
  previous_r_ = residual;
  q_ = rho_ * q_ + u;
  a_.noalias() += q_ * j;
  w_.noalias() += power_ * j;
  power_ *= rho_;
  if (++in_batch_ == block_) CloseBatch();
}

void WhitenedScoreSum::CloseBatch() {
  if (in_batch_ == 0) return;
  const double c = rho_ * q_;
  const Eigen::VectorXd mv = m_ + v_;
  s_.noalias() += a_ * a_.transpose() + mu_ * w_ * w_.transpose();
  s_.noalias() += mv * w_.transpose();
  s_.noalias() += w_ * mv.transpose();
  m_ = power_ * m_ + c * a_;
  v_ = power_ * (v_ + mu_ * w_);
  mu_ = power_ * power_ * mu_ + c * c;
  a_.setZero();
  w_.setZero();
  q_ = 0.0;
  power_ = 1.0;
  in_batch_ = 0;
  ++batches_;
}

const Eigen::MatrixXd& WhitenedScoreSum::Sum() {
  CloseBatch();
  return s_;
}

PrewhitenedCovariance PrewhitenedSandwich(const Eigen::MatrixXd& J, const Eigen::VectorXd& r,
                                          const std::vector<int>& groups,
                                          const Eigen::MatrixXd* bread_inverse) {
  const Eigen::Index p = J.cols();
  PrewhitenedCovariance out;
  const Prewhitening plan = PlanPrewhitening(r, groups);
  out.mean_rho = plan.mean_rho;
  out.block = plan.block;
  WhitenedScoreSum sum(static_cast<int>(p), plan.block);
  const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> rows = J;
  for (std::size_t g = 0; g < plan.runs.size(); ++g) {
    sum.StartGroup(plan.rho[g]);
    for (int i = plan.runs[g].first; i < plan.runs[g].second; ++i)
      sum.Add(rows.row(i).data(), r[i]);
  }
  const Eigen::MatrixXd& S = sum.Sum();
  out.blocks = sum.batches();
  // The scores sum to zero at the solution (p constraints): B/(B − p) as HC1's n/(n − p).
  const double correction =
      out.blocks > p ? static_cast<double>(out.blocks) / (out.blocks - p) : 1.0;
  const Eigen::MatrixXd Ainv =
      bread_inverse
          ? *bread_inverse
          : Eigen::MatrixXd((J.transpose() * J).ldlt().solve(Eigen::MatrixXd::Identity(p, p)));
  out.covariance = correction * Ainv * S * Ainv.transpose();
  return out;
}

}  // namespace uuvplan::ident
