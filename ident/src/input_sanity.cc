// Unit and sign sanity of a campaign's logs (input_sanity.h). Every comparison is on the
// Savitzky–Golay smoothed signals (seed 000 §IV-D window at the log's rate), so that the noise
// of a differentiated position does not decide.
#include "uuvplan/ident/input_sanity.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <initializer_list>
#include <optional>

#include "number_text.h"
#include "options_check.h"
#include "uuvplan/ident/velocity_estimation.h"

namespace uuvplan::ident {
namespace {

using model::Dof;

constexpr double kDegreesPerRadian = 180.0 / M_PI;
constexpr std::size_t kMinSamples = 30;  // fewer aligned samples: no verdict

// The finite samples of a log column.
Signal Finite(const std::vector<double>& t, const std::vector<double>& y) {
  Signal s;
  for (std::size_t i = 0; i < y.size() && i < t.size(); ++i) {
    if (std::isfinite(y[i])) {
      s.t.push_back(t[i]);
      s.y.push_back(y[i]);
    }
  }
  return s;
}

// The signal smoothed and differentiated (twice) at the window seed 000 would use; nullopt when
// too short to smooth.
std::optional<SmoothedSignal> Smooth(const Signal& s, double input_time_scale) {
  if (s.size() < 2 * kMinSamples) return std::nullopt;
  const double step = MedianStep(s.t, 0, s.size());
  if (!(step > 0)) return std::nullopt;
  SavitzkyGolayOptions o;
  o.window = SavitzkyGolayWindow(1.0 / step, input_time_scale);
  return SavitzkyGolay(s, o);
}

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

// y = Σ θ_j x_j + b by least squares: θ (without b) and R².
struct LinearFit {
  Eigen::VectorXd theta;
  double r2 = 0.0;
};
LinearFit FitWithConstant(const std::vector<double>& y, const std::vector<const std::vector<double>*>& x) {
  const Eigen::Index n = static_cast<Eigen::Index>(y.size()), p = static_cast<Eigen::Index>(x.size());
  Eigen::MatrixXd a(n, p + 1);
  Eigen::VectorXd b(n);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index j = 0; j < p; ++j) a(i, j) = (*x[j])[i];
    a(i, p) = 1.0;
    b[i] = y[i];
  }
  const Eigen::VectorXd theta = a.colPivHouseholderQr().solve(b);
  const double ss_res = (a * theta - b).squaredNorm();
  const double ss_tot = (b.array() - b.mean()).square().sum();
  return {theta.head(p), ss_tot > 0 ? 1.0 - ss_res / ss_tot : 0.0};
}

// Whether y varies beyond rounding: its standard deviation above 1% of its RMS (a logged
// constant's printed digits give ~1e-10 of it; the smallest planned change of thrust, a sine's
// or a segment's, is tens of percent).
bool Varies(const std::vector<double>& y) {
  if (y.size() < 2) return false;
  double mean = 0, mean_square = 0;
  for (double v : y) mean += v, mean_square += v * v;
  mean /= static_cast<double>(y.size());
  mean_square /= static_cast<double>(y.size());
  const double variance = std::max(0.0, mean_square - mean * mean);
  return variance > 1e-4 * mean_square;
}

// 99th percentile of |y|.
double AbsQuantile99(const std::vector<double>& y) {
  std::vector<double> a(y.size());
  std::transform(y.begin(), y.end(), a.begin(), [](double v) { return std::abs(v); });
  const std::size_t k = static_cast<std::size_t>(0.99 * (a.size() - 1));
  std::nth_element(a.begin(), a.begin() + k, a.end());
  return a[k];
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
  std::optional<SmoothedSignal> pos, vel;
  Signal force;
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
  // The logged force in effect at t (zero-order hold of its rows, notes/pitfalls.md).
  double ForceAt(double t) const {
    const auto it = std::upper_bound(force.t.begin(), force.t.end(), t);
    return it == force.t.begin() ? std::nan("") : force.y[static_cast<std::size_t>(it - force.t.begin()) - 1];
  }
};

std::string RateUnitOf(Dof d) { return std::string(model::VelocityUnit(d)); }
std::string PositionUnitOf(Dof d) { return std::string(model::PositionUnit(d)); }

