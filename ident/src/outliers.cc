#include "uuvplan/ident/outliers.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

#include "number_text.h"
#include "options_check.h"

namespace uuvplan::ident {
namespace {

double MedianOf(std::vector<double> v) {
  if (v.empty()) return 0.0;
  const std::size_t mid = v.size() / 2;
  std::nth_element(v.begin(), v.begin() + mid, v.end());
  return v[mid];
}

// Prediction residuals y_i − p_i(t_i), p_i the quadratic through the (non-excluded)
// neighbours of i. NaN where too few neighbours remain.
// The prediction residual of sample i.
// Leave-one-out prediction weights of a local quadratic on a uniform grid (offsets −hw…hw,
// the centre left out): the same for every interior sample, so one dot product each.
struct UniformPredictor {
  bool uniform = false;
  std::vector<double> w;  // 2·hw + 1 entries, w[hw] = 0
  UniformPredictor(const Signal& s, int hw) {
    const std::size_t n = s.size();
    if (n < static_cast<std::size_t>(2 * hw + 1)) return;
    const double h = (s.t.back() - s.t.front()) / (n - 1);
    for (std::size_t i = 1; i < n; ++i) {
      if (std::abs(s.t[i] - s.t[i - 1] - h) > 1e-3 * h) return;
    }
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    for (int j = -hw; j <= hw; ++j) {
      if (j == 0) continue;
      const double v[3] = {1.0, double(j), double(j) * j};
      for (int a = 0; a < 3; ++a) {
        for (int c = 0; c < 3; ++c) A(a, c) += v[a] * v[c];
      }
    }
    const Eigen::Vector3d e0 = A.ldlt().solve(Eigen::Vector3d::Unit(0));  // row 0 of A⁻¹
    w.assign(2 * hw + 1, 0.0);
    for (int j = -hw; j <= hw; ++j) {
      if (j != 0) w[j + hw] = e0[0] + e0[1] * j + e0[2] * double(j) * j;
    }
    uniform = true;
  }
};

double PredictionResidual(const Signal& s, int hw, const std::vector<char>& skip, int i,
                          const UniformPredictor* up = nullptr) {
  const int n = static_cast<int>(s.size());
  if (up && up->uniform && i >= hw && i + hw < n) {
    bool clean = true;
    for (int j = i - hw; j <= i + hw && clean; ++j) clean = j == i || !skip[j];
    if (clean) {
      double p = 0.0;
      for (int j = -hw; j <= hw; ++j) p += up->w[j + hw] * s.y[i + j];
      return s.y[i] - p;
    }
  }
  {
    Eigen::Matrix3d A = Eigen::Matrix3d::Zero();
    Eigen::Vector3d b = Eigen::Vector3d::Zero();
    int count = 0;
    // Time scale: the span of the neighbourhood, for conditioning.
    const int lo = std::max(0, i - hw), hi = std::min(n - 1, i + hw);
    const double scale = std::max(1e-12, s.t[hi] - s.t[lo]);
    for (int j = lo; j <= hi; ++j) {
      if (j == i || skip[j]) continue;
      const double u = (s.t[j] - s.t[i]) / scale;
      const double v[3] = {1.0, u, u * u};
      for (int a = 0; a < 3; ++a) {
        b[a] += v[a] * s.y[j];
        for (int c = 0; c < 3; ++c) A(a, c) += v[a] * v[c];
      }
      ++count;
    }
    if (count < 4) return std::nan("");
    const Eigen::Vector3d coef = A.ldlt().solve(b);
    return s.y[i] - coef[0];
  }
}

}  // namespace

bool OutlierOptions::IsValid(std::string* error) const {
  return Require(half_window >= 2 && threshold > 0 && !(noise_floor < 0) &&
                     finding_fraction >= 0 && finding_fraction <= 1,
                 "OutlierOptions: need half_window >= 2, threshold > 0, noise_floor >= 0, "
                 "finding_fraction in [0, 1]",
                 error);
}

std::string OutlierFinding(const std::string& trial, const std::string& signal,
                           std::size_t excluded, std::size_t total, const OutlierOptions& o) {
  if (total == 0 || !(static_cast<double>(excluded) > o.finding_fraction * total)) return "";
  return trial + ": " + std::to_string(excluded) + " of " + std::to_string(total) + " " + signal +
         " samples (" + Fmt(100.0 * excluded / total, 3) + "%) excluded as outliers, more than " +
         Fmt(100.0 * o.finding_fraction, 3) +
         "%: a sensor fault, a unit or timing mistake, or motion the outlier test takes for "
         "noise — look at the log before trusting this fit (the excluded times are in --json)";
}

std::vector<Outlier> DetectOutliers(const Signal& s, const OutlierOptions& o,
                                    double known_sigma, const std::vector<double>* protect,
                                    double protect_radius) {
  std::vector<Outlier> out;
  const std::size_t n = s.size();
  if (n < 8) return out;
  std::vector<char> skip(n, 0);
  std::vector<char> guarded(n, 0);
  if (protect) {
    for (double p : *protect) {
      const auto lo = std::lower_bound(s.t.begin(), s.t.end(), p - protect_radius) - s.t.begin();
      const auto hi = std::upper_bound(s.t.begin(), s.t.end(), p + protect_radius) - s.t.begin();
      for (auto i = lo; i < hi; ++i) guarded[i] = 1;
    }
  }
  const int hw = o.half_window;
  const UniformPredictor up(s, hw);
  std::vector<double> r(n);
  for (std::size_t i = 0; i < n; ++i) r[i] = PredictionResidual(s, hw, skip, static_cast<int>(i), &up);
  std::vector<double> abs_r;
  const std::size_t stride = std::max<std::size_t>(1, n / 100000);  // the MAD of ≤ 1e5 residuals
  abs_r.reserve(n / stride + 1);
  for (std::size_t i = 0; i < n; i += stride) {
    if (!guarded[i] && !std::isnan(r[i])) abs_r.push_back(std::abs(r[i]));
  }
  double limit = o.threshold * 1.4826 * MedianOf(abs_r);
  if (known_sigma > 0) limit = std::max(limit, o.noise_floor * known_sigma);
  if (!(limit > 0)) return out;
  std::vector<std::size_t> changed;
  for (std::size_t i = 0; i < n; ++i) {
    if (!guarded[i] && !std::isnan(r[i]) && std::abs(r[i]) > limit) {
      skip[i] = 1;
      changed.push_back(i);
    }
  }
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
    for (std::size_t i : candidates) r[i] = PredictionResidual(s, hw, skip, static_cast<int>(i), &up);
    changed.clear();
    for (std::size_t i : candidates) {
      if (guarded[i] || std::isnan(r[i])) continue;
      const bool out_now = std::abs(r[i]) > limit;
      if (out_now != static_cast<bool>(skip[i])) {
        skip[i] = out_now;
        changed.push_back(i);
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (skip[i]) out.push_back({i, s.t[i], s.y[i], PredictionResidual(s, hw, skip, static_cast<int>(i))});
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

std::vector<Gap> FindGaps(const std::vector<double>& t, double factor) {
  std::vector<Gap> gaps;
  if (t.size() < 3) return gaps;
  const double h = MedianStep(t, 0, t.size());
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i] - t[i - 1] > factor * h) gaps.push_back({t[i - 1], t[i]});
  }
  return gaps;
}

}  // namespace uuvplan::ident
