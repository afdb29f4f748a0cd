// The steady-state part of each constant-force piece (steady_detection.h, ref 000 §III).
#include "uuvplan/ident/prepare/steady_detection.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>

#include "options_check.h"

namespace uuvplan::ident {

bool SteadyDetectionOptions::IsValid(std::string* error) const {
  return Require(min_duration_s > 0 && min_samples >= 4 && z > 0 && stride >= 0,
                 "SteadyDetectionOptions: need min_duration_s > 0, min_samples >= 4, z > 0, "
                 "stride >= 0",
                 error);
}

namespace {

// Suffix sums of u^k (k = 0..4), u^k·y (k = 0..2) and y² for O(1) polynomial fits of any tail.
struct TailSums {
  std::vector<std::array<double, 9>> s;  // s[i] = sums over samples i..end
  TailSums(const std::vector<double>& u, const std::vector<double>& y) : s(u.size() + 1) {
    s.back().fill(0.0);
    for (std::size_t k = u.size(); k-- > 0;) {
      const double a = u[k], a2 = a * a;
      s[k] = s[k + 1];
      const double add[9] = {1, a, a2, a2 * a, a2 * a2, y[k], a * y[k], a2 * y[k], y[k] * y[k]};
      for (int j = 0; j < 9; ++j) s[k][j] += add[j];
    }
  }
};

// Quadratic (or, for velocities, linear) fit of the tail from sample i: the change of speed
// across [u_i, u_end] and its σ (known noise or residual estimate).
bool TailChange(const TailSums& ts, std::size_t i, double u0, double u1, bool quadratic,
                double known_sigma, double* change, double* sigma) {
  const auto& s = ts.s[i];
  const int q = quadratic ? 3 : 2;
  Eigen::Matrix3d A;
  Eigen::Vector3d b;
  for (int r = 0; r < q; ++r) {
    for (int c = 0; c < q; ++c) A(r, c) = s[r + c];
    b[r] = s[5 + r];
  }
  const Eigen::MatrixXd Aq = A.topLeftCorner(q, q);
  Eigen::LDLT<Eigen::MatrixXd> ldlt(Aq);
  if (ldlt.info() != Eigen::Success) return false;
  const Eigen::VectorXd a = ldlt.solve(b.head(q));
  const Eigen::MatrixXd Ainv = ldlt.solve(Eigen::MatrixXd::Identity(q, q));
  const double n = s[0];
  // rss = Σy² − aᵀb for the normal-equation solution.
  const double rss = std::max(0.0, s[8] - a.dot(b.head(q)));
  const double var = known_sigma > 0 ? known_sigma * known_sigma : rss / std::max(1.0, n - q);
  // Quadratic position fit: v(u) = a1 + 2 a2 u, change = 2 a2 (u1 − u0) (per unit u).
  // Linear velocity fit: v(u) = a0 + a1 u, change = a1 (u1 − u0).
  const int j = quadratic ? 2 : 1;
  const double factor = (quadratic ? 2.0 : 1.0) * (u1 - u0);
  *change = factor * a[j];
  *sigma = std::abs(factor) * std::sqrt(var * Ainv(j, j));
  return true;
}

}  // namespace

std::vector<SteadySegment> DetectSteadySegments(const Signal& s, bool is_position,
                                                const std::vector<ForcePiece>& pieces,
                                                const SteadyDetectionOptions& o,
                                                double known_sigma) {
  std::vector<SteadySegment> out;
  for (std::size_t p = 0; p < pieces.size(); ++p) {
    const ForcePiece& piece = pieces[p];
    if (piece.t1 - piece.t0 < o.min_duration_s) continue;
    const auto lo = std::lower_bound(s.t.begin(), s.t.end(), piece.t0) - s.t.begin();
    const auto hi = std::upper_bound(s.t.begin(), s.t.end(), piece.t1) - s.t.begin();
    const int n = static_cast<int>(hi - lo);
    if (n < o.min_samples) continue;
    // u = (t − t0)/(t1 − t0) in [0, 1]; position values centred for conditioning.
    const double span = piece.t1 - piece.t0;
    std::vector<double> u(n), y(n);
    const double y0 = s.y[lo];
    for (int i = 0; i < n; ++i) {
      u[i] = (s.t[lo + i] - piece.t0) / span;
      y[i] = s.y[lo + i] - y0;
    }
    const TailSums ts(u, y);
    const int stride = o.stride > 0 ? o.stride : std::max(1, n / 200);
    const double t_end = s.t[hi - 1];
    for (int i = 0; i + o.min_samples <= n; i += stride) {
      const double t_start = s.t[lo + i];
      if (t_end - t_start < o.min_duration_s) break;
      SteadySegment seg;
      seg.piece = static_cast<int>(p);
      double change = 0.0, sigma = 0.0;
      if (!TailChange(ts, i, u[i], u[n - 1], is_position, known_sigma, &change, &sigma)) continue;
      if (std::abs(change) > o.z * sigma) continue;
      // Second test: the two halves' constant speeds agree.
      const double t_mid = 0.5 * (t_start + t_end);
      const SpeedFit a = is_position ? ConstantSpeedFit(s, t_start, t_mid, known_sigma)
                                     : MeanSpeedFit(s, t_start, t_mid, known_sigma);
      const SpeedFit b = is_position ? ConstantSpeedFit(s, t_mid, t_end, known_sigma)
                                     : MeanSpeedFit(s, t_mid, t_end, known_sigma);
      if (!a.ok || !b.ok) continue;
      if (std::abs(a.speed - b.speed) > o.z * std::hypot(a.sigma, b.sigma)) continue;
      seg.fit = is_position ? ConstantSpeedFit(s, t_start, piece.t1, known_sigma)
                            : MeanSpeedFit(s, t_start, piece.t1, known_sigma);
      if (o.transient_model) {
        // What remains of the transient is below the tests' power but can still bias the
        // constant speed by several σ: fit it out (SettlingSpeedFit).
        const SettlingFit settling =
            SettlingSpeedFit(s, is_position, t_start, piece.t1, known_sigma);
        if (settling.ok) seg.fit = settling;
      }
      if (seg.fit.ok) out.push_back(seg);
      break;
    }
  }
  return out;
}

}  // namespace uuvplan::ident
