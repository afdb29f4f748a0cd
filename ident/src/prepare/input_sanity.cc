// Unit and sign sanity of a campaign's logs (input_sanity.h). The comparisons are on the
// Savitzky–Golay smoothed signals (ref 000 §IV-D window at the log's rate), so that the noise
// of a differentiated position does not decide; where it still does, the rate's integral is
// compared with the raw position's changes over windows (RateAgainstIncrements).
#include "uuvplan/ident/prepare/input_sanity.h"

#include <Eigen/Dense>
#include <algorithm>
#include <array>
#include <cmath>
#include <initializer_list>
#include <optional>

#include "options_check.h"
#include "stats/centred_moments.h"
#include "uuvplan/ident/prepare/velocity_estimation.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {
namespace {

using model::Dof;

constexpr double kDegreesPerRadian = 180.0 / M_PI;
constexpr std::size_t kMinSamples = 30;  // fewer aligned samples: no verdict

// The finite samples of a log column.
Signal Finite(model::TimesView t, const std::vector<double>& y) {
  Signal s;
  const std::size_t n = std::min(t.size(), y.size());
  const auto finite =
      static_cast<std::size_t>(std::count_if(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(n),
                                             [](double v) { return std::isfinite(v); }));
  s.t.reserve(finite);
  s.y.reserve(finite);
  for (std::size_t i = 0; i < n; ++i) {
    if (std::isfinite(y[i])) {
      s.t.push_back(t[i]);
      s.y.push_back(y[i]);
    }
  }
  return s;
}

// A log column's finite samples with the Savitzky–Golay filter ref 000 would smooth them with
// (window at the log's rate). The smoothed signal is computed when a check needs it, stored
// (Smoothed) or streamed (ForEachSmoothed): a long log's check holds no per-sample copy.
struct Smoothable {
  const Signal& raw;
  SavitzkyGolayOptions sg;
  SmoothedSignal Smoothed() const { return SavitzkyGolay(raw, sg); }
};

// nullopt when too short to smooth.
std::optional<Smoothable> SmoothableOf(const Signal& s, double input_time_scale) {
  if (s.size() < 2 * kMinSamples) return std::nullopt;
  const double step = MedianStep(s.t, 0, s.size());
  if (!(step > 0)) return std::nullopt;
  SavitzkyGolayOptions o;
  o.window = SavitzkyGolayWindow(1.0 / step, input_time_scale);
  return Smoothable{s, o};
}

// A trial's own-DOF columns as signals of their finite samples (copies, Finite). From a log
// that lends them (`lender`), the columns go into their signals instead, and back to the log
// unchanged when this object goes: every all-finite column, the times shared; or, when there is
// none, the one column with few gaps (non-finite cells in at most 1/8 of the rows), compacted in
// place with the rows it drops kept aside. A million-row log's check then holds no second copy
// of it.
class OwnColumns {
 public:
  // `lender`, when given, is `log` itself.
  OwnColumns(const model::TrialLog& log, model::TrialLog* lender, Dof dof)
      : lender_(lender), dof_(dof) {
    if (!lender_) {
      for (std::size_t k = 0; k < kKinds.size(); ++k) signals_[k] = Finite(log.t, Column(log, k));
      return;
    }
    times_ = std::move(lender_->t);
    const std::size_t n = times_.size();
    std::array<std::size_t, 3> gaps{};
    for (std::size_t k = 0; k < kKinds.size(); ++k) {
      const std::vector<double>& y = Column(log, k);
      gaps[k] = y.size() != n
                    ? n + 1
                    : static_cast<std::size_t>(std::count_if(
                          y.begin(), y.end(), [](double v) { return !std::isfinite(v); }));
      lent_[k] = n > 0 && gaps[k] == 0;
    }
    if (std::none_of(lent_.begin(), lent_.end(), [](bool b) { return b; })) {
      for (std::size_t k = 0; k < kKinds.size() && compacted_ < 0; ++k) {
        if (n > 0 && gaps[k] <= n / 8) compacted_ = static_cast<int>(k);
      }
    }
    for (std::size_t k = 0; k < kKinds.size(); ++k) {  // copies first: compaction moves the times
      if (!Owned(k)) signals_[k] = Finite(times_, Column(log, k));
    }
    for (std::size_t k = 0; k < kKinds.size(); ++k) {
      if (!Owned(k)) continue;
      signals_[k].y = std::move(Column(*lender_, k));
      if (static_cast<int>(k) == compacted_) {
        times_.Change([&](std::vector<double>& t) { Compact(&t, &signals_[k].y); });
      }
      signals_[k].t = times_;
    }
  }
  ~OwnColumns() {
    if (!lender_) return;
    std::array<std::vector<double>, 3> ys;
    for (std::size_t k = 0; k < kKinds.size(); ++k) {
      ys[k] = std::move(signals_[k].y);
      signals_[k].t = SharedTimes();
    }
    std::vector<double> t = std::move(times_).Release();
    if (compacted_ >= 0) Restore(&t, &ys[compacted_]);
    for (std::size_t k = 0; k < kKinds.size(); ++k) {
      if (Owned(k)) Column(*lender_, k) = std::move(ys[k]);
    }
    lender_->t = std::move(t);
  }
  OwnColumns(const OwnColumns&) = delete;
  OwnColumns& operator=(const OwnColumns&) = delete;

