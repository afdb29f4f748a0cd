#include "uuvplan/ident/validation.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "uuvplan/model/simulator.h"
#include "uuvplan/model/util/numbers.h"

namespace uuvplan::ident {
namespace {
using model::kNaN;
}

template <class Real>
ResidualAnalysis AnalyzeResiduals(const std::vector<Real>& r, int max_lag, int bins,
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
  // Normalised autocorrelation (ref 004 Fig. 4) with 95% bounds for white noise.
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
      const int b =
          std::clamp(static_cast<int>(std::floor((v - lo) / (hi - lo) * bins)), 0, bins - 1);
      ++a.histogram.counts[b];
    }
  }
  return a;
}
template ResidualAnalysis AnalyzeResiduals(const std::vector<double>&, int, int, double);
template ResidualAnalysis AnalyzeResiduals(const std::vector<float>&, int, int, double);

namespace {

// Up to `points` of the samples of `s` at t >= 0 (the ones `r`, measured − model, is of).
template <class Real>
FreeRunCurve Decimate(const Signal& s, const std::vector<Real>& r, int points) {
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

// The union of two sorted sample-time lists, duplicates and negative times left out: its
// size and ends, and (when `out` is not null) the times themselves.
struct SampleTimes {
  std::size_t count = 0;
  double first = 0.0, last = 0.0;
};
SampleTimes MergedTimes(model::TimesView a, model::TimesView b, std::vector<double>* out) {
  SampleTimes s;
  auto i = static_cast<std::size_t>(std::lower_bound(a.begin(), a.end(), 0.0) - a.begin());
  auto j = static_cast<std::size_t>(std::lower_bound(b.begin(), b.end(), 0.0) - b.begin());
  while (i < a.size() || j < b.size()) {
    const bool from_a = j == b.size() || (i < a.size() && a[i] <= b[j]);
    const double t = from_a ? a[i++] : b[j++];
    if (s.count > 0 && t == s.last) continue;
    if (s.count++ == 0) s.first = t;
    s.last = t;
    if (out) out->push_back(t);
  }
  return s;
}

// The velocity the free run is compared with, visit(t, ν) at each of its samples: the measured
// one, else the Savitzky–Golay estimate away from the edges.
template <class Visit>
void ForEachVelocityReference(const TrialData& trial, const Visit& visit) {
  if (trial.has_velocity()) {
    for (std::size_t i = 0; i < trial.velocity.size(); ++i)
      visit(trial.velocity.t[i], trial.velocity.y[i]);
    return;
  }
  const SmoothedSignal& v = trial.velocity_estimate;
  for (std::size_t i = 0; i < v.size(); ++i) {
    if (!v.edge[i] && std::isfinite(v.value[i])) visit(v.t[i], v.value[i]);
  }
}

// The samples of the velocity reference (ForEachVelocityReference), as a signal: the measured
// one itself, else the estimate's copied into `estimated`.
const Signal& VelocityReference(const TrialData& trial, Signal* estimated) {
  if (trial.has_velocity()) return trial.velocity;  // no copy: a gyro log may hold millions
  ForEachVelocityReference(trial, [&](double t, double v) {
    estimated->t.push_back(t);
    estimated->y.push_back(v);
  });
  return *estimated;
}

// Sensors much faster than the RK4 step: more than about four samples a step.
bool Dense(const SampleTimes& span, double step_s) {
  return span.count > 4 * ((span.last - span.first) / step_s + 1);
}

// The model's free run over a trial's sample times (the velocity reference's and the
// positions'), and its state c at a sample time t: the simulation at t, or, for dense sensors,
// on a grid of about one step (and the input's breakpoints) interpolated linearly (error
// ~ step²/8·|ξ''|, far below any MAE) — the union of the sample times is then not
// materialised (8–16 bytes a sample). Only position and velocity are kept (16 bytes a
// simulated time, not a trajectory's 24–32). Queries come in increasing t within one signal
// (Rewind between signals). ScoreVisitedFreeRun stores nothing where the times are the
// positions' own.
class FreeRun {
 public:
  FreeRun(const model::DofModel& model, const Eigen::VectorXd& theta, const TrialData& trial,
          model::TimesView velocity_times, double step_s, Eigen::VectorXd x0) {
    const SampleTimes span = MergedTimes(velocity_times, trial.position.t, nullptr);
    if (span.count == 0) return;
    dense_ = Dense(span, step_s);
    if (dense_) {
      for (double t = 0.0; t < span.last; t += step_s) times_.push_back(t);
      times_.push_back(span.last);
      for (double b : trial.breakpoints()) {
        if (b < span.last) times_.push_back(b);
      }
      std::sort(times_.begin(), times_.end());
      times_.erase(std::unique(times_.begin(), times_.end()), times_.end());
    } else {
      times_.reserve(span.count);
      MergedTimes(velocity_times, trial.position.t, &times_);
    }
    model::SimulationOptions so;
    so.step_s = step_s;
    position_.resize(times_.size());
    velocity_.resize(times_.size());
    model::SimulateVisiting(model, theta, trial.conditions(), times_, so, &x0,
                            model::Seen::kBySensors,
                            [&](std::size_t i, const double* x, const double*) {
                              position_[i] = x[0];
                              velocity_[i] = x[1];
                            });
  }
  bool empty() const { return times_.empty(); }
  void Rewind() { g_ = 0; }
  /// State c (0 position, 1 velocity) at sample time t.
  double At(double t, int c) {
    const std::vector<double>& x = c == 0 ? position_ : velocity_;
    if (!dense_) {  // every sample time is a simulated time
      if (g_ >= times_.size() || times_[g_] > t) g_ = 0;
      while (g_ < times_.size() && times_[g_] < t) ++g_;
      return x[g_];
    }
    if (g_ >= times_.size() || times_[g_] > t) g_ = 0;
    while (g_ + 2 < times_.size() && times_[g_ + 1] < t) ++g_;
    const double w =
        times_[g_ + 1] > times_[g_] ? (t - times_[g_]) / (times_[g_ + 1] - times_[g_]) : 0.0;
    return x[g_] + w * (x[g_ + 1] - x[g_]);
  }

 private:
  bool dense_ = false;
  std::vector<double> times_;                ///< the simulated times
  std::vector<double> position_, velocity_;  ///< the free run at times_
  std::size_t g_ = 0;
};

// True when the free run is simulated at the positions' own times: an estimated velocity (its
// samples are the positions'), sensors not dense, each time once and none negative.
bool SimulatedAtPositionTimes(const TrialData& trial, double step_s) {
  if (trial.has_velocity() || trial.velocity_estimate.size() != trial.position.size()) return false;
  const SampleTimes span = MergedTimes(trial.position.t, trial.position.t, nullptr);
  return span.count > 0 && span.count == trial.position.size() && !Dense(span, step_s);
}

// The free run's errors, summed: ref 002 eq. 37's velocity MAE (and the zero-velocity model's
// on the same samples) and the position RMS, the position errors kept (float) for the residual
// analysis.
struct FreeRunErrors {
  double sum_abs = 0.0, sum_abs_zero = 0.0, sum_sq = 0.0;
  int velocity_samples = 0;
  std::vector<float>* position_errors;

  void AddVelocity(double model, double measured) {
    sum_abs += std::abs(model - measured);
    sum_abs_zero += std::abs(measured);
    ++velocity_samples;
  }
  void AddPosition(double measured, double model) {
    const double e = measured - model;
    sum_sq += e * e;
    position_errors->push_back(static_cast<float>(e));
  }
  void Fill(TrialFit* f) const {
    f->velocity_samples = velocity_samples;
    f->velocity_mae = velocity_samples > 0 ? sum_abs / velocity_samples : kNaN;
    f->zero_velocity_mae = velocity_samples > 0 ? sum_abs_zero / velocity_samples : kNaN;
    const std::size_t n = position_errors->size();
    f->position_samples = static_cast<int>(n);
    f->position_rms = n > 0 ? std::sqrt(sum_sq / n) : kNaN;
  }
};

// The errors of a free run simulated at the positions' own times, each taken as the simulation
// visits its sample (a million-row trial is not stored twice more): the same sums, in the same
// order, as ScoreStoredFreeRun.
void ScoreVisitedFreeRun(const model::DofModel& model, const Eigen::VectorXd& theta,
                         const TrialData& trial, double step_s, Eigen::VectorXd x0, TrialFit* f,
                         std::vector<float>* perr) {
  const SmoothedSignal& v = trial.velocity_estimate;
  const Signal& p = trial.position;
  FreeRunErrors errors{0.0, 0.0, 0.0, 0, perr};
  perr->reserve(p.size());
  model::SimulationOptions so;
  so.step_s = step_s;
  model::SimulateVisiting(model, theta, trial.conditions(), p.t, so, &x0, model::Seen::kBySensors,
                          [&](std::size_t i, const double* x, const double*) {
                            if (!v.edge[i] && std::isfinite(v.value[i])) {
                              errors.AddVelocity(x[1], v.value[i]);
                            }
                            errors.AddPosition(p.y[i], x[0]);
                          });
  errors.Fill(f);
}

// The same errors from a stored free run (FreeRun) on the union of the velocity reference's and
// the positions' times: velocity residuals kept in `verr` when there are no positions.
void ScoreStoredFreeRun(const model::DofModel& model, const Eigen::VectorXd& theta,
                        const TrialData& trial, double step_s, Eigen::VectorXd x0, TrialFit* f,
                        std::vector<float>* perr, std::vector<double>* verr) {
  // An estimated velocity's times are a subset of the positions' (its samples are theirs).
  const SharedTimes& vtimes = trial.has_velocity() ? trial.velocity.t : trial.position.t;
  FreeRun run(model, theta, trial, vtimes, step_s, std::move(x0));
  if (run.empty()) return;
  const bool keep_velocity = !trial.has_position() || trial.position.t.back() < 0;
  FreeRunErrors errors{0.0, 0.0, 0.0, 0, perr};
  if (keep_velocity)
    verr->reserve(trial.has_velocity() ? trial.velocity.size() : trial.velocity_estimate.size());
  ForEachVelocityReference(trial, [&](double t, double v) {
    if (t < 0) return;
    const double model_v = run.At(t, 1);
    errors.AddVelocity(model_v, v);  // ν_model − ν_measured (eq. 37)
    if (keep_velocity) verr->push_back(v - model_v);
  });
  run.Rewind();
  if (trial.has_position()) {
    perr->reserve(trial.position.size());
    for (std::size_t k = 0; k < trial.position.size(); ++k) {
      if (trial.position.t[k] >= 0)
        errors.AddPosition(trial.position.y[k], run.At(trial.position.t[k], 0));
    }
  }
  errors.Fill(f);
}

// Residual analysis of the position errors when there are positions, else of the velocity's.
template <class Real>
void AnalyzeTrialResiduals(const Signal& s, const std::vector<Real>& r, const char* signal,
                           const ValidationOptions& o, TrialFit* f) {
  const double step = s.size() > 1 ? (s.t.back() - s.t.front()) / (s.size() - 1) : 0.0;
  f->residuals = AnalyzeResiduals(r, o.max_lag, o.bins, step);
  f->residual_signal = signal;
  if (o.curve_points > 0) f->curve = Decimate(s, r, o.curve_points);
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
  f.velocity_reference = trial.has_velocity() ? "measured" : "estimated";
  // Position errors in float (AnalyzeResiduals); velocity errors only without positions.
  std::vector<float> perr;
  std::vector<double> verr;
  if (SimulatedAtPositionTimes(trial, o.step_s)) {
    ScoreVisitedFreeRun(model, theta, trial, o.step_s, x0, &f, &perr);
  } else {
    ScoreStoredFreeRun(model, theta, trial, o.step_s, x0, &f, &perr, &verr);
  }
  if (f.position_samples > 0) {
    AnalyzeTrialResiduals(trial.position, perr, "position", o, &f);
  } else if (f.velocity_samples > 0) {
    Signal estimated;
    AnalyzeTrialResiduals(VelocityReference(trial, &estimated), verr, "velocity", o, &f);
  }
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
