#include "uuvplan/ident/prepare/outliers.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "options_check.h"
#include "uuvplan/model/util/median.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {
namespace {

// Leave-one-out prediction of a sample by a local quadratic fitted to its neighbours (itself
// left out). Where it misses by more than the noise allows, its truncation error is estimated
// by the difference to a quartic through the same neighbours, also without the worst of them:
// neither prediction sees the sample, so a spike cannot hide in it, nor behind one spiked
// neighbour, while motion faster than a quadratic follows (the transient after a step
// measured by a precise sensor, where the truncation exceeds the noise a hundredfold) is
// allowed for.
constexpr int kQuadratic = 2, kQuartic = 4, kQuarticNeighbours = 7;

// The weights, on a uniform grid (offsets −hw…hw, the centre left out), of the quadratic's
// prediction at the centre: the same for every interior sample, one dot product.
std::vector<double> UniformQuadraticWeights(const Signal& s, int hw) {
  const std::size_t n = s.size();
  if (n < static_cast<std::size_t>(2 * hw + 1)) return {};
  const double h = (s.t.back() - s.t.front()) / (n - 1);
  for (std::size_t i = 1; i < n; ++i) {
    if (std::abs(s.t[i] - s.t[i - 1] - h) > 1e-3 * h) return {};
  }
  Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
  for (int j = -hw; j <= hw; ++j) {
    if (j == 0) continue;
    const Eigen::Vector3d v(1.0, j, double(j) * j);
    A += v * v.transpose();
  }
  const Eigen::Vector3d e0 = A.ldlt().solve(Eigen::Vector3d::Unit(0));  // row 0 of A⁻¹
  std::vector<double> w(2 * hw + 1, 0.0);
  for (int j = -hw; j <= hw; ++j) {
    if (j != 0) w[j + hw] = e0[0] + e0[1] * j + e0[2] * double(j) * j;
  }
  return w;
}

// The prediction of sample i by a degree-`degree` polynomial through `neighbours` (one of
// them left out when `drop` >= 0).
double LocalPrediction(const Signal& s, int i, const std::vector<int>& neighbours, int degree,
                       int drop = -1) {
  const int p = degree + 1;
  // Time scale: the span of the neighbourhood, for conditioning.
  const double scale = std::max(1e-12, s.t[neighbours.back()] - s.t[neighbours.front()]);
  Eigen::MatrixXd A = Eigen::MatrixXd::Zero(p, p);
  Eigen::VectorXd b = Eigen::VectorXd::Zero(p);
  Eigen::VectorXd v(p);
  for (int j : neighbours) {
    if (j == drop) continue;
    const double u = (s.t[j] - s.t[i]) / scale;
    v[0] = 1.0;
    for (int a = 1; a < p; ++a) v[a] = v[a - 1] * u;
    A += v * v.transpose();
    b += v * s.y[j];
  }
  return A.ldlt().solve(b)[0];
}

class LocalPredictor {
 public:
  /// `piece`: index of the piece between command steps of each sample (empty: one piece).
  LocalPredictor(const Signal& s, int hw, const std::vector<char>& skip, std::vector<int> piece)
      : s_(s),
        hw_(hw),
        skip_(skip),
        piece_(std::move(piece)),
        uniform_(UniformQuadraticWeights(s, hw)) {}

  /// y_i − quadratic prediction; NaN where fewer than 4 neighbours remain.
  double Residual(int i) const {
    const int n = static_cast<int>(s_.size());
    if (!uniform_.empty() && i >= hw_ && i + hw_ < n && SamePiece(i, i - hw_) &&
        SamePiece(i, i + hw_)) {
      bool clean = true;
      for (int j = i - hw_; j <= i + hw_ && clean; ++j) clean = j == i || !skip_[j];
      if (clean) {
        double p = 0.0;
        for (int j = -hw_; j <= hw_; ++j) p += uniform_[j + hw_] * s_.y[i + j];
        return s_.y[i] - p;
      }
    }
    const std::vector<int> nb = Neighbours(i, hw_);
    if (nb.size() < 4) return std::nan("");
    return s_.y[i] - LocalPrediction(s_, i, nb, kQuadratic);
  }