  const Signal& force() const { return signals_[0]; }
  const Signal& position() const { return signals_[1]; }
  const Signal& velocity() const { return signals_[2]; }

 private:
  static constexpr std::array<model::LogColumnKind, 3> kKinds = {
      &model::TrialLog::force, &model::TrialLog::position, &model::TrialLog::velocity};
  struct Dropped {
    std::size_t row;
    double t, y;
  };

  // Whether column k is in its signal (lent or compacted), not copied.
  bool Owned(std::size_t k) const { return lent_[k] || static_cast<int>(k) == compacted_; }
  const std::vector<double>& Column(const model::TrialLog& log, std::size_t k) const {
    return (log.*kKinds[k])[model::Index(dof_)];
  }
  std::vector<double>& Column(model::TrialLog& log, std::size_t k) const {
    return (log.*kKinds[k])[model::Index(dof_)];
  }
  // Keeps the finite samples at the front, in order; the others are set aside.
  void Compact(std::vector<double>* t, std::vector<double>* y) {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < y->size(); ++i) {
      if (std::isfinite((*y)[i])) {
        (*t)[kept] = (*t)[i];
        (*y)[kept++] = (*y)[i];
      } else {
        dropped_.push_back({i, (*t)[i], (*y)[i]});
      }
    }
    t->resize(kept);
    y->resize(kept);
  }
  // Puts the dropped rows back where they were (the kept ones move down to make room).
  void Restore(std::vector<double>* t, std::vector<double>* y) const {
    std::size_t kept = t->size(), d = dropped_.size();
    t->resize(kept + d);
    y->resize(kept + d);
    for (std::size_t i = t->size(); i-- > 0;) {
      if (d > 0 && dropped_[d - 1].row == i) {
        --d;
        (*t)[i] = dropped_[d].t;
        (*y)[i] = dropped_[d].y;
      } else {
        --kept;
        (*t)[i] = (*t)[kept];
        (*y)[i] = (*y)[kept];
      }
    }
  }

  model::TrialLog* lender_;
  Dof dof_;
  SharedTimes times_;
  std::array<Signal, 3> signals_;
  std::array<bool, 3> lent_{};
  int compacted_ = -1;
  std::vector<Dropped> dropped_;
};

// Aligned samples of up to four quantities, with the least-squares tools the checks need.
struct Samples {
  std::vector<std::vector<double>> columns;  // each of the same length
  explicit Samples(int n) : columns(n) {}
  std::size_t size() const { return columns[0].size(); }
  void Add(std::initializer_list<double> values) {
    if (std::any_of(values.begin(), values.end(), [](double v) { return !std::isfinite(v); })) {
      return;
    }
    int k = 0;
    for (double v : values) columns[k++].push_back(v);
  }
};

double Correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) ma += a[i] / n, mb += b[i] / n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

