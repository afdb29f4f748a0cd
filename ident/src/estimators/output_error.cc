#include "uuvplan/ident/estimators/output_error.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
#include <optional>
#include <sstream>

#include "options_check.h"
#include "stats/model_selection.h"
#include "uuvplan/ident/estimators/block_least_squares.h"
#include "uuvplan/ident/estimators/least_squares.h"
#include "uuvplan/ident/stats/covariance.h"
#include "uuvplan/ident/stats/median_abs.h"
#include "uuvplan/ident/stats/significance.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/simulator.h"
#include "uuvplan/model/util/checked_count.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {
namespace {

// One trial's measurements on a common time grid.
struct TrialProblem {
  const TrialData* trial = nullptr;
  // The sorted union of the used sample times: owned, or the trial's own sample times when one
  // sensor is used sample by sample (not copied: 8 bytes a sample).
  std::vector<double> times_owned;
  const SharedTimes* times_ref = nullptr;
  model::TimesView times() const { return times_ref ? times_ref->view() : times_owned; }
  // One sensor's measurements: measurement k is at times[at(k)], value y(k), weight w(k)
  // (1/σ, √n/σ for a bin). The index is not stored when it is k itself (one sensor), nor the
  // weights when they are all equal (unbinned), nor the values when they are the trial's own
  // samples: 20 bytes a measurement.
  struct Measurements {
    std::vector<int> at_index;  // empty: measurement k is at times[k]
    std::vector<double> y_owned;
    const std::vector<double>* y_ref = nullptr;  // the trial's samples, when not binned
    std::vector<double> w;      // empty: every weight is w_all
    double w_all = 1.0;
    std::size_t size() const { return y_ref ? y_ref->size() : y_owned.size(); }
    double y(std::size_t k) const { return y_ref ? (*y_ref)[k] : y_owned[k]; }
    int at(std::size_t k) const { return at_index.empty() ? static_cast<int>(k) : at_index[k]; }
    double weight(std::size_t k) const { return w.empty() ? w_all : w[k]; }
  };
  Measurements pos, vel;
  TrialInitialState init;
  int z_chi0 = -1, z_xi0 = -1;       // indices in z
  int r_offset = 0;                  // first residual of this trial
  // Dense samples: the simulation's output grid (empty: simulate at `times`). Sample time t
  // lies in interval g, grid[g] <= t <= grid[g + 1], the first such g (IntervalCursor).
  std::vector<double> grid;
  struct Hermite {
    double h00, h10, h01, h11, u;  // cubic Hermite basis at the time (h10, h11 times h)
  };
  // The basis of time t in grid interval g, computed when read (stored, it was 40 bytes a
  // sample: 40 MB of a 10⁶-sample trial).
  double U(double t, int g) const {
    const double h = grid[g + 1] - grid[g];
    return h > 0 ? std::clamp((t - grid[g]) / h, 0.0, 1.0) : 0.0;
  }
  Hermite Weights(double t, int g) const {
    const double h = grid[g + 1] - grid[g];
    const double u = U(t, g);
    return {(1 + 2 * u) * (1 - u) * (1 - u), h * u * (1 - u) * (1 - u), u * u * (3 - 2 * u),
            h * u * u * (u - 1), u};
  }
  int num_residuals() const { return static_cast<int>(pos.size() + vel.size()); }
  // The state a one-sensor trial measures: 0 position, 1 velocity.
  int sensor() const { return pos.size() > 0 ? 0 : 1; }
  // One sensor, on the grid or at its own times without a sensor delay to differentiate: its
  // rows can be made while the simulation runs (Problem::Stream).
  bool streamable(const model::DofModel& model) const {
    return (pos.size() == 0 || vel.size() == 0) &&
           (!grid.empty() || model.sensor_delay_index() < 0);
  }
};

// The grid interval of increasing sample times, found by a forward cursor (the first g with
// t <= grid[g + 1], the last interval for times beyond it).
class IntervalCursor {
 public:
  explicit IntervalCursor(const std::vector<double>& grid) : grid_(grid) {}
  int operator()(double t) {
    while (g_ + 2 < grid_.size() && grid_[g_ + 1] < t) ++g_;
    return static_cast<int>(g_);
  }

