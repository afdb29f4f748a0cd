// The speed of a steady segment (speed_fit.h): ref 000 §III eqs. 11–12, the settling fit, and
// their σ under AR(1) noise.
#include "uuvplan/ident/prepare/speed_fit.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "uuvplan/ident/stats/covariance.h"

namespace uuvplan::ident {
namespace {

// Lag-1 autocorrelation of a residual vector.
double Lag1(const std::vector<double>& r) {
  if (r.size() < 3) return 0.0;
  double num = 0.0, den = 0.0;
  for (std::size_t i = 0; i < r.size(); ++i) {
    den += r[i] * r[i];
    if (i > 0) num += r[i] * r[i - 1];
  }
  return den > 0 ? num / den : 0.0;
}

// Inflation of σ for positively autocorrelated residuals (AR(1) effective sample size).
double AutocorrelationFactor(double rho, int n) {
  if (n < 3 || rho <= 2.0 / std::sqrt(static_cast<double>(n))) return 1.0;
  rho = std::min(rho, 0.95);
  return std::sqrt((1 + rho) / (1 - rho));
}

// The fit's window: t0, t1, and the samples [*lo, *hi) inside it (f.n of them).
SpeedFit SpeedWindow(const Signal& s, double t0, double t1, std::ptrdiff_t* lo,
                     std::ptrdiff_t* hi) {
  SpeedFit f;
  f.t0 = t0;
  f.t1 = t1;
  *lo = std::lower_bound(s.t.begin(), s.t.end(), t0) - s.t.begin();
  *hi = std::upper_bound(s.t.begin(), s.t.end(), t1) - s.t.begin();
  f.n = static_cast<int>(*hi - *lo);
  return f;
}

// From the residuals r of a fit with `fitted` coefficients: the residual σ (eq. 12), their
// lag-1 autocorrelation, and the speed's σ = σ_ε/√spread (eq. 11; σ_ε known or eq. 12),
// inflated for autocorrelated residuals.
void SetSpeedSigma(const std::vector<double>& r, int fitted, double known_sigma, double spread,
                   SpeedFit* f) {
  double rss = 0.0;
  for (double x : r) rss += x * x;
  f->residual_sd = std::sqrt(rss / (f->n - fitted));
  f->lag1 = Lag1(r);
  const double sigma_eps = known_sigma > 0 ? known_sigma : f->residual_sd;
  f->sigma = sigma_eps / std::sqrt(spread) * AutocorrelationFactor(f->lag1, f->n);
  f->ok = true;
}

}  // namespace

SpeedFit ConstantSpeedFit(const Signal& s, double t0, double t1, double known_sigma) {
  std::ptrdiff_t lo = 0, hi = 0;
  SpeedFit f = SpeedWindow(s, t0, t1, &lo, &hi);
  const int n = f.n;
  if (n < 3) return f;
  double tm = 0.0, ym = 0.0;
  for (auto i = lo; i < hi; ++i) {
    tm += s.t[i];
    ym += s.y[i];
  }
  tm /= n;
  ym /= n;
  double stt = 0.0, sty = 0.0;
  for (auto i = lo; i < hi; ++i) {
    stt += (s.t[i] - tm) * (s.t[i] - tm);
    sty += (s.t[i] - tm) * (s.y[i] - ym);
  }
  if (!(stt > 0)) return f;
  f.speed = sty / stt;
  f.offset = ym;
  std::vector<double> r;
  r.reserve(n);
  for (auto i = lo; i < hi; ++i) r.push_back(s.y[i] - ym - f.speed * (s.t[i] - tm));
  // Eq. 11 for the slope: σ_v² = σ_ε² / Σ(t − t̄)².
  SetSpeedSigma(r, 2, known_sigma, stt, &f);
  f.fitted = 2;
  Eigen::MatrixXd design(n, 2);
  for (auto i = lo; i < hi; ++i) {
    f.weights.push_back((s.t[i] - tm) / stt);
    design(i - lo, 0) = 1.0;
    design(i - lo, 1) = s.t[i] - tm;
  }
  f.basis = std::make_shared<const ColumnBasis>(ColumnBasis{OrthonormalBasis(design)});
  return f;
}

SpeedFit MeanSpeedFit(const Signal& s, double t0, double t1, double known_sigma) {
  std::ptrdiff_t lo = 0, hi = 0;
  SpeedFit f = SpeedWindow(s, t0, t1, &lo, &hi);
  const int n = f.n;
  if (n < 2) return f;
  double mean = 0.0;
  for (auto i = lo; i < hi; ++i) mean += s.y[i];
  mean /= n;
  std::vector<double> r;
  for (auto i = lo; i < hi; ++i) r.push_back(s.y[i] - mean);
  f.speed = mean;
  SetSpeedSigma(r, 1, known_sigma, static_cast<double>(n), &f);
  f.fitted = 1;
  f.weights.assign(n, 1.0 / n);
  f.basis = std::make_shared<const ColumnBasis>(
      ColumnBasis{OrthonormalBasis(Eigen::MatrixXd::Ones(n, 1))});
  return f;
}

namespace {

// The samples [lo, hi) of a settling fit and the model's reference times: e = exp(−(t − start)/τ)
// from the first sample, positions' slope about the samples' mean time tbar.
struct SettlingWindow {
  const Signal& s;
  std::size_t lo = 0, hi = 0;
  bool is_position = false;
  double start = 0.0, tbar = 0.0;
  int n() const { return static_cast<int>(hi - lo); }
  int num_parameters() const { return is_position ? 4 : 3; }  // with τ
};

// Linear least squares of the settling model at a fixed τ: columns [1, t − t̄, e] (positions)
// or [1, e] (velocities), e = exp(−(t − t0)/τ). Returns the RSS and the coefficients.
double SettlingProfile(const SettlingWindow& w, double tau, Eigen::Vector3d* coef) {
  const Signal& s = w.s;
  const int q = w.is_position ? 3 : 2;
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  Eigen::Vector3d b = Eigen::Vector3d::Zero();
  double yy = 0.0;
  for (std::size_t i = w.lo; i < w.hi; ++i) {
    // Past 40 time constants e < 4e-18: its products are below rounding of the leading
    // entries (e ≤ 1 at the start), so the exponential is not evaluated there.
    const double arg = (s.t[i] - w.start) / tau;
    const double e = arg < 40.0 ? std::exp(-arg) : 0.0;
    const double row[3] = {1.0, w.is_position ? s.t[i] - w.tbar : e, e};
    for (int a = 0; a < q; ++a) {
      b[a] += row[a] * s.y[i];
      for (int c = 0; c < q; ++c) A(a, c) += row[a] * row[c];
    }
    yy += s.y[i] * s.y[i];
  }
  Eigen::LDLT<Eigen::MatrixXd> ldlt(A.topLeftCorner(q, q));
  const Eigen::VectorXd x = ldlt.solve(b.head(q));
  coef->setZero();
  coef->head(q) = x;
  return std::max(0.0, yy - x.dot(b.head(q)));
}

// The τ of least profiled RSS: the best of 24 points on a log grid over [tau_lo, tau_hi], then
// 20 golden-section steps in log τ between that point's neighbours.
double ProfiledTau(const SettlingWindow& w, double tau_lo, double tau_hi) {
  constexpr int kGrid = 24;
  Eigen::Vector3d coef;
  double best_rss = std::numeric_limits<double>::infinity();
  int best = 0;
  std::vector<double> grid(kGrid);
  for (int g = 0; g < kGrid; ++g) {
    grid[g] = tau_lo * std::pow(tau_hi / tau_lo, static_cast<double>(g) / (kGrid - 1));
    const double rss = SettlingProfile(w, grid[g], &coef);
    if (rss < best_rss) {
      best_rss = rss;
      best = g;
    }
  }
  double a = std::log(grid[std::max(0, best - 1)]),
         b = std::log(grid[std::min(kGrid - 1, best + 1)]);
  const double gr = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = b - gr * (b - a), d = a + gr * (b - a);
  double fc = SettlingProfile(w, std::exp(c), &coef);
  double fd = SettlingProfile(w, std::exp(d), &coef);
  for (int it = 0; it < 20; ++it) {
    if (fc < fd) {
      b = d;
      d = c;
      fd = fc;
      c = b - gr * (b - a);
      fc = SettlingProfile(w, std::exp(c), &coef);
    } else {
      a = c;
      c = d;
      fc = fd;
      d = a + gr * (b - a);
      fd = SettlingProfile(w, std::exp(d), &coef);
    }
  }
  return std::exp(0.5 * (a + b));
}

// ∂ model/∂[c, v, B, τ] (positions) or ∂/∂[v∞, A, τ] (velocities) at every sample: the
// Gauss–Newton Jacobian of the settling model with amplitude B.
Eigen::MatrixXd SettlingJacobian(const SettlingWindow& w, double tau, double B) {
  Eigen::MatrixXd J(w.n(), w.num_parameters());
  for (int i = 0; i < w.n(); ++i) {
    const double u = w.s.t[w.lo + i] - w.start;
    const double e = std::exp(-u / tau);
    int k = 0;
    J(i, k++) = 1.0;
    if (w.is_position) J(i, k++) = w.s.t[w.lo + i] - w.tbar;
    J(i, k++) = e;
    J(i, k++) = B * u / (tau * tau) * e;
  }
  return J;
}

// The samples minus the settling model of coefficients `coef` at τ.
std::vector<double> SettlingResiduals(const SettlingWindow& w, double tau,
                                      const Eigen::Vector3d& coef) {
  const Signal& s = w.s;
  std::vector<double> r(w.n());
  for (int i = 0; i < w.n(); ++i) {
    const double arg = (s.t[w.lo + i] - w.start) / tau;
    const double e = arg < 40.0 ? std::exp(-arg) : 0.0;
    r[i] = s.y[w.lo + i] - coef[0] -
           (w.is_position ? coef[1] * (s.t[w.lo + i] - w.tbar) + coef[2] * e : coef[1] * e);
  }
  return r;
}

// The fit at τ (profiled or fixed) from its coefficients and RSS: the speed, its weights on the
// samples and σ from the Gauss–Newton covariance of every parameter (τ among them when the
// transient determines it), the residuals' lag-1 and χ².
void SetSettlingEstimate(const SettlingWindow& w, double tau, bool tau_fixed,
                         const Eigen::Vector3d& coef, double rss, double known_sigma,
                         SettlingFit* f) {
  const int n = w.n(), p = w.num_parameters();
  const double B = w.is_position ? coef[2] : coef[1];
  // Gauss–Newton covariance of [c, v, B, τ] (or [v∞, A, τ]).
  const Eigen::MatrixXd J = SettlingJacobian(w, tau, B);
  Eigen::MatrixXd N = J.transpose() * J;
  Eigen::JacobiSVD<Eigen::MatrixXd> svd(N);
  const double cond = svd.singularValues()[0] / std::max(1e-300, svd.singularValues()[p - 1]);
  // Without a visible transient τ is not determined: the covariance at fixed τ is used.
  const int q = cond < 1e12 && !tau_fixed ? p : p - 1;
  const double var = known_sigma > 0 ? known_sigma * known_sigma : rss / (n - q);
  const Eigen::MatrixXd Ninv = N.topLeftCorner(q, q).ldlt().solve(Eigen::MatrixXd::Identity(q, q));
  const Eigen::MatrixXd C = var * Ninv;
  const int iv = w.is_position ? 1 : 0, ib = w.is_position ? 2 : 1;
  // The speed's weights on the samples: row iv of (JᵀJ)⁻¹Jᵀ; the residuals' lag-1.
  const Eigen::VectorXd weights = J.leftCols(q) * Ninv.col(iv);
  f->weights.assign(weights.data(), weights.data() + n);
  f->fitted = q;
  f->basis = std::make_shared<const ColumnBasis>(ColumnBasis{OrthonormalBasis(J.leftCols(q))});
  f->lag1 = Lag1(SettlingResiduals(w, tau, coef));
  f->speed = w.is_position ? coef[1] : coef[0];
  f->sigma = std::sqrt(std::max(0.0, C(iv, iv)));
  f->offset = coef[0];
  f->residual_sd = std::sqrt(rss / (n - q));
  f->tau = tau;
  f->amplitude = B;
  f->amplitude_sigma = std::sqrt(std::max(0.0, C(ib, ib)));
  f->dof = n - q;
  f->chi2 = known_sigma > 0 ? rss / (known_sigma * known_sigma) : f->dof;
  f->ok = std::isfinite(f->speed) && std::isfinite(f->sigma) && f->sigma > 0;
}

}  // namespace

SettlingFit SettlingSpeedFit(const Signal& s, bool is_position, double t0, double t1,
                             double known_sigma, double fixed_tau) {
  SettlingFit f;
  f.t0 = t0;
  f.t1 = t1;
  SettlingWindow w{s};
  w.lo = std::lower_bound(s.t.begin(), s.t.end(), t0) - s.t.begin();
  w.hi = std::upper_bound(s.t.begin(), s.t.end(), t1) - s.t.begin();
  w.is_position = is_position;
  const int n = w.n();
  f.n = n;
  if (n < w.num_parameters() + 4) return f;
  const double span = s.t[w.hi - 1] - s.t[w.lo];
  if (!(span > 0)) return f;
  for (std::size_t i = w.lo; i < w.hi; ++i) w.tbar += s.t[i];
  w.tbar /= n;
  w.start = s.t[w.lo];
  // Profile over τ on a log grid, then golden-section refinement around the best point.
  const double tau_lo = std::max(3.0 * span / (n - 1), 1e-3), tau_hi = span / 3.0;
  const bool tau_fixed = fixed_tau > 0;
  if (!(tau_hi > tau_lo) && !tau_fixed) return f;
  const double tau = tau_fixed ? fixed_tau : ProfiledTau(w, tau_lo, tau_hi);
  Eigen::Vector3d coef;
  const double rss = SettlingProfile(w, tau, &coef);
  SetSettlingEstimate(w, tau, tau_fixed, coef, rss, known_sigma, &f);
  return f;
}

double PooledNoiseAr1(const std::vector<const SpeedFit*>& fits) {
  std::vector<FittedResiduals> sets;
  for (const SpeedFit* f : fits) {
    if (!f->ok || f->fitted < 1 || !f->basis || f->basis->Q.rows() != f->n) continue;
    FittedResiduals r;
    r.basis = f->basis;  // shared, not computed again here
    r.sum_sq = f->residual_sd * f->residual_sd * (f->n - f->fitted);
    r.sum_lag1 = f->lag1 * r.sum_sq;
    sets.push_back(std::move(r));
  }
  return Ar1FromFittedResiduals(sets);
}

double Ar1SpeedSigma(const SpeedFit& fit, double rho, double noise_sigma) {
  if (fit.weights.empty()) return fit.sigma;
  double sd = noise_sigma;
  if (!(sd > 0)) {
    // E rss ≈ σ²·(n − q·(1 + ρ)/(1 − ρ)): fitted coefficients absorb q long-run variances.
    const double dof = fit.n - fit.fitted * (1 + rho) / (1 - rho);
    sd = fit.residual_sd * std::sqrt((fit.n - fit.fitted) / std::max(0.25 * fit.n, dof));
  }
  return sd * std::sqrt(std::max(0.0, Ar1QuadraticForm(fit.weights, rho)));
}

}  // namespace uuvplan::ident