// The logged rate against the derivative of the logged position (both smoothed).
void CheckRateAgainstPosition(TrialCheck& c) {
  if (!c.pos || !c.vel) return;
  Samples s(3);  // d pos/dt, vel, pos
  for (std::size_t i = 0; i < c.pos->size(); ++i) {
    if (c.pos->edge[i]) continue;
    s.Add({c.pos->derivative[i], Interpolate(c.vel->t, c.vel->value, c.pos->t[i]), c.pos->value[i]});
  }
  if (s.size() < kMinSamples) return;
  const auto& dx = s.columns[0];
  const auto& v = s.columns[1];
  const double corr = Correlation(v, dx);
  if (std::abs(corr) < c.o.min_correlation) {
    const double follow = Correlation(v, s.columns[2]);
    if (std::abs(follow) >= c.o.follow_correlation && std::abs(corr) < c.o.min_correlation / 2) {
      c.Report(c.pos_name,
               "follows " + c.vel_name + " (correlation " + Fmt(follow, 3) +
                   ") instead of integrating it (correlation of " + c.vel_name +
                   " with its derivative " + Fmt(corr, 3) + ")",
               "it holds a velocity, not a position in " + PositionUnitOf(c.dof) +
                   " (log the position, or leave the column out)");
    }
    return;
  }
  double vdx = 0, dxdx = 0;
  for (std::size_t i = 0; i < dx.size(); ++i) vdx += v[i] * dx[i], dxdx += dx[i] * dx[i];
  const double ratio = vdx / dxdx;
  const std::string seen = c.vel_name + " is " + Fmt(ratio, 3) + " × the derivative of " +
                           c.pos_name + " (correlation " + Fmt(corr, 3) + ")";
  const bool rotational = model::IsRotational(c.dof);
  if (rotational && Near(ratio, kDegreesPerRadian, c.o.ratio_tolerance)) {
    c.Report(c.vel_name, seen, "likely in deg/s: expected rad/s (multiply by π/180)");
  } else if (rotational && Near(ratio, 1.0 / kDegreesPerRadian, c.o.ratio_tolerance)) {
    c.Report(c.pos_name, seen, "likely in degrees: expected rad (multiply by π/180)");
  } else if (Near(ratio, -1.0, c.o.ratio_tolerance)) {
    c.Report(c.vel_name, seen,
             "the two columns have opposite sign conventions: negate the one that is wrong "
             "(contract §Conventions)");
  } else if (std::abs(ratio) > c.o.unit_ratio_limit || std::abs(ratio) < 1.0 / c.o.unit_ratio_limit) {
    c.Report(c.vel_name, seen,
             "the two columns are in different units: expected " + PositionUnitOf(c.dof) + " and " +
                 RateUnitOf(c.dof));
  }
}

// A rotational rate faster than one turn per second is in degrees.
void CheckRotationRate(TrialCheck& c) {
  if (!model::IsRotational(c.dof)) return;
  const bool measured = c.vel.has_value();
  const SmoothedSignal* s = measured ? &*c.vel : c.pos ? &*c.pos : nullptr;
  if (!s) return;
  std::vector<double> rate;
  for (std::size_t i = 0; i < s->size(); ++i) {
    const double r = measured ? s->value[i] : s->derivative[i];
    if (!s->edge[i] && std::isfinite(r)) rate.push_back(r);
  }
  if (rate.size() < kMinSamples) return;
  const double q = AbsQuantile99(rate);
  if (!(q > c.o.max_rate)) return;
  const std::string column = measured ? c.vel_name : c.pos_name;
  c.Report(column,
           std::string(measured ? "its rate" : "its derivative") + " reaches " + Fmt(q, 3) +
               " rad/s (99th percentile), more than one turn per second",
           measured ? "likely in deg/s: expected rad/s (multiply by π/180)"
                    : "likely in degrees: expected rad (multiply by π/180)");
}

// Velocity and acceleration of the DOF at the motion's sample times, with the logged force.
Samples ForceAndMotion(const TrialCheck& c) {
  Samples s(4);  // force, acceleration, velocity, position
  const bool measured = c.vel.has_value();
  const SmoothedSignal& m = measured ? *c.vel : *c.pos;
  for (std::size_t i = 0; i < m.size(); ++i) {
    if (m.edge[i]) continue;
    const double v = measured ? m.value[i] : m.derivative[i];
    const double a = measured ? m.derivative[i] : m.second_derivative[i];
    s.Add({c.ForceAt(m.t[i]), a, v, measured ? 0.0 : m.value[i]});
  }
  return s;
}