  /// The excess |y_i − quadratic| − allowance·(|quadratic − quartic| − limit)₊ (truncation
  /// beyond the noise `limit`: where the noise dominates, the plain test), the larger of that over
  /// the neighbours and that without the neighbour of largest |residual| (`residual`, NaN
  /// ignored): a spiked neighbour would otherwise hide a spike. Near the ends of a piece the
  /// neighbourhood is widened to twice the half window for the 7 a quartic needs; failing
  /// that, |Residual|.
  double Excess(int i, double allowance, double limit, const std::vector<double>& residual) const {
    std::vector<int> nb = Neighbours(i, hw_);
    if (static_cast<int>(nb.size()) < kQuarticNeighbours) nb = Neighbours(i, 2 * hw_);  // ends
    if (static_cast<int>(nb.size()) < kQuarticNeighbours) return std::abs(Residual(i));
    const auto excess = [&](int drop) {
      const double quadratic = LocalPrediction(s_, i, nb, kQuadratic, drop);
      const double truncation = std::abs(quadratic - LocalPrediction(s_, i, nb, kQuartic, drop));
      return std::abs(s_.y[i] - quadratic) - allowance * std::max(0.0, truncation - limit);
    };
    int worst = -1;
    for (int j : nb) {
      if (!std::isnan(residual[j]) &&
          (worst < 0 || std::abs(residual[j]) > std::abs(residual[worst]))) {
        worst = j;
      }
    }
    const double all = excess(-1);
    if (worst < 0 || static_cast<int>(nb.size()) <= kQuarticNeighbours) return all;
    return std::max(all, excess(worst));
  }

 private:
  bool SamePiece(int i, int j) const { return piece_.empty() || piece_[i] == piece_[j]; }

  // The neighbours of i are those of its own smooth piece where at least 4 are there: the
  // motion is analytic between command steps, while across one the acceleration jumps and the
  // position has a kink of size Δa·h² that no polynomial predicts. Pieces too short to fit
  // fall back to the whole neighbourhood.
  std::vector<int> Neighbours(int i, int half_window) const {
    const int lo = std::max(0, i - half_window);
    const int hi = std::min(static_cast<int>(s_.size()) - 1, i + half_window);
    std::vector<int> all, own;
    for (int j = lo; j <= hi; ++j) {
      if (j == i || skip_[j]) continue;
      all.push_back(j);
      if (SamePiece(i, j)) own.push_back(j);
    }
    return own.size() >= 4 ? own : all;
  }

  const Signal& s_;
  int hw_;
  const std::vector<char>& skip_;
  std::vector<int> piece_;
  std::vector<double> uniform_;
};

}  // namespace

bool OutlierOptions::IsValid(std::string* error) const {
  return Require(half_window >= 2 && threshold > 0 && !(noise_floor < 0) &&
                     !(truncation_allowance < 0) && finding_fraction >= 0 && finding_fraction <= 1,
                 "OutlierOptions: need half_window >= 2, threshold > 0, noise_floor >= 0, "
                 "truncation_allowance >= 0, finding_fraction in [0, 1]",
                 error);
}

std::string OutlierFinding(const std::string& trial, const std::string& signal,
                           std::size_t excluded, std::size_t total, const OutlierOptions& o) {
  if (total == 0 || !(static_cast<double>(excluded) > o.finding_fraction * total)) return "";
  return trial + ": " + std::to_string(excluded) + " of " + std::to_string(total) + " " + signal +
         " samples (" + model::Significant(100.0 * excluded / total, 3) +
         "%) excluded as outliers, more than " + model::Significant(100.0 * o.finding_fraction, 3) +
         "%: a sensor fault, a unit or timing mistake, or motion the outlier test takes for "
         "noise — look at the log before trusting this fit (the excluded times are in --json)";
}

