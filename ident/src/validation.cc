#include "uuvplan/ident/validation.h"

#include <algorithm>
#include <iterator>
#include <cmath>
#include <limits>

#include "uuvplan/model/simulator.h"

namespace uuvplan::ident {
namespace {
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
}

ResidualAnalysis AnalyzeResiduals(const std::vector<double>& r, int max_lag, int bins,
                                  double step_s) {
  ResidualAnalysis a;
  a.n = static_cast<int>(r.size());
  a.lag_step_s = step_s;
  if (a.n == 0) return a;
  double sum = 0.0, sum2 = 0.0;
  for (double v : r) {
    sum += v;
    sum2 += v * v;
  }
  a.mean = sum / a.n;
  a.rms = std::sqrt(sum2 / a.n);
  double m2 = 0.0, m3 = 0.0, m4 = 0.0;
  for (double v : r) {
    const double c = v - a.mean;
    m2 += c * c;
    m3 += c * c * c;
    m4 += c * c * c * c;
  }
  m2 /= a.n;
  m3 /= a.n;
  m4 /= a.n;
  a.std = a.n > 1 ? std::sqrt(m2 * a.n / (a.n - 1)) : 0.0;
  // Normalised autocorrelation (seed 004 Fig. 4) with 95% bounds for white noise.
  const int L = std::min(max_lag, a.n - 1);
  a.autocorrelation.assign(L + 1, 0.0);
  a.bound95 = 1.959963984540054 / std::sqrt(static_cast<double>(a.n));
  if (m2 > 0) {
    for (int l = 0; l <= L; ++l) {
      double c = 0.0;
      for (int i = l; i < a.n; ++i) c += (r[i] - a.mean) * (r[i - l] - a.mean);
      a.autocorrelation[l] = c / (m2 * a.n);
    }
    for (int l = 1; l <= L; ++l) {
      if (std::abs(a.autocorrelation[l]) > a.bound95) ++a.lags_outside;
    }
    a.histogram.skewness = m3 / std::pow(m2, 1.5);
    a.histogram.excess_kurtosis = m4 / (m2 * m2) - 3.0;
  }
  // White when no more lags fall outside than white noise puts there 99% of the time: the 99%
  // quantile of Binomial(L, 0.05) (lags treated as independent), e.g. 3 of 20.
  int allowed = 0;
  {
    double cdf = 0.0, term = std::pow(0.95, L);  // P(X = 0)
    for (int c = 0; c <= L; ++c) {
      cdf += term;
      if (cdf >= 0.99) {
        allowed = c;
        break;
      }
      term *= (L - c) / (c + 1.0) * (0.05 / 0.95);
    }
  }
  a.white = L > 0 && a.lags_outside <= allowed;
  // Histogram over mean ± 4σ.
  if (bins > 0 && a.std > 0) {
    const double lo = a.mean - 4 * a.std, hi = a.mean + 4 * a.std;
    a.histogram.edges.resize(bins + 1);
    for (int b = 0; b <= bins; ++b) a.histogram.edges[b] = lo + (hi - lo) * b / bins;
    a.histogram.counts.assign(bins, 0);
    for (double v : r) {
      const int b = std::clamp(static_cast<int>(std::floor((v - lo) / (hi - lo) * bins)), 0, bins - 1);
      ++a.histogram.counts[b];
    }
  }
  return a;
}

namespace {

// Up to `points` of the samples of `s` at t >= 0 (the ones `r`, measured − model, is of).
FreeRunCurve Decimate(const Signal& s, const std::vector<double>& r, int points) {
  FreeRunCurve c;
  std::size_t first = 0;
  while (first < s.size() && s.t[first] < 0) ++first;
  const std::size_t n = std::min(r.size(), s.size() - first);
  const std::size_t stride = std::max<std::size_t>(1, (n + points - 1) / points);
  for (std::size_t k = 0; k < n; k += stride) {
    c.t.push_back(s.t[first + k]);
    c.measured.push_back(s.y[first + k]);
    c.simulated.push_back(s.y[first + k] - r[k]);
  }
  return c;
}

}  // namespace

TrialFit ValidateTrial(const model::DofModel& model, const Eigen::VectorXd& theta,
                       const TrialData& trial, const ValidationOptions& o,
                       const Eigen::VectorXd* x0_given) {
  TrialFit f;
  f.trial = trial.index;
  f.name = trial.name;
  f.use = trial.use;
  f.position_rms = kNaN;
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(model.num_states());
  if (x0_given) {
    x0.head(std::min<Eigen::Index>(x0_given->size(), x0.size())) =
        x0_given->head(std::min<Eigen::Index>(x0_given->size(), x0.size()));
  } else {
    x0[0] = std::isfinite(trial.initial_position) ? trial.initial_position : 0.0;
    x0[1] = std::isfinite(trial.initial_velocity) ? trial.initial_velocity : 0.0;
  }
  f.initial_position = x0[0];
  f.initial_velocity = x0[1];
  // Velocity reference: measured, else the Savitzky–Golay estimate away from the edges.
  Signal vref_estimated;
  const Signal* vref_ptr = &vref_estimated;
  if (trial.has_velocity()) {
    vref_ptr = &trial.velocity;  // no copy: a gyro log may hold millions of samples
    f.velocity_reference = "measured";
  } else {
    Signal& vref = vref_estimated;
    const SmoothedSignal& v = trial.velocity_estimate;
    for (std::size_t i = 0; i < v.size(); ++i) {
      if (!v.edge[i] && std::isfinite(v.value[i])) {
        vref.t.push_back(v.t[i]);
        vref.y.push_back(v.value[i]);
      }
    }
    f.velocity_reference = "estimated";
  }
  const Signal& vref = *vref_ptr;
  std::vector<double> times;
  times.reserve(vref.size() + trial.position.size());
  std::merge(vref.t.begin(), vref.t.end(), trial.position.t.begin(), trial.position.t.end(),
             std::back_inserter(times));
  times.erase(std::unique(times.begin(), times.end()), times.end());
  times.erase(times.begin(), std::lower_bound(times.begin(), times.end(), 0.0));
  if (times.empty()) return f;
  model::SimulationOptions so;
  so.step_s = o.step_s;
  // Sensors much faster than the RK4 step: simulate on a grid of about one step (and the
  // input's breakpoints) and interpolate linearly (error ~ step²/8·|ξ''|, far below any MAE).
  const double span = times.back() - times.front();
  const bool dense = times.size() > 4 * (span / o.step_s + 1);
  std::vector<double> grid;
  if (dense) {
    for (double t = 0.0; t < times.back(); t += o.step_s) grid.push_back(t);
    grid.push_back(times.back());
    for (double b : trial.breakpoints) {
      if (b < times.back()) grid.push_back(b);
    }
    std::sort(grid.begin(), grid.end());
    grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  }
  const model::Trajectory sim =
      model::SimulateMeasured(model, theta, trial.conditions(), dense ? grid : times, so, &x0);
  // The model's state c at a sample time t (every sample time is in `times`; the queries of
  // each signal come in increasing order): the simulation at t, or on the dense grid
  // interpolated linearly — nothing is materialised at millions of sample times.
  std::size_t cursor = 0, g = 0;
  auto model_at = [&](double t, int c) {
    if (!dense) {
      if (cursor >= times.size() || times[cursor] > t) cursor = 0;
      while (cursor < times.size() && times[cursor] < t) ++cursor;
      return sim.x(cursor, c);
    }
    if (g >= grid.size() || grid[g] > t) g = 0;
    while (g + 2 < grid.size() && grid[g + 1] < t) ++g;
    const double w = grid[g + 1] > grid[g] ? (t - grid[g]) / (grid[g + 1] - grid[g]) : 0.0;
    return sim.x(g, c) + w * (sim.x(g + 1, c) - sim.x(g, c));
  };
  double sum_abs = 0.0, sum_abs_zero = 0.0;
  std::vector<double> verr;
  for (std::size_t k = 0; k < vref.size(); ++k) {
    if (vref.t[k] < 0) continue;
    const double e = model_at(vref.t[k], 1) - vref.y[k];  // ν_model − ν_measured (eq. 37)
    sum_abs += std::abs(e);
    sum_abs_zero += std::abs(vref.y[k]);
    verr.push_back(-e);
  }
  f.velocity_samples = static_cast<int>(verr.size());
  f.velocity_mae = f.velocity_samples > 0 ? sum_abs / f.velocity_samples : kNaN;
  f.zero_velocity_mae = f.velocity_samples > 0 ? sum_abs_zero / f.velocity_samples : kNaN;
  std::vector<double> perr;
  cursor = 0;
  g = 0;
  if (trial.has_position()) {
    double ss = 0.0;
    for (std::size_t k = 0; k < trial.position.size(); ++k) {
      if (trial.position.t[k] < 0) continue;
      const double e = trial.position.y[k] - model_at(trial.position.t[k], 0);
      ss += e * e;
      perr.push_back(e);
    }
    f.position_samples = static_cast<int>(perr.size());
    f.position_rms = f.position_samples > 0 ? std::sqrt(ss / f.position_samples) : kNaN;
  }
  const bool use_pos = !perr.empty();
  const std::vector<double>& r = use_pos ? perr : verr;
  const Signal& s = use_pos ? trial.position : vref;
  const double step = s.size() > 1 ? (s.t.back() - s.t.front()) / (s.size() - 1) : 0.0;
  f.residuals = AnalyzeResiduals(r, o.max_lag, o.bins, step);
  f.residual_signal = use_pos ? "position" : "velocity";
  if (o.curve_points > 0) f.curve = Decimate(s, r, o.curve_points);
  return f;
}

FitSummary Summarize(std::vector<TrialFit> trials) {
  FitSummary s;
  s.trials = std::move(trials);
  double va[3] = {0, 0, 0}, za[3] = {0, 0, 0}, pa[3] = {0, 0, 0};
  int vn[3] = {0, 0, 0}, pn[3] = {0, 0, 0};
  for (const TrialFit& f : s.trials) {
    const int u = f.use == model::TrialUse::kFit ? 0 : 1;
    for (int k : {u, 2}) {
      if (f.velocity_samples > 0) {
        va[k] += f.velocity_mae * f.velocity_samples;
        za[k] += f.zero_velocity_mae * f.velocity_samples;
        vn[k] += f.velocity_samples;
      }
      if (f.position_samples > 0) {
        pa[k] += f.position_rms * f.position_rms * f.position_samples;
        pn[k] += f.position_samples;
      }
    }
  }
  auto mae = [&](int k) { return vn[k] > 0 ? va[k] / vn[k] : kNaN; };
  auto rms = [&](int k) { return pn[k] > 0 ? std::sqrt(pa[k] / pn[k]) : kNaN; };
  s.velocity_mae_fit = mae(0);
  s.velocity_mae_validate = mae(1);
  s.velocity_mae_all = mae(2);
  s.zero_velocity_mae_fit = vn[0] > 0 ? za[0] / vn[0] : kNaN;
  s.zero_velocity_mae_validate = vn[1] > 0 ? za[1] / vn[1] : kNaN;
  s.position_rms_fit = rms(0);
  s.position_rms_validate = rms(1);
  s.position_rms_all = rms(2);
  return s;
}

}  // namespace uuvplan::ident
