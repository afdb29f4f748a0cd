// One trial of the output error (output_error_trial.h): its measurements, binned where the
// sensor is faster than the RK4 step, its initial state and its output grid.
#include "estimators/output_error_trial.h"

#include <algorithm>
#include <cmath>
#include <functional>

#include "estimators/averaged_input.h"
#include "uuvplan/model/util/checked_count.h"

namespace uuvplan::ident::internal {
namespace {

// Samples faster than the RK4 step are averaged into bins about one step long (never across a
// gap): the bin mean at the mean time, with weight √n/σ. For motion that is linear across a
// bin this loses nothing (the mean is a sufficient statistic); it keeps the simulation's
// output times, and so its cost, independent of the sensor rate.
struct Binned {
  std::vector<double> t, y, w;
};
Binned Bin(const Signal& s, double sigma, double step, model::TimesView breaks) {
  Binned b;
  const double w1 = 1.0 / (sigma > 0 ? sigma : 1.0);
  const std::size_t n = s.size();
  double h = n > 1 ? (s.t.back() - s.t.front()) / (n - 1) : step;
  if (h >= 0.5 * step) {
    // One measurement a sample: sized once (grown by doubling, a 10⁶-sample trial would hold
    // up to 25% more for the whole fit).
    b.t.reserve(n);
    b.y.reserve(n);
    b.w.reserve(n);
    for (std::size_t k = 0; k < n; ++k) {
      if (s.t[k] < 0) continue;
      b.t.push_back(s.t[k]);
      b.y.push_back(s.y[k]);
      b.w.push_back(w1);
    }
    return b;
  }
  std::size_t k = 0;
  while (k < n) {
    if (s.t[k] < 0) {
      ++k;
      continue;
    }
    const double start = s.t[k];
    // A bin ends at the next input breakpoint: the motion has a kink there.
    const auto next = std::upper_bound(breaks.begin(), breaks.end(), start);
    const double stop = std::min(start + step, next == breaks.end() ? start + step : *next);
    double st = 0.0, sy = 0.0;
    int c = 0;
    while (k < n && (c == 0 || (s.t[k] < stop && s.t[k] - s.t[k - 1] < 3.0 * h))) {
      st += s.t[k];
      sy += s.y[k];
      ++c;
      ++k;
    }
    b.t.push_back(st / c);
    b.y.push_back(sy / c);
    b.w.push_back(w1 * std::sqrt(static_cast<double>(c)));
  }
  return b;
}

// A sensor's binned samples as a trial's measurements at `times` (sorted, unique, holding
// every sample time >= 0 of the sensor; TrialProblem::Measurements: the identity index and
// equal weights not stored).
TrialProblem::Measurements Measured(Binned b, const std::vector<double>& times) {
  TrialProblem::Measurements m;
  const bool identity =
      b.t.size() <= times.size() && std::equal(b.t.begin(), b.t.end(), times.begin());
  if (!identity) {
    m.at_index.reserve(b.t.size());
    for (double t : b.t) {
      m.at_index.push_back(
          static_cast<int>(std::lower_bound(times.begin(), times.end(), t) - times.begin()));
    }
  }
  const bool equal =
      std::all_of(b.w.begin(), b.w.end(), [&](double w) { return w == b.w.front(); });
  if (equal && !b.w.empty()) {
    m.w_all = b.w.front();
  } else {
    m.w = std::move(b.w);
  }
  m.y_owned = std::move(b.y);
  return m;
}

// A sensor fitted sample by sample, as logged (one measurement a sample: not binned, every
// time >= 0 and strictly increasing): its times and values are read in place.
bool UsedAsLogged(const Signal& s, double step) {
  const std::size_t n = s.size();
  if (n < 2 || s.t.front() < 0) return false;
  const double h = (s.t.back() - s.t.front()) / (n - 1);
  return h >= 0.5 * step &&
         std::adjacent_find(s.t.begin(), s.t.end(), std::greater_equal<double>()) == s.t.end();
}

// The measurements of the sensors used (`use_pos`, `use_vel`) and the times they are at: a lone
// sensor fitted as logged is read in place; otherwise each is binned (Bin) and both are put on
// the sorted union of their times from t = 0.
void SetMeasurements(const TrialData& d, bool use_pos, bool use_vel, const OutputErrorOptions& o,
                     TrialProblem* tp) {
  const Signal* only = use_pos != use_vel ? (use_pos ? &d.position : &d.velocity) : nullptr;
  if (only && UsedAsLogged(*only, o.bin_s)) {
    TrialProblem::Measurements& m = use_pos ? tp->pos : tp->vel;
    const double sigma = use_pos ? d.position_sigma : d.velocity_sigma;
    m.w_all = 1.0 / (sigma > 0 ? sigma : 1.0);  // as Bin's
    m.y_ref = &only->y;
    tp->times_ref = &only->t;
    return;
  }
  const model::TimesView breaks = tp->breakpoints();
  Binned pos = use_pos ? Bin(d.position, d.position_sigma, o.bin_s, breaks) : Binned{};
  Binned vel = use_vel ? Bin(d.velocity, d.velocity_sigma, o.bin_s, breaks) : Binned{};
  std::vector<double> times;
  times.reserve(pos.t.size() + vel.t.size());
  times.insert(times.end(), pos.t.begin(), pos.t.end());
  times.insert(times.end(), vel.t.begin(), vel.t.end());
  std::sort(times.begin(), times.end());
  times.erase(std::unique(times.begin(), times.end()), times.end());
  // Simulation starts at t = 0; samples before it (none after PrepareTrial) are dropped.
  times.erase(times.begin(), std::lower_bound(times.begin(), times.end(), 0.0));
  tp->pos = Measured(std::move(pos), times);
  tp->vel = Measured(std::move(vel), times);
  tp->times_owned = std::move(times);
}

// The trial's initial state: `initial`'s entry for it when given, else the first position (the
// smoothed position at t = 0 is not kept; the first sample is a fine start for a parameter that
// enters linearly) and the estimated velocity at t = 0 or rest, each estimated as the options
// say.
TrialInitialState InitialStateOf(const TrialData& d, const std::vector<TrialInitialState>* initial,
                                 bool use_pos, const OutputErrorOptions& o) {
  const TrialInitialState* given = nullptr;
  if (initial) {
    for (const auto& s : *initial) {
      if (s.trial == d.index) given = &s;
    }
  }
  if (given) return *given;
  TrialInitialState init;
  init.trial = d.index;
  init.chi0 = use_pos ? d.position.y.front() : 0.0;
  init.chi0_estimated = use_pos;
  const bool estimate_xi0 = o.initial_velocity == InitialVelocity::kEstimate ||
                            (o.initial_velocity == InitialVelocity::kAuto && !d.starts_at_rest);
  init.xi0_estimated = estimate_xi0;
  const double v0 = d.velocity_estimate.value.empty() ? 0.0 : EstimatedVelocity(d, 0.0);
  init.xi0 = estimate_xi0 && std::isfinite(v0) ? v0 : 0.0;
  return init;
}

// The simulation's output grid for measurements at `times`: every input breakpoint and points at
// most o.grid_s apart in between. Empty (simulate at `times`) when it would not be smaller, or
// without a grid (o.grid_s = 0, a sensor delay, no measurement).
std::vector<double> OutputGrid(const model::DofModel& model, const TrialProblem& tp,
                               model::TimesView times, const OutputErrorOptions& o) {
  if (!(o.grid_s > 0 && model.sensor_delay_index() < 0 && !times.empty())) return {};
  // The grid holds 0, every breakpoint before the last sample and that sample: with about as
  // many breakpoints as samples (a force logged at every row) it cannot be smaller.
  const model::TimesView breaks = tp.breakpoints();
  const auto inside = std::lower_bound(breaks.begin(), breaks.end(), times.back()) - breaks.begin();
  if (static_cast<std::size_t>(inside) + 2 >= times.size()) return {};
  std::vector<double> grid = {0.0};
  auto extend_to = [&](double t) {
    const double last = grid.back();
    const int pieces = model::CheckedCount<int>((t - last) / o.grid_s, "output error grid",
                                                model::limits::kMaxTrialRows, "a coarser grid_s");
    for (int k = 1; k < pieces; ++k) grid.push_back(last + (t - last) * k / pieces);
    if (t > last) grid.push_back(t);
  };
  for (double b : breaks) {
    if (b > 0 && b < times.back()) extend_to(b);
  }
  extend_to(times.back());
  if (grid.size() >= times.size()) return {};
  grid.shrink_to_fit();
  return grid;
}

}  // namespace

std::optional<TrialProblem> MakeTrialProblem(const model::DofModel& model, const TrialData& d,
                                             const std::vector<TrialInitialState>* initial,
                                             const OutputErrorOptions& o, double average_input_s) {
  const bool use_pos = o.use_position && d.has_position();
  const bool use_vel = o.use_velocity && d.has_velocity();
  if (!use_pos && !use_vel) return std::nullopt;
  TrialProblem tp;
  tp.trial = &d;
  if (average_input_s > 0) tp.averaged_input = AveragedInput(d, average_input_s);
  SetMeasurements(d, use_pos, use_vel, o, &tp);
  tp.init = InitialStateOf(d, initial, use_pos, o);
  tp.grid = OutputGrid(model, tp, tp.times(), o);
  return tp;
}

}  // namespace uuvplan::ident::internal
