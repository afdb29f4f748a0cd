#include "uuvplan/ident/prepare/start_at_rest.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "uuvplan/ident/prepare/speed_fit.h"

namespace uuvplan::ident {
namespace {

constexpr double kUnresolved = std::numeric_limits<double>::quiet_NaN();

// A polynomial of `degree` in u = (t − t0)/T through the first n positions (T their span): the
// initial velocity dχ/dt(t0) and the top coefficient, each with its σ from white noise of sd
// `sigma` (the residuals' when sigma <= 0).
struct StartPolynomial {
  bool ok = false;
  double v0 = 0.0, v0_sd = 0.0;
  double top = 0.0, top_sd = 0.0;
};

StartPolynomial FitStartPolynomial(const Signal& p, int n, int degree, double sigma) {
  StartPolynomial f;
  const int k = degree + 1;
  const double t0 = p.t[0], span = p.t[n - 1] - t0;
  if (n <= k || !(span > 0)) return f;
  Eigen::MatrixXd V(n, k);
  Eigen::VectorXd y(n);
  for (int i = 0; i < n; ++i) {
    const double u = (p.t[i] - t0) / span;
    double power = 1.0;
    for (int j = 0; j < k; ++j, power *= u) V(i, j) = power;
    y[i] = p.y[i] - p.y[0];
  }
  const Eigen::MatrixXd N = V.transpose() * V;
  const Eigen::VectorXd c = N.ldlt().solve(V.transpose() * y);
  const double s = sigma > 0 ? sigma : (y - V * c).norm() / std::sqrt(double(n - k));
  const Eigen::MatrixXd cov = N.inverse();
  f.ok = std::isfinite(c[1]) && cov(1, 1) > 0;
  f.v0 = c[1] / span;
  f.v0_sd = s * std::sqrt(cov(1, 1)) / span;
  f.top = c[degree];
  f.top_sd = s * std::sqrt(cov(degree, degree));
  return f;
}

bool Resolved(double value, double sd) { return std::abs(value) >= 3.0 * std::max(sd, 1e-12); }

// The longest window of positions from the first, doubling from n0, before the first command
// step, over which a quartic term is not significant: a cubic still describes the motion there.
int LongestCubicStart(const TrialData& d, int n0, double sigma) {
  const Signal& p = d.position;
  const auto jump = std::upper_bound(d.force_jumps.begin(), d.force_jumps.end(), p.t[0]);
  const double step = jump == d.force_jumps.end() ? std::numeric_limits<double>::infinity() : *jump;
  int n = n0;
  for (long next = 2L * n; next <= static_cast<long>(p.size()); next *= 2) {
    if (p.t[next - 1] >= step) break;
    const StartPolynomial quartic = FitStartPolynomial(p, static_cast<int>(next), 4, sigma);
    if (!quartic.ok || Resolved(quartic.top, quartic.top_sd)) break;
    n = static_cast<int>(next);
  }
  return n;
}

TrialStart PositionsStart(const TrialData& d) {
  const Signal& p = d.position;
  const int n0 = std::min<int>(static_cast<int>(p.size()), std::max(d.sg_window, 7));
  if (n0 < 5) return {};
  const StartPolynomial first = FitStartPolynomial(p, n0, 2, d.position_sigma);
  if (first.ok && !Resolved(first.v0, first.v0_sd)) return {};
  const int n = LongestCubicStart(d, n0, d.position_sigma);
  if (n == n0) return {false, kUnresolved};
  const StartPolynomial longest = FitStartPolynomial(p, n, 3, d.position_sigma);
  return {false, longest.ok ? longest.v0 : kUnresolved};
}

}  // namespace

TrialStart JudgeStart(const TrialData& d) {
  if (d.has_velocity()) {
    const double h = d.velocity.t[1] - d.velocity.t[0];
    const double t_end = d.velocity.t.front() + std::max(0.2, 5.0 * h);
    const SpeedFit f = MeanSpeedFit(d.velocity, d.velocity.t.front(), t_end, d.velocity_sigma);
    return {f.ok && std::abs(f.speed) < 3.0 * std::max(f.sigma, 1e-12), kUnresolved};
  }
  return PositionsStart(d);
}

}  // namespace uuvplan::ident