// F = m·a + c·ν + b with m < 0 and c < 0: the force and the motion have opposite signs. Without
// a vel_ column, a position column that is a velocity is told by its force balance.
void CheckForceAgainstMotion(TrialCheck& c) {
  if (c.force.size() < 2 || (!c.pos && !c.vel)) return;
  const Samples s = ForceAndMotion(c);
  if (s.size() < kMinSamples) return;
  const auto& f = s.columns[0];
  // A force that does not vary (a steady trial's one step from rest) has no variance for a
  // balance to explain: its R² is 0/0, and neither the column's kind nor the sign can be read.
  if (!Varies(f)) return;
  const LinearFit as_position = FitWithConstant(f, {&s.columns[1], &s.columns[2]});
  if (!c.vel) {
    // The column read as a velocity: F = m·dx/dt + k·x + b.
    const LinearFit as_velocity = FitWithConstant(f, {&s.columns[2], &s.columns[3]});
    if (as_velocity.r2 >= c.o.min_fit && as_velocity.r2 >= as_position.r2 + c.o.fit_margin &&
        as_velocity.theta[0] > 0 && as_velocity.theta[1] > 0) {
      c.Report(c.pos_name,
               "the logged force reads as m·dx/dt + k·x of it (R² " + Fmt(as_velocity.r2, 3) +
                   ", m, k > 0), not as m·d²x/dt² + k·dx/dt (R² " + Fmt(as_position.r2, 3) + ")",
               "it holds a velocity in " + RateUnitOf(c.dof) + ", not a position: name it " +
                   c.vel_name);
      return;
    }
  }
  if (as_position.r2 >= c.o.min_sign_fit && as_position.theta[0] < 0 && as_position.theta[1] < 0) {
    c.Report(c.force_name,
             "F = m·a + c·ν + b fits the motion with m = " + Fmt(as_position.theta[0], 3) +
                 " and c = " + Fmt(as_position.theta[1], 3) + " (both < 0, R² " +
                 Fmt(as_position.r2, 3) + "): the force and the motion have opposite signs",
             "negate " + c.force_name + " (or the motion columns, or the mapping's direction; "
             "contract §Conventions)");
  }
}

void CheckTrial(const model::TrialEntry& e, const InputSanityOptions& o, std::vector<InputProblem>* out) {
  const model::TrialLog& log = e.log;
  const Dof dof = e.dof;
  const std::string name(model::DofName(dof));
  TrialCheck c{e, o, dof, "pos_" + name, "vel_" + name, "force_" + name, {}, {}, {}, out};
  c.force = Finite(log.t, log.HasForce(dof) ? log.force[model::Index(dof)] : std::vector<double>{});
  const double time_scale = InputTimeScale(c.force.t, c.force.y);
  if (log.HasPosition(dof)) c.pos = Smooth(Finite(log.t, log.position[model::Index(dof)]), time_scale);
  if (log.HasVelocity(dof)) c.vel = Smooth(Finite(log.t, log.velocity[model::Index(dof)]), time_scale);
  CheckRateAgainstPosition(c);
  CheckRotationRate(c);
  CheckForceAgainstMotion(c);
}

}  // namespace

bool InputSanityOptions::IsValid(std::string* error) const {
  return Require(min_correlation > 0 && min_correlation <= 1 && ratio_tolerance > 1 &&
                     unit_ratio_limit > 1 && max_rate > 0 && follow_correlation > 0 &&
                     follow_correlation <= 1 && min_fit > 0 && min_fit <= 1 && fit_margin >= 0 &&
                     min_sign_fit > 0 && min_sign_fit <= 1,
                 "InputSanityOptions: correlations and R² thresholds in (0, 1], tolerances > 1, "
                 "max_rate > 0",
                 error);
}

std::string InputProblem::Text() const { return file + ": column " + column + ": " + finding + " — " + fix; }

std::vector<InputProblem> CheckInputSanity(const model::Campaign& campaign, const InputSanityOptions& o) {
  std::vector<InputProblem> out;
  for (const model::TrialEntry& e : campaign.trials) CheckTrial(e, o, &out);
  return out;
}

}  // namespace uuvplan::ident
