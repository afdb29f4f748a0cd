#include "uuvplan/ident/prepare/velocity_estimation.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <limits>

#include "options_check.h"
#include "uuvplan/ident/stats/covariance.h"
#include "uuvplan/model/util/median.h"
#include "uuvplan/model/util/numbers.h"

namespace uuvplan::ident {
namespace {

using model::kNaN;

}  // namespace

double MedianStep(model::TimesView t, std::size_t begin, std::size_t end) {
  if (end <= begin + 1) return kNaN;
  const std::size_t n = end - begin - 1;
  const std::size_t stride = model::SpreadStride(n);
  std::vector<double> steps;
  steps.reserve(n / stride + 1);
  for (std::size_t i = begin + 1; i < end; i += stride) steps.push_back(t[i] - t[i - 1]);
  return model::Median(std::move(steps));
}

namespace {

// Runs of samples separated by steps longer than gap_factor × the median step: [begin, end).
std::vector<std::pair<std::size_t, std::size_t>> Runs(model::TimesView t, double gap_factor) {
  std::vector<std::pair<std::size_t, std::size_t>> runs;
  if (t.empty()) return runs;
  const double h = t.size() < 2 ? 1.0 : MedianStep(t, 0, t.size());
  std::size_t begin = 0;
  for (std::size_t i = 1; i < t.size(); ++i) {
    if (t[i] - t[i - 1] > gap_factor * h) {
      runs.push_back({begin, i});
      begin = i;
    }
  }
  runs.push_back({begin, t.size()});
  return runs;
}

// Row vectors giving the value and the first derivative (per unit of u) at u = at of the
// least-squares polynomial of `order` through points u: e_kᵀ (VᵀV)⁻¹ Vᵀ.
void PolynomialWeights(const std::vector<double>& u, int order, double at, Eigen::VectorXd* wv,
                       Eigen::VectorXd* wd, Eigen::VectorXd* w2) {
  const int n = static_cast<int>(u.size());
  const int q = order + 1;
  Eigen::MatrixXd V(n, q);
  for (int i = 0; i < n; ++i) {
    double p = 1.0;
    for (int j = 0; j < q; ++j) {
      V(i, j) = p;
      p *= u[i];
    }
  }
  const Eigen::MatrixXd P = (V.transpose() * V).ldlt().solve(V.transpose());  // q × n
  // value(at) = Σ_j a_j at^j, derivative = Σ_j j a_j at^{j-1}.
  Eigen::VectorXd ev = Eigen::VectorXd::Zero(q), ed = Eigen::VectorXd::Zero(q),
                  e2 = Eigen::VectorXd::Zero(q);
  double p = 1.0;
  for (int j = 0; j < q; ++j) {
    ev[j] = p;
    if (j + 1 < q) ed[j + 1] = (j + 1) * p;
    if (j + 2 < q) e2[j + 2] = (j + 2) * (j + 1) * p;
    p *= at;
  }
  *wv = P.transpose() * ev;
  *wd = P.transpose() * ed;
  *w2 = P.transpose() * e2;
}

// The local polynomial's value, slope and curvature at sample `at`: the weights applied to
// the w samples from `y` (u in units of the step h).
SmoothedSample LocalFit(const Eigen::VectorXd& wv, const Eigen::VectorXd& wd,
                        const Eigen::VectorXd& w2, const double* y, int w, double h, std::size_t at,
                        bool edge, int run) {
  double v = 0.0, d = 0.0, a = 0.0;
  for (int j = 0; j < w; ++j) {
    v += wv[j] * y[j];
    d += wd[j] * y[j];
    a += w2[j] * y[j];
  }
  return {at, v, d / h, a / (h * h), edge, run};
}

// The local fit of one run [b, e) of samples: window, order and step as SmoothRun uses them.
struct RunFit {
  std::size_t b = 0;
  int n = 0, w = 0, q = 0, hw = 0;
  double h = 0.0;
  bool uniform = true;  ///< every step within 1% of the median step: one set of weights
};

RunFit FitOfRun(const Signal& s, std::size_t b, std::size_t e, int order, int window) {
  RunFit f;
  f.b = b;
  f.n = static_cast<int>(e - b);
  f.w = std::min(window, f.n % 2 == 1 ? f.n : f.n - 1);
  f.q = std::min(order, f.w - 2);
  f.hw = f.w / 2;
  f.h = MedianStep(s.t, b, e);
  for (std::size_t i = b + 1; i < e; ++i) {
    if (std::abs(s.t[i] - s.t[i - 1] - f.h) > 0.01 * f.h) {
      f.uniform = false;
      break;
    }
  }
  return f;
}

// The weights of sample b + i's local fit (value, slope, curvature per unit u) and the first
// sample of its window: the centred window inside a uniform run, the first/last window's
// polynomial at its edge points, the window on the actual times for irregular steps.
int LocalWeights(const Signal& s, const RunFit& f, int i, Eigen::VectorXd* wv, Eigen::VectorXd* wd,
                 Eigen::VectorXd* w2) {
  std::vector<double> u(f.w);
  const int first = std::clamp(i - f.hw, 0, f.n - f.w);
  if (f.uniform) {
    for (int j = 0; j < f.w; ++j) u[j] = j - f.hw;
    PolynomialWeights(u, f.q, static_cast<double>(i - first - f.hw), wv, wd, w2);
    return first;
  }
  for (int j = 0; j < f.w; ++j) u[j] = (s.t[f.b + first + j] - s.t[f.b + i]) / f.h;
  PolynomialWeights(u, f.q, 0.0, wv, wd, w2);
  return first;
}

// The centred filter's noise gains, from the first interior sample's weights.
void SetGains(const Eigen::VectorXd& wv, const Eigen::VectorXd& wd, double h, SmoothedSignal* out) {
  out->value_gain = wv.norm();
  out->derivative_gain = wd.norm() / h;
  out->derivative_weights.assign(wd.data(), wd.data() + wd.size());
  for (double& x : out->derivative_weights) x /= h;
}

// Smooths one run [b, e) of samples, handing each sample in order to sink(SmoothedSample);
// the first interior sample's gains go to `gains` (when not null and not yet set).
template <class Sink>
void SmoothRun(const Signal& s, std::size_t b, std::size_t e, int run, int order, int window,
               const Sink& sink, SmoothedSignal* gains, bool* gains_set) {
  const int n = static_cast<int>(e - b);
  if (n < 3) {
    for (std::size_t i = b; i < e; ++i) sink(SmoothedSample{i, s.y[i], kNaN, kNaN, true, run});
    return;
  }
  const RunFit f = FitOfRun(s, b, e, order, window);
  Eigen::VectorXd wv, wd, w2;
  for (int i = 0; i < n; ++i) {
    const bool edge = i < f.hw || i >= n - f.hw;
    // A uniform run's interior shares the centred weights (computed once).
    if (!(f.uniform && !edge && i > f.hw)) LocalWeights(s, f, i, &wv, &wd, &w2);
    const int first = std::clamp(i - f.hw, 0, n - f.w);
    sink(LocalFit(wv, wd, w2, &s.y[b + first], f.w, f.h, b + i, edge, run));
    if (gains && !*gains_set && !edge) {
      SetGains(wv, wd, f.h, gains);
      *gains_set = true;
    }
  }
}

// Every run of s smoothed in order (SmoothRun).
template <class Sink>
void SmoothRuns(const Signal& s, const SavitzkyGolayOptions& options, const Sink& sink,
                SmoothedSignal* gains) {
  bool gains_set = false;
  int run = 0;
  for (const auto& [b, e] : Runs(s.t, options.gap_factor)) {
    SmoothRun(s, b, e, run++, options.order, options.window, sink, gains, &gains_set);
  }
}

}  // namespace

bool SavitzkyGolayOptions::IsValid(std::string* error) const {
  return Require(order >= 1 && order <= 8,
                 "SavitzkyGolayOptions::order = " + std::to_string(order) +
                     ". Violated constraint: 1 <= order <= 8",
                 error) &&
         Require(window >= order + 2 && window % 2 != 0,
                 "SavitzkyGolayOptions::window = " + std::to_string(window) +
                     ". Violated constraint: odd and >= order + 2",
                 error) &&
         Require(gap_factor > 1, "SavitzkyGolayOptions::gap_factor must be > 1", error);
}

int SavitzkyGolayWindow(double rate_hz, double input_time_scale_s) {
  int n = static_cast<int>(std::lround(4.0 * rate_hz));
  n = std::clamp(n, 21, 41);
  if (input_time_scale_s > 0) {
    const int fast = static_cast<int>(std::floor(0.25 * input_time_scale_s * rate_hz)) + 1;
    n = std::min(n, std::max(9, fast));
  }
  if (n % 2 == 0) ++n;
  return std::min(n, 41);
}

int ChosenWindow(int given, double rate_hz, double input_time_scale_s) {
  return given > 0 ? given : SavitzkyGolayWindow(rate_hz, input_time_scale_s);
}

double InputTimeScale(model::TimesView t, const std::vector<double>& f) {
  if (f.size() < 3) return 0.0;
  double lo = f[0], hi = f[0], mean = 0.0;
  for (double v : f) {
    lo = std::min(lo, v);
    hi = std::max(hi, v);
    mean += v;
  }
  mean /= f.size();
  const double tol = 1e-9 * std::max(std::abs(lo), std::abs(hi)) + 1e-12;
  if (hi - lo <= tol) return 0.0;
  std::vector<double> changes;
  for (std::size_t i = 1; i < f.size(); ++i) {
    if (std::abs(f[i] - f[i - 1]) > tol) changes.push_back(t[i]);
  }
  if (changes.size() < 0.2 * (f.size() - 1)) {
    // Piecewise constant: durations between changes (including the first and last piece).
    std::vector<double> legs;
    double prev = t.front();
    for (double c : changes) {
      legs.push_back(c - prev);
      prev = c;
    }
    legs.push_back(t.back() - prev);
    return model::Median(legs);
  }
  std::vector<double> crossings;
  for (std::size_t i = 1; i < f.size(); ++i) {
    if ((f[i] - mean) * (f[i - 1] - mean) < 0) crossings.push_back(t[i]);
  }
  if (crossings.size() < 3) return t.back() - t.front();
  // Full periods (every other crossing), robust to a mean that is off the sine's offset.
  std::vector<double> periods;
  for (std::size_t i = 2; i < crossings.size(); ++i)
    periods.push_back(crossings[i] - crossings[i - 2]);
  return model::Median(periods);
}

namespace {

// A smoothed signal at times t with nothing estimated yet (NaN, every sample an edge), its runs
// split at gaps longer than gap_factor × the median step, its second derivative sized only
// `with_second_derivative`.
SmoothedSignal Unsmoothed(const SharedTimes& t, double gap_factor, bool with_second_derivative) {
  SmoothedSignal out;
  const std::size_t n = t.size();
  out.t = t;
  out.value.assign(n, kNaN);
  out.derivative.assign(n, kNaN);
  if (with_second_derivative) out.second_derivative.assign(n, kNaN);
  out.edge.assign(n, true);
  for (const auto& run : Runs(t, gap_factor)) out.run_starts.push_back(run.first);
  return out;
}

}  // namespace

int SmoothedSignal::run(std::size_t i) const {
  const auto after = std::upper_bound(run_starts.begin(), run_starts.end(), i);
  return after == run_starts.begin() ? 0 : static_cast<int>(after - run_starts.begin()) - 1;
}

SmoothedSignal SavitzkyGolay(const Signal& s, const SavitzkyGolayOptions& options) {
  SmoothedSignal out = Unsmoothed(s.t, options.gap_factor, true);
  SmoothRuns(
      s, options,
      [&out](const SmoothedSample& p) {
        out.value[p.i] = p.value;
        out.derivative[p.i] = p.derivative;
        out.second_derivative[p.i] = p.second_derivative;
        out.edge[p.i] = p.edge;
      },
      &out);
  return out;
}

SmoothedSignal SavitzkyGolayRate(const Signal& s, const SavitzkyGolayOptions& options,
                                 double* first_value) {
  SmoothedSignal out = Unsmoothed(s.t, options.gap_factor, false);
  *first_value = kNaN;
  SmoothRuns(
      s, options,
      [&](const SmoothedSample& p) {
        if (p.i == 0) *first_value = p.value;
        out.value[p.i] = p.derivative;
        out.derivative[p.i] = p.second_derivative;
        out.edge[p.i] = p.edge;
      },
      &out);
  return out;
}

void ForEachSmoothed(const Signal& s, const SavitzkyGolayOptions& options,
                     const std::function<void(const SmoothedSample&)>& visit) {
  SmoothRuns(s, options, visit, nullptr);
}

std::vector<SampleWeights> SavitzkyGolayDerivativeWeights(const Signal& s,
                                                          const SavitzkyGolayOptions& options,
                                                          std::size_t begin, std::size_t end) {
  std::vector<SampleWeights> out;
  Eigen::VectorXd wv, wd, w2;
  for (const auto& [b, e] : Runs(s.t, options.gap_factor)) {
    if (e <= begin || b >= end) continue;
    const RunFit f = FitOfRun(s, b, e, options.order, options.window);
    for (std::size_t i = std::max(b, begin); i < std::min(e, end); ++i) {
      SampleWeights sw;
      sw.first = i;
      if (f.n >= 3) {
        sw.first = b + LocalWeights(s, f, static_cast<int>(i - b), &wv, &wd, &w2);
        sw.w.resize(wd.size());
        for (Eigen::Index j = 0; j < wd.size(); ++j) sw.w[j] = wd[j] / f.h;
      }
      out.push_back(std::move(sw));
    }
  }
  return out;
}

double PositionNoiseAr1(const Signal& position, const SavitzkyGolayOptions& options, double sigma) {
  const int w = options.window, q = std::min(options.order, options.window - 3) + 1;
  std::vector<std::pair<std::size_t, std::size_t>> blocks;
  for (const auto& [b, e] : Runs(position.t, options.gap_factor)) {
    for (std::size_t a = b; a + w <= e; a += w) blocks.push_back({a, a + w});
  }
  // At most ~200 blocks evenly spread: ρ to ~0.01 on ρ = 0.9 noise, bounded work on long logs.
  const std::size_t stride = std::max<std::size_t>(1, blocks.size() / 200);
  std::vector<FittedResiduals> sets;
  for (std::size_t k = 0; k < blocks.size(); k += stride) {
    const auto [a, e] = blocks[k];
    const double mid = 0.5 * (position.t[a] + position.t[e - 1]);
    const double span = std::max(position.t[e - 1] - position.t[a], 1e-12);
    FittedResiduals f;
    Eigen::MatrixXd X(w, q);
    Eigen::VectorXd y(w);
    for (int i = 0; i < w; ++i) {
      const double u = (position.t[a + i] - mid) / span;
      double p = 1.0;
      for (int j = 0; j < q; ++j, p *= u) X(i, j) = p;
      y[i] = position.y[a + i];
    }
    const Eigen::VectorXd r = y - X * X.colPivHouseholderQr().solve(y);
    f.basis = std::make_shared<const ColumnBasis>(ColumnBasis{OrthonormalBasis(X)});
    f.sum_sq = r.squaredNorm();
    f.sum_lag1 = r.head(w - 1).dot(r.tail(w - 1));
    sets.push_back(std::move(f));
  }
  return sigma > 0 ? Ar1FromResidualVariance(sets, sigma) : Ar1FromFittedResiduals(sets);
}

std::vector<double> ButterworthFiltFilt(const std::vector<double>& y, double rate_hz,
                                        double cutoff_hz) {
  const std::size_t n = y.size();
  if (n < 2 || !(cutoff_hz > 0) || !(cutoff_hz < 0.5 * rate_hz)) return y;
  // Bilinear transform with prewarping of H(s) = ωc² / (s² + √2 ωc s + ωc²).
  const double k = std::tan(M_PI * cutoff_hz / rate_hz);
  const double norm = 1.0 / (1.0 + std::sqrt(2.0) * k + k * k);
  const double b0 = k * k * norm, b1 = 2 * b0, b2 = b0;
  const double a1 = 2.0 * (k * k - 1.0) * norm;
  const double a2 = (1.0 - std::sqrt(2.0) * k + k * k) * norm;
  // Odd reflection padding of about three time constants of the filter.
  const std::size_t pad =
      std::min(n - 1, static_cast<std::size_t>(std::ceil(3.0 * rate_hz / cutoff_hz)) + 3);
  std::vector<double> x;
  x.reserve(n + 2 * pad);
  for (std::size_t i = pad; i >= 1; --i) x.push_back(2 * y[0] - y[i]);
  x.insert(x.end(), y.begin(), y.end());
  for (std::size_t i = 1; i <= pad; ++i) x.push_back(2 * y[n - 1] - y[n - 1 - i]);
  auto pass = [&](std::vector<double>& v) {
    // Direct form I, started in the steady state of the first value (DC gain 1).
    double x1 = v[0], x2 = v[0], y1 = v[0], y2 = v[0];
    for (double& xi : v) {
      const double yi = b0 * xi + b1 * x1 + b2 * x2 - a1 * y1 - a2 * y2;
      x2 = x1;
      x1 = xi;
      y2 = y1;
      y1 = yi;
      xi = yi;
    }
  };
  pass(x);
  std::reverse(x.begin(), x.end());
  pass(x);
  std::reverse(x.begin(), x.end());
  return std::vector<double>(x.begin() + pad, x.begin() + pad + n);
}

SmoothedSignal ButterworthVelocity(const Signal& p, double cutoff_hz, double gap_factor) {
  SmoothedSignal out = Unsmoothed(p.t, gap_factor, true);
  for (const auto& [b, e] : Runs(p.t, gap_factor)) {
    const std::size_t m = e - b;
    if (m < 3) continue;
    std::vector<double> d(m), y(p.y.begin() + b, p.y.begin() + e);
    // Central differences (exact for parabolas on any grid: the derivative of the parabola
    // through three points at the middle one), second-order one-sided at the ends.
    const std::size_t first = b;  // a structured binding cannot be captured before C++20
    auto t = [&](std::size_t i) { return p.t[first + i]; };
    auto parabola_slope = [&](std::size_t i0, std::size_t at) {
      const double t0 = t(i0), t1 = t(i0 + 1), t2 = t(i0 + 2), x = t(at);
      const double y0 = y[i0], y1 = y[i0 + 1], y2 = y[i0 + 2];
      return y0 * (2 * x - t1 - t2) / ((t0 - t1) * (t0 - t2)) +
             y1 * (2 * x - t0 - t2) / ((t1 - t0) * (t1 - t2)) +
             y2 * (2 * x - t0 - t1) / ((t2 - t0) * (t2 - t1));
    };
    for (std::size_t i = 0; i < m; ++i) {
      d[i] = parabola_slope(i == 0 ? 0 : (i + 1 == m ? m - 3 : i - 1), i);
    }
    const double rate = (m - 1) / (p.t[e - 1] - p.t[b]);
    const std::vector<double> fv = ButterworthFiltFilt(y, rate, cutoff_hz);
    const std::vector<double> fd = ButterworthFiltFilt(d, rate, cutoff_hz);
    // The filter's transient spans a few periods of the cutoff at each end.
    const std::size_t edge = static_cast<std::size_t>(std::ceil(3.0 * rate / cutoff_hz));
    for (std::size_t i = 0; i < m; ++i) {
      out.value[b + i] = fv[i];
      out.derivative[b + i] = fd[i];
      out.edge[b + i] = i < edge || i + edge >= m;
    }
  }
  return out;
}

template <class Real>
double Interpolate(model::TimesView t, const std::vector<Real>& y, double at) {
  if (t.empty()) return kNaN;
  if (at <= t.front()) return y.front();
  if (at >= t.back()) return y.back();
  const auto it = std::upper_bound(t.begin(), t.end(), at);
  const std::size_t i = static_cast<std::size_t>(it - t.begin());
  const double w = (at - t[i - 1]) / (t[i] - t[i - 1]);
  const double y0 = y[i - 1], y1 = y[i];
  return y0 + w * (y1 - y0);
}
template double Interpolate(model::TimesView, const std::vector<double>&, double);
template double Interpolate(model::TimesView, const std::vector<float>&, double);

double NoiseSigmaFromDifferences(const Signal& s) {
  if (s.size() < 8) return kNaN;
  std::vector<double> d;
  // At most ~100,000 evenly spread differences: the MAD to well within 1%.
  const std::size_t stride = std::max<std::size_t>(1, s.size() / 100000);
  d.reserve(s.size() / stride + 1);
  for (std::size_t i = 3; i < s.size(); i += stride) {
    d.push_back(std::abs(s.y[i] - 3 * s.y[i - 1] + 3 * s.y[i - 2] - s.y[i - 3]));
  }
  return 1.4826 * model::Median(d) / std::sqrt(20.0);
}

}  // namespace uuvplan::ident