// y = Σ θ_j x_j + b by least squares over the samples summed in `m` (quantity y against the
// quantities x): θ (without b) and R². Centred, the constant drops out: θ = S_xx⁻¹ S_xy,
// SS_res = S_yy − θᵀ S_xy, SS_tot = S_yy.
struct LinearFit {
  Eigen::Vector2d theta = Eigen::Vector2d::Zero();
  double r2 = 0.0;
};
LinearFit FitWithConstant(const CentredMoments<4>& m, int y, int x0, int x1) {
  const Eigen::Matrix4d s = m.scatter();
  Eigen::Matrix2d sxx;
  sxx << s(x0, x0), s(x0, x1), s(x1, x0), s(x1, x1);
  const Eigen::Vector2d sxy(s(x0, y), s(x1, y));
  const Eigen::Vector2d theta = sxx.colPivHouseholderQr().solve(sxy);
  const double ss_tot = s(y, y);
  const double ss_res = std::max(0.0, ss_tot - theta.dot(sxy));
  return {theta, ss_tot > 0 ? 1.0 - ss_res / ss_tot : 0.0};
}

// Whether quantity k varies beyond rounding: its standard deviation above 1% of its RMS (a
// logged constant's printed digits give ~1e-10 of it; the smallest planned change of thrust, a
// sine's or a segment's, is tens of percent).
bool Varies(const CentredMoments<4>& m, int k) {
  if (m.count() < 2) return false;
  const double variance = m.scatter()(k, k) / static_cast<double>(m.count());
  const double mean_square = variance + m.mean()[k] * m.mean()[k];
  return variance > 1e-4 * mean_square;
}

// 99th percentile of |y| (y reordered in place).
double AbsQuantile99(std::vector<double> y) {
  for (double& v : y) v = std::abs(v);
  const std::size_t k = static_cast<std::size_t>(0.99 * (y.size() - 1));
  std::nth_element(y.begin(), y.begin() + static_cast<std::ptrdiff_t>(k), y.end());
  return y[k];
}

bool Near(double ratio, double target, double tolerance) {
  return ratio / target > 1.0 / tolerance && ratio / target < tolerance;
}

// One trial's own-DOF signals and what the checks found.
struct TrialCheck {
  const model::TrialEntry& entry;
  const InputSanityOptions& o;
  Dof dof;
  std::string pos_name, vel_name, force_name;
  std::optional<Smoothable> pos, vel;
  const Signal& force;
  std::vector<InputProblem>* out;

  bool Flagged(const std::string& column) const {
    return std::any_of(out->begin(), out->end(), [&](const InputProblem& p) {
      return p.column == column && p.file == File();
    });
  }
  std::string File() const { return entry.path.empty() ? entry.file : entry.path; }
  void Report(const std::string& column, const std::string& finding, const std::string& fix) {
    if (!Flagged(column)) out->push_back({File(), column, finding, fix});
  }
};

std::string RateUnitOf(Dof d) { return std::string(model::VelocityUnit(d)); }
std::string PositionUnitOf(Dof d) { return std::string(model::PositionUnit(d)); }

// The ratio of the rate to the position's change, read from windows of about `window_s` (and
// at least 5 samples) of the position samples: the change Δp of each against the rate's
// integral I over it (trapezoids of the rate samples, interpolated at the window's ends).
// With Δp ≈ I/ratio in every window, ratio = ΣI²/ΣIΔp; `cosine` = ΣIΔp/√(ΣI²ΣΔp²) says how
// well one ratio explains them all (uncentred: a steady run's windows all change alike).
struct IncrementRatio {
  double ratio = 0.0, cosine = 0.0;
  int windows = 0;
};
IncrementRatio RateAgainstIncrements(const Signal& pos, const Signal& vel, double window_s) {
  IncrementRatio out;
  if (pos.size() < 2 || vel.size() < 2) return out;
  const double step = MedianStep(pos.t, 0, pos.size());
  const std::size_t k = std::max<std::size_t>(5, static_cast<std::size_t>(window_s / step));
  const SharedTimes& vt = vel.t;
  auto integral = [&](double a, double b) {  // ∫_a^b rate dt, trapezoids
    if (a < vt.front() || b > vt.back()) return std::nan("");
    std::size_t i = std::upper_bound(vt.begin(), vt.end(), a) - vt.begin();
    double s = 0.0, t0 = a, v0 = Interpolate(vt, vel.y, a);
    for (; i < vt.size() && vt[i] < b; ++i) {
      s += 0.5 * (v0 + vel.y[i]) * (vt[i] - t0);
      t0 = vt[i];
      v0 = vel.y[i];
    }
    return s + 0.5 * (v0 + Interpolate(vt, vel.y, b)) * (b - t0);
  };
  double ii = 0.0, ip = 0.0, pp = 0.0;
  for (std::size_t a = 0; a + k < pos.size(); a += k) {
    const double I = integral(pos.t[a], pos.t[a + k]);
    const double dp = pos.y[a + k] - pos.y[a];
    if (!std::isfinite(I) || !std::isfinite(dp)) continue;
    ii += I * I, ip += I * dp, pp += dp * dp;
    ++out.windows;
  }
  if (!(ii > 0 && pp > 0 && ip != 0)) return out;
  out.ratio = ii / ip;
  out.cosine = ip / std::sqrt(ii * pp);
  return out;
}