std::vector<Outlier> DetectOutliers(const Signal& s, const OutlierOptions& o, double known_sigma,
                                    const CommandSteps* steps) {
  std::vector<Outlier> out;
  const std::size_t n = s.size();
  if (n < 8) return out;
  std::vector<char> skip(n, 0);
  std::vector<char> guarded(n, 0);
  std::vector<int> piece;
  if (steps) {
    for (double p : steps->t) {
      const double radius = steps->protect_radius;
      const auto lo = std::lower_bound(s.t.begin(), s.t.end(), p - radius) - s.t.begin();
      const auto hi = std::upper_bound(s.t.begin(), s.t.end(), p + radius) - s.t.begin();
      for (auto i = lo; i < hi; ++i) guarded[i] = 1;
    }
    piece.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      piece[i] = static_cast<int>(std::upper_bound(steps->t.begin(), steps->t.end(), s.t[i]) -
                                  steps->t.begin());
    }
  }
  const int hw = o.half_window;
  const LocalPredictor predictor(s, hw, skip, std::move(piece));
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = predictor.Residual(static_cast<int>(i));
  std::vector<double> abs_r;
  const std::size_t stride = std::max<std::size_t>(1, n / 100000);  // the MAD of ≤ 1e5 residuals
  abs_r.reserve(n / stride + 1);
  for (std::size_t i = 0; i < n; i += stride) {
    if (!guarded[i] && !std::isnan(r[i])) abs_r.push_back(std::abs(r[i]));
  }
  double limit = abs_r.empty() ? 0.0 : o.threshold * 1.4826 * model::Median(std::move(abs_r));
  if (known_sigma > 0) limit = std::max(limit, o.noise_floor * known_sigma);
  if (!(limit > 0)) return out;
  // Beyond the noise limit and the allowed truncation error (false for NaN).
  const auto is_outlier = [&](std::size_t i) {
    if (!(std::abs(r[i]) > limit)) return false;
    return o.truncation_allowance <= 0 ||
           predictor.Excess(static_cast<int>(i), o.truncation_allowance, limit, r) > limit;
  };
  std::vector<std::size_t> changed;
  for (std::size_t i = 0; i < n; ++i) {
    if (!guarded[i] && is_outlier(i)) changed.push_back(i);
  }
  for (std::size_t i : changed) skip[i] = 1;
  // Flagging a sample changes its neighbours' predictions: re-test the neighbourhood of every
  // change (a spike's neighbour flagged only because the spike spoiled its prediction is
  // cleared, a second spike hidden by the first is found), until nothing changes.
  for (int pass = 0; pass < 5 && !changed.empty(); ++pass) {
    std::vector<char> mark(n, 0);
    for (std::size_t c : changed) {
      const std::size_t lo = c >= static_cast<std::size_t>(hw) ? c - hw : 0;
      for (std::size_t i = lo; i <= std::min(n - 1, c + hw); ++i) mark[i] = 1;
    }
    std::vector<std::size_t> candidates;
    for (std::size_t i = 0; i < n; ++i) {
      if (mark[i]) candidates.push_back(i);
    }
    for (std::size_t i : candidates) r[i] = predictor.Residual(static_cast<int>(i));
    changed.clear();
    for (std::size_t i : candidates) {
      if (guarded[i] || std::isnan(r[i])) continue;
      const bool out_now = is_outlier(i);
      if (out_now != static_cast<bool>(skip[i])) {
        skip[i] = out_now;
        changed.push_back(i);
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (skip[i]) out.push_back({i, s.t[i], s.y[i], predictor.Residual(static_cast<int>(i))});
  }
  return out;
}

Signal RemoveSamples(const Signal& s, const std::vector<Outlier>& outliers) {
  if (outliers.empty()) return s;
  Signal out;
  out.t.reserve(s.size());
  out.y.reserve(s.size());
  std::size_t k = 0;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (k < outliers.size() && outliers[k].index == i) {
      ++k;
      continue;
    }
    out.t.push_back(s.t[i]);
    out.y.push_back(s.y[i]);
  }
  return out;
}

std::vector<Gap> FindGaps(model::TimesView t, double factor) {
  std::vector<Gap> gaps;
  if (t.size() < 3) return gaps;
  const double h = MedianStep(t, 0, t.size());
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i] - t[i - 1] > factor * h) gaps.push_back({t[i - 1], t[i]});
  }
  return gaps;
}

}  // namespace uuvplan::ident
