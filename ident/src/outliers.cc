#include "uuvplan/ident/outliers.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

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
std::vector<double> PredictionResiduals(const Signal& s, int hw, const std::vector<char>& skip) {
  const int n = static_cast<int>(s.size());
  std::vector<double> r(n, std::nan(""));
  for (int i = 0; i < n; ++i) {
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
    if (count < 4) continue;
    const Eigen::Vector3d coef = A.ldlt().solve(b);
    r[i] = s.y[i] - coef[0];
  }
  return r;
}

}  // namespace

bool OutlierOptions::IsValid(std::string* error) const {
  if (half_window < 2 || !(threshold > 0) || noise_floor < 0) {
    if (error) *error = "OutlierOptions: need half_window >= 2, threshold > 0, noise_floor >= 0";
    return false;
  }
  return true;
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
  for (int pass = 0; pass < 2; ++pass) {
    const std::vector<double> r = PredictionResiduals(s, o.half_window, skip);
    std::vector<double> abs_r;
    abs_r.reserve(n);
    for (std::size_t i = 0; i < n; ++i) {
      if (!skip[i] && !guarded[i] && !std::isnan(r[i])) abs_r.push_back(std::abs(r[i]));
    }
    const double scale = 1.4826 * MedianOf(abs_r);
    double limit = o.threshold * scale;
    if (known_sigma > 0) limit = std::max(limit, o.noise_floor * known_sigma);
    if (!(limit > 0)) break;
    bool added = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (!skip[i] && !guarded[i] && !std::isnan(r[i]) && std::abs(r[i]) > limit) {
        skip[i] = 1;
        added = true;
      }
    }
    if (!added) break;
  }
  // Re-test every flagged sample against its clean neighbours: a neighbour of a spike may have
  // been flagged only because the spike spoiled its prediction.
  for (int pass = 0; pass < 3; ++pass) {
    const std::vector<double> r = PredictionResiduals(s, o.half_window, skip);
    std::vector<double> abs_r;
    for (std::size_t i = 0; i < n; ++i) {
      if (!skip[i] && !guarded[i] && !std::isnan(r[i])) abs_r.push_back(std::abs(r[i]));
    }
    double limit = o.threshold * 1.4826 * MedianOf(abs_r);
    if (known_sigma > 0) limit = std::max(limit, o.noise_floor * known_sigma);
    bool changed = false;
    for (std::size_t i = 0; i < n; ++i) {
      if (skip[i] && !std::isnan(r[i]) && std::abs(r[i]) <= limit) {
        skip[i] = 0;
        changed = true;
      }
    }
    if (!changed) break;
  }
  const std::vector<double> r = PredictionResiduals(s, o.half_window, skip);
  for (std::size_t i = 0; i < n; ++i) {
    if (skip[i]) out.push_back({i, s.t[i], s.y[i], r[i]});
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
  std::vector<double> steps;
  steps.reserve(t.size());
  for (std::size_t i = 1; i < t.size(); ++i) steps.push_back(t[i] - t[i - 1]);
  const double h = MedianOf(steps);
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i] - t[i - 1] > factor * h) gaps.push_back({t[i - 1], t[i]});
  }
  return gaps;
}

}  // namespace uuvplan::ident