// The logged rate against the derivative of the logged position (both smoothed), else
// against the position's changes over windows (RateAgainstIncrements).
void CheckRateAgainstPosition(TrialCheck& c) {
  if (!c.pos || !c.vel) return;
  const SmoothedSignal vel = c.vel->Smoothed();
  Samples s(3);  // d pos/dt, vel, pos
  ForEachSmoothed(c.pos->raw, c.pos->sg, [&](const SmoothedSample& p) {
    if (!p.edge) s.Add({p.derivative, Interpolate(vel.t, vel.value, c.pos->raw.t[p.i]), p.value});
  });
  if (s.size() < kMinSamples) return;
  const auto& dx = s.columns[0];
  const auto& v = s.columns[1];
  const double corr = Correlation(v, dx);
  double ratio = 0.0;
  std::string seen;
  // Read from windows, the ratio is not centred: a steady run's windows all change alike, so a
  // rate offset (a gyro's bias) moves it. It names degrees and a flipped sign (57.3, 1/57.3,
  // −1), not a ratio merely outside [1/2, 2].
  bool from_windows = false;
  if (std::abs(corr) >= c.o.min_correlation) {
    double vdx = 0, dxdx = 0;
    for (std::size_t i = 0; i < dx.size(); ++i) vdx += v[i] * dx[i], dxdx += dx[i] * dx[i];
    ratio = vdx / dxdx;
    seen = c.vel_name + " is " + model::Significant(ratio, 3) + " × the derivative of " +
           c.pos_name + " (correlation " + model::Significant(corr, 3) + ")";
  } else if (const IncrementRatio inc =
                 RateAgainstIncrements(c.pos->raw, c.vel->raw, c.o.increment_window_s);
             inc.windows >= 5 && std::abs(inc.cosine) >= c.o.min_correlation) {
    from_windows = true;
    ratio = inc.ratio;
    seen = "the integral of " + c.vel_name + " is " + model::Significant(ratio, 3) +
           " × the change of " + c.pos_name + " over " + std::to_string(inc.windows) +
           " windows of " + model::Significant(c.o.increment_window_s, 3) + " s (cosine " +
           model::Significant(inc.cosine, 3) +
           "; the derivative is too noisy to compare, correlation " + model::Significant(corr, 3) +
           ")";
  } else {
    const double follow = Correlation(v, s.columns[2]);
    if (std::abs(follow) >= c.o.follow_correlation && std::abs(corr) < c.o.min_correlation / 2) {
      c.Report(c.pos_name,
               "follows " + c.vel_name + " (correlation " + model::Significant(follow, 3) +
                   ") instead of integrating it (correlation of " + c.vel_name +
                   " with its derivative " + model::Significant(corr, 3) + ")",
               "it holds a velocity, not a position in " + PositionUnitOf(c.dof) +
                   " (log the position, or leave the column out)");
    }
    return;
  }
  const bool rotational = model::IsRotational(c.dof);
  if (rotational && Near(ratio, kDegreesPerRadian, c.o.ratio_tolerance)) {
    c.Report(c.vel_name, seen, "likely in deg/s: expected rad/s (multiply by π/180)");
  } else if (rotational && Near(ratio, 1.0 / kDegreesPerRadian, c.o.ratio_tolerance)) {
    c.Report(c.pos_name, seen, "likely in degrees: expected rad (multiply by π/180)");
  } else if (Near(ratio, -1.0, c.o.ratio_tolerance)) {
    c.Report(c.vel_name, seen,
             "the two columns have opposite sign conventions: negate the one that is wrong "
             "(contract §Conventions)");
  } else if (!from_windows && (std::abs(ratio) > c.o.unit_ratio_limit ||
                               std::abs(ratio) < 1.0 / c.o.unit_ratio_limit)) {
    c.Report(c.vel_name, seen,
             "the two columns are in different units: expected " + PositionUnitOf(c.dof) + " and " +
                 RateUnitOf(c.dof));
  }
}