 private:
  const std::vector<double>& grid_;
  std::size_t g_ = 0;
};

// Samples faster than the RK4 step are averaged into bins about one step long (never across a
// gap): the bin mean at the mean time, with weight √n/σ. For motion that is linear across a
// bin this loses nothing (the mean is a sufficient statistic); it keeps the simulation's
// output times, and so its cost, independent of the sensor rate.
struct Binned {
  std::vector<double> t, y, w;
};
Binned Bin(const Signal& s, double sigma, double step, const std::vector<double>& breaks) {
  Binned b;
  const double w1 = 1.0 / (sigma > 0 ? sigma : 1.0);
  const std::size_t n = s.size();
  double h = n > 1 ? (s.t.back() - s.t.front()) / (n - 1) : step;
  if (h >= 0.5 * step) {
    // One measurement a sample: sized once (grown by doubling, a 10⁶-sample trial held 25%
    // more for the whole fit).
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
  const bool identity = b.t.size() <= times.size() && std::equal(b.t.begin(), b.t.end(), times.begin());
  if (!identity) {
    m.at_index.reserve(b.t.size());
    for (double t : b.t) {
      m.at_index.push_back(static_cast<int>(std::lower_bound(times.begin(), times.end(), t) - times.begin()));
    }
  }
  const bool equal = std::all_of(b.w.begin(), b.w.end(), [&](double w) { return w == b.w.front(); });
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

// Every parameter within the range its family allows a fit (model/parameter.h).
bool Admissible(const model::DofModel& model, const Eigen::VectorXd& theta) {
  const auto& names = model.parameter_names();
  for (int j = 0; j < model.num_parameters(); ++j) {
    const model::ParameterFamily* family = model::FamilyOf(names[j]);
    if (family ? !family->Fittable(theta[j]) : !std::isfinite(theta[j])) return false;
  }
  return true;
}

// dx/dt (position, velocity) at both ends of the grid interval [ta, tb], states xa and xb,
// with the input held at its start (one-sided derivatives at breakpoints): the slopes of the
// cubic Hermite interpolation of the output error's grid.
void HermiteSlopes(const model::DofModel& model, double ta, double tb, const double* xa,
                   const double* xb, const Eigen::VectorXd& theta, const model::TrialConditions& c,
                   double* dl, double* dr) {
  const model::InputSample in = model.SampleInput(ta, c, theta.data());
  double dx[3];
  model.Derivative(ta, xa, in, c, theta.data(), dx);
  dl[0] = dx[0];
  dl[1] = dx[1];
  model.Derivative(tb, xb, in, c, theta.data(), dx);
  dr[0] = dx[0];
  dr[1] = dx[1];
}

class Problem {
 public:
  Problem(const model::DofModel& model, const std::vector<const TrialData*>& trials,
          const Eigen::VectorXd& theta, const std::vector<int>& free,
          const std::vector<TrialInitialState>* initial, const OutputErrorOptions& o)
      : model_(model), theta_(theta), free_(free), o_(o) {
    int z = static_cast<int>(free.size());
    int r = 0;
    for (const TrialData* d : trials) {
      TrialProblem tp;
      tp.trial = d;
      const bool use_pos = o.use_position && d->has_position();
      const bool use_vel = o.use_velocity && d->has_velocity();
      if (!use_pos && !use_vel) continue;
      const Signal* only = use_pos != use_vel ? (use_pos ? &d->position : &d->velocity) : nullptr;
      if (only && UsedAsLogged(*only, o.bin_s)) {
        TrialProblem::Measurements& m = use_pos ? tp.pos : tp.vel;
        const double sigma = use_pos ? d->position_sigma : d->velocity_sigma;
        m.w_all = 1.0 / (sigma > 0 ? sigma : 1.0);  // as Bin's
        m.y_ref = &only->y;
        tp.times_ref = &only->t;
      } else {
        Binned pos =
            use_pos ? Bin(d->position, d->position_sigma, o.bin_s, d->breakpoints) : Binned{};
        Binned vel =
            use_vel ? Bin(d->velocity, d->velocity_sigma, o.bin_s, d->breakpoints) : Binned{};
        std::vector<double> times;
        times.reserve(pos.t.size() + vel.t.size());
        times.insert(times.end(), pos.t.begin(), pos.t.end());
        times.insert(times.end(), vel.t.begin(), vel.t.end());
        std::sort(times.begin(), times.end());
        times.erase(std::unique(times.begin(), times.end()), times.end());
        // Simulation starts at t = 0; samples before it (none after PrepareTrial) are dropped.
        times.erase(times.begin(), std::lower_bound(times.begin(), times.end(), 0.0));
        tp.pos = Measured(std::move(pos), times);
        tp.vel = Measured(std::move(vel), times);
        tp.times_owned = std::move(times);
      }
      // Initial state: given, or guessed from the smoothed data.
      const TrialInitialState* given = nullptr;
      if (initial) {
        for (const auto& s : *initial) {
          if (s.trial == d->index) given = &s;
        }
      }
      tp.init.trial = d->index;
      if (given) {
        tp.init = *given;
      } else {
        tp.init.chi0 = use_pos ? d->position.y.front() : 0.0;
        tp.init.chi0_estimated = use_pos;
        bool estimate_xi0 = o.initial_velocity == InitialVelocity::kEstimate ||
                            (o.initial_velocity == InitialVelocity::kAuto && !d->starts_at_rest);
        tp.init.xi0_estimated = estimate_xi0;
        const double v0 = d->velocity_estimate.value.empty() ? 0.0 : EstimatedVelocity(*d, 0.0);
        tp.init.xi0 = estimate_xi0 && std::isfinite(v0) ? v0 : 0.0;
        if (use_pos && d->velocity_estimate.size() > 0 && std::isfinite(d->velocity_estimate.value.front())) {
          // Smoothed position at t = 0 from the SG end polynomial is not kept; the first
          // sample is a fine start for a parameter that enters linearly.
        }
      }
      const model::TimesView times = tp.times();
      if (o.grid_s > 0 && model.sensor_delay_index() < 0 && !times.empty()) {
        // Grid: every breakpoint, and points at most grid_s apart in between.
        std::vector<double> grid = {0.0};
        auto extend_to = [&](double t) {
          const double last = grid.back();
          const int pieces = model::CheckedCount<int>((t - last) / o.grid_s, "output error grid",
                                                      model::limits::kMaxTrialRows, "a coarser grid_s");
          for (int k = 1; k < pieces; ++k) grid.push_back(last + (t - last) * k / pieces);
          if (t > last) grid.push_back(t);
        };
        for (double b : d->breakpoints) {
          if (b > 0 && b < times.back()) extend_to(b);
        }
        extend_to(times.back());
        if (grid.size() < times.size()) {
          grid.shrink_to_fit();
          tp.grid = std::move(grid);
        }
      }
      if (tp.init.chi0_estimated) tp.z_chi0 = z++;
      if (tp.init.xi0_estimated) tp.z_xi0 = z++;
      tp.r_offset = r;
      r += tp.num_residuals();
      trials_.push_back(std::move(tp));
    }
    num_z_ = z;
    num_r_ = r;
  }

  int num_z() const { return num_z_; }
  int num_free() const { return static_cast<int>(free_.size()); }
  int num_r() const { return num_r_; }
  /// Measurements left out (gross errors found after a first fit): residual and Jacobian 0.
  void Exclude(const std::vector<char>& mask) { excluded_ = mask; }
  int num_excluded() const {
    return static_cast<int>(std::count(excluded_.begin(), excluded_.end(), 1));
  }
  const std::vector<TrialProblem>& trials() const { return trials_; }

  Eigen::VectorXd InitialZ() const {
    Eigen::VectorXd z(num_z_);
    for (std::size_t c = 0; c < free_.size(); ++c) z[c] = theta_[free_[c]];
    for (const TrialProblem& tp : trials_) {
      if (tp.z_chi0 >= 0) z[tp.z_chi0] = tp.init.chi0;
      if (tp.z_xi0 >= 0) z[tp.z_xi0] = tp.init.xi0;
    }
    return z;
  }

  Eigen::VectorXd Theta(const Eigen::VectorXd& z) const {
    Eigen::VectorXd theta = theta_;
    for (std::size_t c = 0; c < free_.size(); ++c) theta[free_[c]] = z[c];
    return theta;
  }

  std::vector<TrialInitialState> Initial(const Eigen::VectorXd& z) const {
    std::vector<TrialInitialState> out;
    for (const TrialProblem& tp : trials_) {
      TrialInitialState s = tp.init;
      if (tp.z_chi0 >= 0) s.chi0 = z[tp.z_chi0];
      if (tp.z_xi0 >= 0) s.xi0 = z[tp.z_xi0];
      out.push_back(s);
    }
    return out;
  }

  /// Residuals r = w·(y − ŷ) (when `r` is given), their cost ½‖r‖² (when `cost` is), and, when
  /// `rows` is given, the rows of J = ∂r/∂z, trial by trial (a block of its own initial-state
  /// columns and the free parameters', block_least_squares.h): the Jacobian of the campaign is
  /// never stored, nor, for a trial of one sensor on a grid, its simulation. False if a
  /// simulation fails.
  bool Evaluate(const Eigen::VectorXd& z, Eigen::VectorXd* r, BlockRowSink* rows,
                double* cost = nullptr) const {
    const Eigen::VectorXd theta = Theta(z);
    if (!Admissible(model_, theta)) return false;
    if (r) r->resize(num_r_);
    model::SimulationOptions so;
    so.step_s = o_.step_s;
    so.sensitivities = rows != nullptr;
    RowWriter out{r, rows, 0.0, true};
    for (const TrialProblem& tp : trials_) {
      Eigen::VectorXd x0 = Eigen::VectorXd::Zero(model_.num_states());
      x0[0] = tp.z_chi0 >= 0 ? z[tp.z_chi0] : tp.init.chi0;
      x0[1] = tp.z_xi0 >= 0 ? z[tp.z_xi0] : tp.init.xi0;
      const model::TrialConditions c = tp.trial->conditions();
      const model::TimesView at = tp.grid.empty() ? tp.times() : tp.grid;
      // ∂ŷ/∂ξ0 by a forward difference: a second, plain simulation (of a streamed trial at its
      // own times, only its sensor's values are kept).
      const bool streamed = tp.streamable(model_);
      const bool own_times = streamed && tp.grid.empty();
      model::Trajectory sim_xi;
      std::vector<double> sensor_xi;
      double h_xi = 0.0;
      if (rows && tp.z_xi0 >= 0) {
        h_xi = 1e-6 * std::max(1e-3, std::abs(x0[1]));
        Eigen::VectorXd x1 = x0;
        x1[1] += h_xi;
        model::SimulationOptions plain = so;
        plain.sensitivities = false;
        if (own_times) {
          sensor_xi = SensorValues(tp, theta, c, plain, x1);
        } else {
          sim_xi = model::SimulateMeasured(model_, theta, c, at, plain, &x1);
        }
      }
      const View tr_xi(tp, sim_xi, model_, theta, c);
      auto x_xi = [&](int i, int g, int s) { return own_times ? sensor_xi[i] : tr_xi.x(i, g, s); };
      const int own = (tp.z_chi0 >= 0 ? 1 : 0) + (tp.z_xi0 >= 0 ? 1 : 0);
      if (rows) rows->StartBlock(tp.z_chi0 >= 0 ? tp.z_chi0 : std::max(tp.z_xi0, 0), own);
      // Row of measurement k of sensor s at time index i (grid interval g): ŷ = x, its
      // sensitivities S(j) = ∂x_s/∂θ_j.
      auto fill = [&](const TrialProblem::Measurements& m, int s, std::size_t k, int i, int g,
                      double x, const auto& S) {
        const int row = tp.r_offset + static_cast<int>(s == 0 ? k : tp.pos.size() + k);
        const double w = m.weight(k);
        const bool excluded = row < static_cast<int>(excluded_.size()) && excluded_[row];
        const double res = excluded ? 0.0 : w * (m.y(k) - x);  // left out: residual and row 0
        double* J = out.Add(row, res);
        if (!J) return;
        int col = 0;
        if (tp.z_chi0 >= 0) J[col++] = s == 0 ? -w : 0.0;
        if (tp.z_xi0 >= 0) J[col++] = -w * (x_xi(i, g, s) - x) / h_xi;
        for (int j : free_) J[col++] = -w * S(j);
        J[col] = res;
        out.Commit(J, col, excluded);
      };
      if (streamed) {
        if (!Stream(tp, theta, c, so, x0, fill)) return false;
      } else {
        const model::Trajectory sim = model::SimulateMeasured(model_, theta, c, at, so, &x0);
        if (!sim.x.allFinite()) return false;
        const View tr(tp, sim, model_, theta, c);
        auto sensor = [&](const TrialProblem::Measurements& m, int s) {
          IntervalCursor interval(tp.grid);
          for (std::size_t k = 0; k < m.size(); ++k) {
            const int i = m.at(k);
            const int g = tp.grid.empty() ? 0 : interval(tp.times()[i]);
            fill(m, s, k, i, g, tr.x(i, g, s), [&](int j) { return tr.S(i, g, s, j); });
          }
        };
        sensor(tp.pos, 0);
        sensor(tp.vel, 1);
      }
      if (rows) rows->EndBlock();
    }
    if (rows) rows->Finish();
    if (cost) *cost = 0.5 * out.sum_squares;
    return out.finite;
  }

 private:
  // Where Evaluate's rows go: the residual vector (if any), the cost, the Jacobian's sink.
  struct RowWriter {
    Eigen::VectorXd* r;
    BlockRowSink* rows;
    double sum_squares;
    bool finite;
    // Records residual `res` of `row`; the sink's row to fill (the Jacobian's entries, then the
    // residual), or null without a Jacobian.
    double* Add(int row, double res) {
      if (r) (*r)[row] = res;
      sum_squares += res * res;
      finite = finite && std::isfinite(res);
      if (!rows) return nullptr;
      return rows->Row();
    }
    void Commit(double* J, int cols, bool excluded) {
      for (int c = 0; c < cols; ++c) {
        if (excluded) J[c] = 0.0;
        finite = finite && std::isfinite(J[c]);
      }
      rows->Commit();
    }
  };

  // One grid point of a streamed simulation: state, dx/dt (position, velocity) under the
  // interval's held input, and S row-major (state s, parameter j at s·P + j).
  struct GridPoint {
    double x[3] = {0, 0, 0};
    double dx[2] = {0, 0};
    std::vector<double> S;
  };

  // The sensor's values of a plain simulation of a trial at its own times, from x0.
  std::vector<double> SensorValues(const TrialProblem& tp, const Eigen::VectorXd& theta,
                                   const model::TrialConditions& c,
                                   const model::SimulationOptions& so,
                                   const Eigen::VectorXd& x0) const {
    const int s = tp.sensor();
    std::vector<double> values;
    values.reserve(tp.times().size());
    model::SimulateVisiting(
        model_, theta, c, tp.times(), so, &x0, model::Seen::kBySensors,
        [&](std::size_t, const double* x, const double*) { values.push_back(x[s]); });
    return values;
  }

  // The rows of a one-sensor trial at its own times, made while the simulation runs: nothing
  // of the simulation is stored (issue #16: 40 bytes a sample of a trial binned to 200k).
  template <class Fill>
  bool StreamAtOwnTimes(const TrialProblem& tp, const Eigen::VectorXd& theta,
                        const model::TrialConditions& c, const model::SimulationOptions& so,
                        const Eigen::VectorXd& x0, const Fill& fill) const {
    const int s = tp.sensor();
    const TrialProblem::Measurements& m = s == 0 ? tp.pos : tp.vel;
    const int np = model_.num_parameters();
    std::size_t k = 0;
    bool finite = true;
    const model::OutputVisitor visit = [&](std::size_t i, const double* x, const double* S) {
      if (!finite) return;  // diverged: Evaluate fails, its rows are not wanted
      finite = std::all_of(x, x + model_.num_states(), [](double v) { return std::isfinite(v); });
      for (; finite && k < m.size() && static_cast<std::size_t>(m.at(k)) == i; ++k) {
        fill(m, s, k, static_cast<int>(i), 0, x[s], [&](int j) { return S[s * np + j]; });
      }
    };
    model::SimulateVisiting(model_, theta, c, tp.times(), so, &x0, model::Seen::kBySensors, visit);
    return finite;
  }

  // The rows of a one-sensor trial on a grid, made while the simulation runs: each grid point
  // is kept until the next arrives, and the samples between the two are interpolated as View
  // does (the same numbers); the simulation with its sensitivities is never stored (16–24
  // bytes a sample). The samples' times must increase (a log's do). A trial whose initial
  // velocity is estimated still stores its plain finite-difference run on the grid (tr_xi).
  template <class Fill>
  bool Stream(const TrialProblem& tp, const Eigen::VectorXd& theta, const model::TrialConditions& c,
              const model::SimulationOptions& so, const Eigen::VectorXd& x0,
              const Fill& fill) const {
    if (tp.grid.empty()) return StreamAtOwnTimes(tp, theta, c, so, x0, fill);
    const int s = tp.sensor();
    const TrialProblem::Measurements& m = s == 0 ? tp.pos : tp.vel;
    const model::TimesView times = tp.times();
    const int np = model_.num_parameters();
    const std::size_t last = tp.grid.size() - 1;
    GridPoint left, right;
    std::size_t k = 0;
    bool finite = true;
    const model::OutputVisitor visit = [&](std::size_t g, const double* x, const double* S) {
      if (!finite) return;  // diverged: Evaluate fails, its rows are not wanted
      GridPoint& p = g == 0 ? left : right;
      std::copy(x, x + model_.num_states(), p.x);
      if (S) p.S.assign(S, S + model_.num_states() * np);
      finite = std::all_of(x, x + model_.num_states(), [](double v) { return std::isfinite(v); });
      if (g == 0 || !finite) return;
      const int a = static_cast<int>(g - 1);  // the interval [grid[a], grid[g]]
      HermiteSlopes(model_, tp.grid[a], tp.grid[g], left.x, right.x, theta, c, left.dx, right.dx);
      for (; k < m.size(); ++k) {
        const int i = m.at(k);
        const double t = times[i];
        if (t > tp.grid[g] && g < last) break;
        const TrialProblem::Hermite w = tp.Weights(t, a);
        const double xs =
            w.h00 * left.x[s] + w.h10 * left.dx[s] + w.h01 * right.x[s] + w.h11 * right.dx[s];
        fill(m, s, k, i, a, xs,
             [&](int j) { return (1 - w.u) * left.S[s * np + j] + w.u * right.S[s * np + j]; });
      }
      std::swap(left, right);
    };
    model::SimulateVisiting(model_, theta, c, tp.grid, so, &x0, model::Seen::kBySensors, visit);
    return finite;
  }

  // A simulation seen at tp.times: run there (as is), or on tp.grid and interpolated
  // (OutputErrorOptions::grid_s): position and velocity by cubic Hermite with dx/dt from the
  // model and the interval's input held at both ends (one-sided derivatives at breakpoints),
  // other states and the sensitivities linearly. Nothing is materialised at the sample times.
  class View {
   public:
    View(const TrialProblem& tp, const model::Trajectory& g, const model::DofModel& model,
         const Eigen::VectorXd& theta, const model::TrialConditions& c)
        : tp_(tp), g_(g) {
      if (tp.grid.empty() || g.x.rows() == 0) return;
      const int nx = static_cast<int>(g.x.cols());
      const std::size_t ng = tp.grid.size();
      dl_.resize(ng, 2);
      dr_.resize(ng, 2);
      double xa[3] = {0, 0, 0}, xb[3] = {0, 0, 0}, dl[2], dr[2];
      for (std::size_t k = 0; k + 1 < ng; ++k) {
        for (int s = 0; s < nx; ++s) {
          xa[s] = g.x(k, s);
          xb[s] = g.x(k + 1, s);
        }
        HermiteSlopes(model, tp.grid[k], tp.grid[k + 1], xa, xb, theta, c, dl, dr);
        dl_.row(k) << dl[0], dl[1];
        dr_.row(k) << dr[0], dr[1];
      }
    }
    // State s at time index i, in grid interval k (ignored without a grid).
    double x(int i, int k, int s) const {
      if (tp_.grid.empty()) return g_.x(i, s);
      const TrialProblem::Hermite w = tp_.Weights(tp_.times()[i], k);
      if (s >= 2) return (1 - w.u) * g_.x(k, s) + w.u * g_.x(k + 1, s);
      return w.h00 * g_.x(k, s) + w.h10 * dl_(k, s) + w.h01 * g_.x(k + 1, s) + w.h11 * dr_(k, s);
    }
    double S(int i, int k, int s, int j) const {
      if (tp_.grid.empty()) return g_.S[s](i, j);
      const double u = tp_.U(tp_.times()[i], k);
      return (1 - u) * g_.S[s](k, j) + u * g_.S[s](k + 1, j);
    }

   private:
    const TrialProblem& tp_;
    const model::Trajectory& g_;
    Eigen::MatrixXd dl_, dr_;  // dx/dt (position, velocity) at the left and right end of each interval
  };

  const model::DofModel& model_;
  Eigen::VectorXd theta_;
  std::vector<int> free_;
  OutputErrorOptions o_;
  std::vector<TrialProblem> trials_;
  int num_z_ = 0, num_r_ = 0;
  std::vector<char> excluded_;
};

// Mean lag-1 autocorrelation of the residuals within each trial's position and velocity parts.
double ResidualLag1(const Problem& p, const Eigen::VectorXd& r) {
  double sum = 0.0;
  int count = 0;
  for (const TrialProblem& tp : p.trials()) {
    int off = tp.r_offset;
    for (std::size_t len : {tp.pos.size(), tp.vel.size()}) {
      if (len >= 10) {  // read in place (two copies were 16 bytes a measurement)
        const auto seg = r.segment(off, len);
        const double mean = seg.mean();
        double den = 0.0, num = 0.0;
        for (Eigen::Index i = 0; i < seg.size(); ++i) {
          const double c = seg[i] - mean;
          den += c * c;
          if (i > 0) num += (seg[i - 1] - mean) * c;
        }
        if (den > 0) {
          sum += num / den;
          ++count;
        }
      }
      off += static_cast<int>(len);
    }
  }
  return count > 0 ? sum / count : 0.0;
}

}  // namespace

bool OutputErrorOptions::IsValid(std::string* error) const {
  return Require(max_iterations >= 1 && tolerance > 0 && step_s > 0 && max_condition > 1 &&
                     bin_s > 0 && grid_s >= 0,
                 "OutputErrorOptions: max_iterations >= 1, tolerance > 0, step_s > 0, bin_s > 0, "
                 "grid_s >= 0, max_condition > 1",
                 error) &&
         Require(use_position || use_velocity,
                 "OutputErrorOptions: use_position or use_velocity must be true", error);
}

std::string_view OutputErrorStatusName(OutputErrorStatus s) {
  static constexpr model::EnumNames<OutputErrorStatus, 4> kNames{{{
      {OutputErrorStatus::kConverged, "converged"},
      {OutputErrorStatus::kMaxIterations, "max_iterations"},
      {OutputErrorStatus::kIllConditioned, "ill_conditioned"},
      {OutputErrorStatus::kFailed, "failed"},
  }}};
  return kNames.Name(s);
}

namespace {

struct LmOutcome {
  Eigen::VectorXd z;
  Eigen::VectorXd r;       // at z: WithResiduals (the iterations keep only the cost)
  BlockLeastSquares rows;  // J at z, as its block-angular factor
  int iterations = 0;
  bool converged = false;
  bool failed = false;
  std::string message;
};

// Levenberg–Marquardt with Marquardt's diagonal scaling (Marquardt 1963): the step solves
// (JᵀJ + λ·diag(JᵀJ))·δ = −Jᵀr; a step is accepted only if it lowers the cost ½‖r‖² and keeps
// the parameters admissible and the simulation finite, λ shrinks after an accepted step and
// grows until one is found. Converged when the Gauss–Newton step at the current point is
// statistically negligible: its length in the metric of the estimate's covariance s²·(JᵀJ)⁻¹,
//   δ_GNᵀ (JᵀJ) δ_GN / s² = gᵀ(JᵀJ)⁻¹g / s²  <  kNegligibleStep² ,   g = Jᵀr,
// i.e. under a hundredth of a standard deviation. A tiny step taken under heavy damping is
// not convergence (the classic false stop of LM far from the minimum), nor is a point where no
// step lowers the cost while the Gauss–Newton step is still long: both are reported as not
// converged and the caller falls back. JᵀJ and Jᵀr come trial by trial from the block factor
// (block_least_squares.h), and the steps from its Schur complement.
constexpr double kNegligibleStep = 0.1;

LmOutcome LevenbergMarquardt(const Problem& p, Eigen::VectorXd z, const OutputErrorOptions& o) {
  LmOutcome out;
  const int shared = p.num_free();
  BlockLeastSquares J(shared);
  double cost = 0.0;
  if (!p.Evaluate(z, nullptr, &J, &cost)) {
    out.failed = true;
    out.message = "the simulation fails at the starting parameters";
    out.z = z;
    return out;
  }
  double lambda = 1e-3;
  const int dof = std::max(1, p.num_r() - p.num_excluded() - p.num_z());
  // Gauss–Newton decrement in units of the estimate's standard deviations (squared).
  auto decrement = [&](const BlockLeastSquares& a) {
    const double s2 = std::max(2.0 * cost / dof, 1e-300);
    const double dec = a.Gradient().dot(a.Solve(a.Gradient(), 0.0)) / s2;
    return std::isfinite(dec) ? std::abs(dec) : std::numeric_limits<double>::infinity();
  };
  for (int it = 0; it < o.max_iterations; ++it) {
    if (decrement(J) < kNegligibleStep * kNegligibleStep) {
      out.converged = true;
      break;
    }
    out.iterations = it + 1;
    bool accepted = false;
    double rel_decrease = 0.0;
    for (int tries = 0; tries < 30; ++tries) {
      const Eigen::VectorXd step = -J.Solve(J.Gradient(), lambda);
      if (!step.allFinite()) {
        lambda *= 10;
        continue;
      }
      const Eigen::VectorXd z_new = z + step;
      // The trial point is simulated with its sensitivities: most steps are accepted, and an
      // accepted step then needs no second simulation for its Jacobian.
      BlockLeastSquares J_trial(shared);
      double cost_new = 0.0;
      if (!p.Evaluate(z_new, nullptr, &J_trial, &cost_new)) {
        lambda *= 10;
        continue;
      }
      if (cost_new <= cost) {
        rel_decrease = (cost - cost_new) / std::max(cost, 1e-300);
        z = z_new;
        cost = cost_new;
        std::swap(J, J_trial);
        lambda = std::max(1e-12, lambda / 3);
        accepted = true;
        break;
      }
      lambda *= 4;
    }
    if (!accepted) {
      // No step lowers the cost. At the minimum to rounding when the Gauss–Newton step is
      // tiny in σ units (checked by the caller's final test below); otherwise stalled. (The
      // decrement of the point the last iteration started from: J is unchanged.)
      const double dec = decrement(J);
      out.converged = dec < 1.0;
      if (!out.converged) {
        out.message =
            "Levenberg–Marquardt stalled (no step lowers the cost, the Gauss–Newton "
            "step is still " +
            model::Significant(std::sqrt(dec), 3) + " σ long)";
      }
      break;
    }
    // The cost no longer changes at all (to the tolerance) with an undamped step: done.
    if (rel_decrease < o.tolerance && lambda < 1e-2 && decrement(J) < 1.0) {
      out.converged = true;
      break;
    }
  }
  if (!out.converged && !out.failed && out.message.empty()) {
    out.message = "Levenberg–Marquardt did not converge in " + std::to_string(o.max_iterations) +
                  " iterations";
  }
  out.z = z;
  out.rows = std::move(J);
  return out;
}

// The residuals at the fit's answer (one plain simulation; the iterations keep none: 16 bytes a
// measurement). False if that simulation fails, which the fit's own evaluation there did not.
bool WithResiduals(const Problem& p, LmOutcome* lm) { return p.Evaluate(lm->z, &lm->r, nullptr); }

}  // namespace

namespace {

// The coarse stage of a long record (OutputErrorOptions::coarse_measurements): the same
// unknowns (z layout) fitted on bins ~duration/coarse_measurements long with a longer RK4
// step; its answer starts the full-size fit. The start `z0` when the record is short or the
// coarse fit fails (the full-size fit then does all the work, as without this stage).
Eigen::VectorXd CoarseStart(const model::DofModel& model, const std::vector<const TrialData*>& trials,
                            const Eigen::VectorXd& theta, const std::vector<int>& free,
                            const std::vector<TrialInitialState>* initial, const Problem& full,
                            const Eigen::VectorXd& z0, const OutputErrorOptions& o) {
  if (o.coarse_measurements <= 0 || full.num_r() <= 2 * o.coarse_measurements) return z0;
  double duration = 0.0;
  for (const TrialProblem& tp : full.trials()) {
    if (!tp.times().empty()) duration += tp.times().back();
  }
  OutputErrorOptions c = o;
  c.bin_s = std::max(o.bin_s, duration / o.coarse_measurements);
  c.step_s = std::min(std::max(o.step_s, 0.1), std::max(o.step_s, 5.0 * o.step_s));
  c.grid_s = 0.0;
  const Problem coarse(model, trials, theta, free, initial, c);
  if (coarse.num_z() != full.num_z() || coarse.num_r() <= coarse.num_z()) return z0;
  const LmOutcome lm = LevenbergMarquardt(coarse, z0, c);
  return !lm.failed && lm.z.allFinite() ? lm.z : z0;
}

// Gross errors the data preparation let through (an outlier next to a command step, say)
// would pull a least-squares fit: residuals beyond 6 robust standard deviations (and 5
// declared σ) are left out and the fit repeated once. Returns how many were left out.
int RefitWithoutGrossErrors(Problem* p, const OutputErrorOptions& o, LmOutcome* lm,
                            int* iterations) {
  const double limit = std::max(5.0, 6.0 * 1.4826 * MedianAbs(lm->r));
  const auto gross =
      std::count_if(lm->r.begin(), lm->r.end(), [&](double x) { return std::abs(x) > limit; });
  if (gross == 0 || gross >= lm->r.size() / 100 + 1) return 0;
  std::vector<char> mask(lm->r.size(), 0);
  for (Eigen::Index i = 0; i < lm->r.size(); ++i) mask[i] = std::abs(lm->r[i]) > limit;
  p->Exclude(mask);
  LmOutcome again = LevenbergMarquardt(*p, lm->z, o);
  *iterations += again.iterations;
  if (again.failed || !WithResiduals(*p, &again)) {
    p->Exclude({});
    return 0;
  }
  *lm = std::move(again);
  return static_cast<int>(gross);
}

// The whitened score sums of the trials (covariance.h's WhitenedScoreSum over each trial's
// groups, in its local columns [own, θ]), fed by a second evaluation at the solution.
class TrialScoreSums : public BlockRowSink {
 public:
  TrialScoreSums(const Prewhitening& plan, int shared) : plan_(plan), shared_(shared) {}
  void StartBlock(int first_own, int own) override {
    sum_.emplace(own + shared_, plan_.block);
    row_.resize(own + shared_ + 1);
    blocks_.push_back({first_own, own, {}});
  }
  double* Row() override { return row_.data(); }
  void Commit() override {
    if (run_ < plan_.runs.size() && next_ == plan_.runs[run_].first) sum_->StartGroup(plan_.rho[run_++]);
    sum_->Add(row_.data(), row_.back());
    ++next_;
  }
  void EndBlock() override {
    blocks_.back().top = sum_->Sum();
    batches_ += sum_->batches();
  }
  /// Per trial: its first own column, own count and S_t (in `top`).
  const std::vector<BlockLeastSquares::Block>& sums() const { return blocks_; }
  int batches() const { return batches_; }

 private:
  const Prewhitening& plan_;
  int shared_;
  std::optional<WhitenedScoreSum> sum_;
  std::vector<double> row_;
  std::vector<BlockLeastSquares::Block> blocks_;
  std::size_t run_ = 0;
  int next_ = 0, batches_ = 0;
};

// Residuals correlated over the record (model error or coloured noise): the AR(1)-prewhitened
// sandwich of z (covariance.h; ρ per trial and sensor), each σ floored at its white-noise value
// (below). The scores are summed trial by trial (C·S·C = Σ_t C_t·S_t·C_tᵀ, S_t in the trial's
// columns); with the analysis' θ block only (many trials), C_t = SharedResponse.
Eigen::MatrixXd RobustCovariance(const Problem& p, const LmOutcome& lm, double sigma2,
                                 const BlockAnalysis& fa) {
  std::vector<int> groups(p.num_r());
  for (const TrialProblem& tp : p.trials()) {
    const int npos = static_cast<int>(tp.pos.size());
    for (int k = 0; k < tp.num_residuals(); ++k) {
      groups[tp.r_offset + k] = 2 * tp.trial->index + (k < npos ? 0 : 1);
    }
  }
  const Prewhitening plan = PlanPrewhitening(lm.r, groups);
  const int shared = p.num_free(), P = p.num_z();
  TrialScoreSums sums(plan, shared);
  if (!p.Evaluate(lm.z, nullptr, &sums)) return sigma2 * fa.unit_covariance;
  const double correction = sums.batches() > P ? double(sums.batches()) / (sums.batches() - P) : 1.0;
  const Eigen::MatrixXd& crb = fa.unit_covariance;
  Eigen::MatrixXd hac = Eigen::MatrixXd::Zero(crb.rows(), crb.cols());
  for (std::size_t t = 0; t < sums.sums().size(); ++t) {
    const BlockLeastSquares::Block& st = sums.sums()[t];
    Eigen::MatrixXd K(crb.rows(), st.own + shared);  // C_t: crb's columns [own, θ]
    if (fa.dense) {
      K << crb.middleCols(st.first, st.own), crb.leftCols(shared);
    } else {
      K = SharedResponse(lm.rows.blocks()[t], crb, shared);
    }
    hac.noalias() += K * st.top * K.transpose();
  }
  hac *= correction;
  // Each σ at least its white-noise value, the sandwich's correlations kept: D·HAC·D with
  // D_jj = max(1, √(s²·crb_jj / HAC_jj)). Replacing the whole matrix by the white one when any
  // entry (an initial state) fell below it threw away the colour of every other entry: VSOR
  // under ρ = 0.9 covered 83–87%, now 94.5–97%; bluerov yaw's kq −0.56 ± 0.07 (white σ on
  // residuals of lag-1 0.93) is ± 0.35.
  Eigen::VectorXd d(hac.rows());
  for (int j = 0; j < hac.rows(); ++j) {
    if (!(hac(j, j) > 0)) return sigma2 * crb;  // a degenerate sandwich: the white matrix
    d[j] = std::max(1.0, std::sqrt(sigma2 * crb(j, j) / hac(j, j)));
  }
  return d.asDiagonal() * hac * d.asDiagonal();
}

// Cov(z) = s²·(JᵀJ)⁻¹ (HAC when the residuals are coloured) and the CRB (JᵀJ)⁻¹, in the model
// layout; s², condition number, unidentifiable parameters and the status of the fit.
void StoreCovariance(const Problem& p, const LmOutcome& lm, const std::vector<int>& free,
                     const OutputErrorOptions& o, OutputErrorResult* res) {
  res->num_residuals = p.num_r() - p.num_excluded();
  res->cost = 0.5 * lm.r.squaredNorm();
  res->sigma2 = lm.r.squaredNorm() / (res->num_residuals - p.num_z());
  LeastSquaresOptions lso;
  lso.max_condition = o.max_condition;
  const BlockAnalysis fa = AnalyseBlocks(lm.rows, lso);
  res->condition_number = fa.condition_number;
  res->not_identifiable.clear();
  for (int c : fa.not_identifiable) {
    res->not_identifiable.push_back(c < static_cast<int>(free.size()) ? res->names[free[c]]
                                                                       : "initial state");
  }
  const Eigen::MatrixXd& crb_z = fa.unit_covariance;
  res->residual_lag1 = ResidualLag1(p, lm.r);
  res->hac_covariance = res->residual_lag1 > o.whiteness_threshold;
  const Eigen::MatrixXd cov_z =
      res->hac_covariance ? RobustCovariance(p, lm, res->sigma2, fa) : res->sigma2 * crb_z;
  res->covariance.setZero();
  res->crb.setZero();
  for (std::size_t a = 0; a < free.size(); ++a) {
    for (std::size_t b = 0; b < free.size(); ++b) {
      res->covariance(free[a], free[b]) = cov_z(a, b);
      res->crb(free[a], free[b]) = crb_z(a, b);
    }
  }
  const bool ill = fa.condition_number > o.max_condition || !fa.not_identifiable.empty();
  res->status = ill            ? OutputErrorStatus::kIllConditioned
                : lm.converged ? OutputErrorStatus::kConverged
                               : OutputErrorStatus::kMaxIterations;
  if (!lm.converged) res->notes.push_back(lm.message);
}

// Seed 000 §IV-D model selection: the free parameter to drop (the worst insignificant
// prunable one), or -1; its value and σ are kept and a note says why.
int DropWorst(const std::vector<int>& free, const OutputErrorOptions& o, Eigen::VectorXd* theta,
              std::vector<double>* before_value, std::vector<double>* before_sigma,
              OutputErrorResult* res) {
  const std::vector<PruneCandidate> candidates =
      CandidatesOf(res->names, *theta, res->covariance, free);
  double worst_pe = 0.0;
  std::vector<std::string> kept;
  const int c = WorstInsignificant(candidates, o.prunable, o.drop_correlation, &worst_pe, &kept);
  if (c < 0 || free.size() <= 1) {  // the final model: say what it kept
    res->notes.insert(res->notes.end(), kept.begin(), kept.end());
    return -1;
  }
  const int worst = free[c];
  (*before_value)[worst] = (*theta)[worst];
  (*before_sigma)[worst] = std::sqrt(res->covariance(worst, worst));
  res->notes.push_back(res->names[worst] + " = " + model::Significant((*theta)[worst], 4) + " ± " +
                       model::Significant((*before_sigma)[worst], 4) + " (" +
                       model::Significant(worst_pe, 3) +
                       "% > 51.02%): insignificant at 95%, dropped and the rest refitted");
  (*theta)[worst] = 0.0;
  res->state[worst] = ParameterState::kDropped;
  return worst;
}

std::string Message(const OutputErrorResult& res) {
  std::ostringstream os;
  os.precision(4);
  os << "output error: " << OutputErrorStatusName(res.status) << " after " << res.iterations
     << " iterations on " << res.num_residuals << " measurements, s² = " << res.sigma2;
  if (!res.not_identifiable.empty()) os << "; not identifiable: " << model::Join(res.not_identifiable);
  return os.str();
}

}  // namespace

OutputErrorResult OutputErrorFit(const model::DofModel& model,
                                 const std::vector<const TrialData*>& trials,
                                 const Eigen::VectorXd& theta0,
                                 const std::vector<ParameterState>& state0,
                                 const OutputErrorOptions& o) {
  OutputErrorResult res;
  const int np = model.num_parameters();
  res.names = model.parameter_names();
  res.theta = theta0;
  res.state = state0;
  res.state.resize(np, ParameterState::kEstimated);
  res.covariance = Eigen::MatrixXd::Zero(np, np);
  res.crb = Eigen::MatrixXd::Zero(np, np);
  if (!Admissible(model, theta0)) {
    res.status = OutputErrorStatus::kFailed;
    res.message = "output error: the starting parameters are not admissible (m must be > 0)";
    return res;
  }
  std::vector<double> before_value(np, 0.0), before_sigma(np, 0.0);
  Eigen::VectorXd theta = theta0;
  std::vector<TrialInitialState> initial;  // of the last fit, the next one's start
  int excluded_total = 0;
  // Fit, then drop the worst insignificant parameter and refit from where the fit ended.
  while (true) {
    std::vector<int> free;
    for (int j = 0; j < np; ++j) {
      if (res.state[j] == ParameterState::kEstimated) free.push_back(j);
    }
    Problem p(model, trials, theta, free, initial.empty() ? nullptr : &initial, o);
    if (p.num_r() <= p.num_z()) {
      res.status = OutputErrorStatus::kFailed;
      res.message = "output error: " + std::to_string(p.num_r()) + " measurements for " +
                    std::to_string(p.num_z()) + " unknowns";
      return res;
    }
    LmOutcome lm = LevenbergMarquardt(
        p, CoarseStart(model, trials, theta, free, initial.empty() ? nullptr : &initial, p, p.InitialZ(), o), o);
    res.iterations += lm.iterations;
    if (lm.failed || !WithResiduals(p, &lm)) {
      res.status = OutputErrorStatus::kFailed;
      res.message =
          "output error: " +
          (lm.failed ? lm.message : std::string("the simulation fails at the fitted parameters"));
      return res;
    }
    const int gross = RefitWithoutGrossErrors(&p, o, &lm, &res.iterations);
    if (gross > 0) excluded_total = gross;
    theta = p.Theta(lm.z);
    initial = p.Initial(lm.z);
    StoreCovariance(p, lm, free, o, &res);
    if (!o.prune_insignificant || res.status != OutputErrorStatus::kConverged) break;
    if (DropWorst(free, o, &theta, &before_value, &before_sigma, &res) < 0) break;
  }
  res.theta = theta;
  res.initial = initial;
  res.estimates = EstimatedAndDropped(res.names, res.theta, res.covariance, res.state,
                                      before_value, before_sigma);
  if (excluded_total > 0) {
    res.notes.push_back(std::to_string(excluded_total) +
                        " measurement(s) more than 6 robust σ from the fitted model left out as "
                        "gross errors");
  }
  if (res.hac_covariance) {
    res.notes.push_back(
        "output-error residuals are not white (mean lag-1 autocorrelation " +
        model::Significant(res.residual_lag1, 3) +
        "): model error or coloured noise; σ from the scores prewhitened by an "
        "AR(1) of the residuals per trial and sensor, then batch means (a sandwich)");
  }
  res.message = Message(res);
  return res;
}

Eigen::MatrixXd CramerRaoBound(const model::DofModel& model,
                               const std::vector<const TrialData*>& trials,
                               const Eigen::VectorXd& theta,
                               const std::vector<ParameterState>& state,
                               const std::vector<TrialInitialState>& initial,
                               const OutputErrorOptions& o) {
  const int np = model.num_parameters();
  std::vector<int> free;
  for (int j = 0; j < np; ++j) {
    if (j >= static_cast<int>(state.size()) || state[j] == ParameterState::kEstimated) free.push_back(j);
  }
  const Problem p(model, trials, theta, free, initial.empty() ? nullptr : &initial, o);
  BlockLeastSquares J(p.num_free());
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(np, np);
  if (!p.Evaluate(p.InitialZ(), nullptr, &J)) return out;
  // The θ block of M⁻¹, M = JᵀJ the Fisher information with r scaled by 1/σ.
  for (std::size_t a = 0; a < free.size(); ++a) {
    const Eigen::VectorXd column = J.Solve(Eigen::VectorXd::Unit(p.num_z(), a), 0.0);
    for (std::size_t b = 0; b < free.size(); ++b) out(free[b], free[a]) = column[b];
  }
  return out;
}

}  // namespace uuvplan::ident