// A rotational rate faster than one turn per second is in degrees.
void CheckRotationRate(TrialCheck& c) {
  if (!model::IsRotational(c.dof)) return;
  const bool measured = c.vel.has_value();
  const Smoothable* s = measured ? &*c.vel : c.pos ? &*c.pos : nullptr;
  if (!s) return;
  std::vector<double> rate;
  ForEachSmoothed(s->raw, s->sg, [&](const SmoothedSample& p) {
    const double r = measured ? p.value : p.derivative;
    if (!p.edge && std::isfinite(r)) rate.push_back(r);
  });
  if (rate.size() < kMinSamples) return;
  const double q = AbsQuantile99(std::move(rate));
  if (!(q > c.o.max_rate)) return;
  const std::string column = measured ? c.vel_name : c.pos_name;
  c.Report(column,
           std::string(measured ? "its rate" : "its derivative") + " reaches " +
               model::Significant(q, 3) + " rad/s (99th percentile), more than one turn per second",
           measured ? "likely in deg/s: expected rad/s (multiply by π/180)"
                    : "likely in degrees: expected rad (multiply by π/180)");
}

// Sums of (force, acceleration, velocity, position) over the finite non-edge samples of the
// DOF's smoothed motion (the measured velocity, else the position; position 0 with a measured
// velocity), the force held from its last row at or before each sample (zero-order hold,
// notes/pitfalls.md; a forward cursor, the samples are in time order).
CentredMoments<4> ForceAndMotion(const TrialCheck& c) {
  CentredMoments<4> sums;
  const bool measured = c.vel.has_value();
  const Smoothable& m = measured ? *c.vel : *c.pos;
  std::size_t rows = 0;  // force rows at or before the sample's time
  ForEachSmoothed(m.raw, m.sg, [&](const SmoothedSample& p) {
    if (p.edge) return;
    const double t = m.raw.t[p.i];
    while (rows < c.force.size() && c.force.t[rows] <= t) ++rows;
    const double f = rows == 0 ? std::nan("") : c.force.y[rows - 1];
    const double v = measured ? p.value : p.derivative;
    const double a = measured ? p.derivative : p.second_derivative;
    const Eigen::Vector4d x(f, a, v, measured ? 0.0 : p.value);
    if (x.allFinite()) sums.Add(x);
  });
  return sums;
}

// F = m·a + c·ν + b with m < 0 and c < 0: the force and the motion have opposite signs. Without
// a vel_ column, a position column that is a velocity is told by its force balance.
void CheckForceAgainstMotion(TrialCheck& c) {
  if (c.force.size() < 2 || (!c.pos && !c.vel)) return;
  const CentredMoments<4> s = ForceAndMotion(c);  // 0 force, 1 acceleration, 2 velocity, 3 position
  if (s.count() < kMinSamples) return;
  // A force that does not vary (a steady trial's one step from rest) has no variance for a
  // balance to explain: its R² is 0/0, and neither the column's kind nor the sign can be read.
  if (!Varies(s, 0)) return;
  const LinearFit as_position = FitWithConstant(s, 0, 1, 2);
  if (!c.vel) {
    // The column read as a velocity: F = m·dx/dt + k·x + b.
    const LinearFit as_velocity = FitWithConstant(s, 0, 2, 3);
    if (as_velocity.r2 >= c.o.min_fit && as_velocity.r2 >= as_position.r2 + c.o.fit_margin &&
        as_velocity.theta[0] > 0 && as_velocity.theta[1] > 0) {
      c.Report(c.pos_name,
               "the logged force reads as m·dx/dt + k·x of it (R² " +
                   model::Significant(as_velocity.r2, 3) +
                   ", m, k > 0), not as m·d²x/dt² + k·dx/dt (R² " +
                   model::Significant(as_position.r2, 3) + ")",
               "it holds a velocity in " + RateUnitOf(c.dof) + ", not a position: name it " +
                   c.vel_name);
      return;
    }
  }
  if (as_position.r2 >= c.o.min_sign_fit && as_position.theta[0] < 0 && as_position.theta[1] < 0) {
    c.Report(c.force_name,
             "F = m·a + c·ν + b fits the motion with m = " +
                 model::Significant(as_position.theta[0], 3) +
                 " and c = " + model::Significant(as_position.theta[1], 3) + " (both < 0, R² " +
                 model::Significant(as_position.r2, 3) +
                 "): the force and the motion have opposite signs",
             "negate " + c.force_name +
                 " (or the motion columns, or the mapping's direction; "
                 "contract §Conventions)");
  }
}

// A measurement that never changes while the force commands thrust: a stuck or disconnected
// sensor (identification would fit it: a constant position read as an immovable vehicle gave
// payload60 surge m = 3227 kg, 27× its a priori range, with exit 0).
void CheckStuckSensor(TrialCheck& c) {
  double push = 0.0;
  for (double f : c.force.y) push = std::max(push, std::abs(f));
  if (!(push > 0)) return;
  for (const auto& [m, column] : {std::pair(&c.pos, c.pos_name), std::pair(&c.vel, c.vel_name)}) {
    if (!m->has_value()) continue;
    const std::vector<double>& y = (*m)->raw.y;
    const auto [lo, hi] = std::minmax_element(y.begin(), y.end());
    if (*lo != *hi) continue;
    c.Report(column,
             "every one of its " + std::to_string(y.size()) + " values is " +
                 model::Significant(*lo, 4) + " while " + c.force_name + " commands up to " +
                 model::Significant(push, 3) + " " + std::string(model::ForceUnit(c.dof)),
             "a stuck or disconnected sensor, or a vehicle that did not move: check the log, "
             "or leave the column empty");
  }
}

void CheckTrial(const model::TrialEntry& e, model::TrialLog* lender, const InputSanityOptions& o,
                std::vector<InputProblem>* out) {
  const OwnColumns columns(e.log, lender, e.dof);
  const std::string name(model::DofName(e.dof));
  const double time_scale = InputTimeScale(columns.force().t, columns.force().y);
  TrialCheck c{e,
               o,
               e.dof,
               "pos_" + name,
               "vel_" + name,
               "force_" + name,
               SmoothableOf(columns.position(), time_scale),
               SmoothableOf(columns.velocity(), time_scale),
               columns.force(),
               out};
  CheckStuckSensor(c);
  CheckRateAgainstPosition(c);
  CheckRotationRate(c);
  CheckForceAgainstMotion(c);
}

}  // namespace

bool InputSanityOptions::IsValid(std::string* error) const {
  return Require(min_correlation > 0 && min_correlation <= 1 && ratio_tolerance > 1 &&
                     unit_ratio_limit > 1 && max_rate > 0 && follow_correlation > 0 &&
                     follow_correlation <= 1 && min_fit > 0 && min_fit <= 1 && fit_margin >= 0 &&
                     min_sign_fit > 0 && min_sign_fit <= 1 && std::isfinite(increment_window_s) &&
                     increment_window_s > 0,
                 "InputSanityOptions: correlations and R² thresholds in (0, 1], tolerances > 1, "
                 "max_rate > 0, increment_window_s finite and > 0",
                 error);
}

std::string InputProblem::Text() const {
  return file + ": column " + column + ": " + finding + " — " + fix;
}

std::vector<InputProblem> CheckInputSanity(const model::Campaign& campaign,
                                           const InputSanityOptions& o) {
  std::vector<InputProblem> out;
  for (const model::TrialEntry& e : campaign.trials) CheckTrial(e, nullptr, o, &out);
  return out;
}

std::vector<InputProblem> CheckInputSanity(model::Campaign* campaign, const InputSanityOptions& o) {
  std::vector<InputProblem> out;
  for (model::TrialEntry& e : campaign->trials) CheckTrial(e, &e.log, o, &out);
  return out;
}

}  // namespace uuvplan::ident
