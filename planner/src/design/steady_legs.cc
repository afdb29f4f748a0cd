// Step 1 of the steady design (steady_design.h): legs timed over the a priori box (settling
// from rest or from the legs before, the hold that measures the speed, the travel), and the
// candidates of every mapping and direction, from the no-reversal minimum to the largest force
// whose run fits the pool.
#include "design/steady_legs.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "design/sensor_information.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/mapping.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/fisher_information.h"
#include "uuvplan/planner/design/seed_rules.h"
#include "uuvplan/planner/design/steady_design.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner {
namespace internal {

std::string DirName(const std::string& mapping, int sign) {
  return mapping + (sign > 0 ? " (phi > 0)" : " (phi < 0)");
}

double SteadyLegTimer::HoldTime(double speed) const {
  const auto& s = ctx_.sensors();
  const double target = o_.speed_rel_sigma * std::max(std::abs(speed), 1e-6);
  double t = std::numeric_limits<double>::infinity();
  if (s.position) {  // LS slope of N = rate·T positions: σ² = 12σ_p²/(rate·T³)
    t = std::min(
        t, std::cbrt(12.0 * NoiseVariance(*s.position) / (s.position->rate_hz * target * target)));
  }
  if (s.velocity) {  // mean of N = rate·T velocities
    t = std::min(t, NoiseVariance(*s.velocity) / (s.velocity->rate_hz * target * target));
  }
  return std::max(o_.min_hold_s, t);
}

SteadyLegTimer::Timing SteadyLegTimer::TimeLeg(const std::vector<model::SegmentDesign>& prefix,
                                               const SteadyLeg& leg, double horizon) const {
  model::TrialDesign d;
  d.dof = ctx_.dof();
  d.kind = model::TrialKind::kSegments;
  d.mapping = leg.mapping;
  double t0 = 0.0;
  for (const auto& s : prefix) {
    d.segments.push_back(s);
    t0 += s.duration;
  }
  d.segments.push_back({leg.force, horizon, leg.mapping});
  d.duration = t0 + horizon;
  const auto input = model::MakeExcitation(ctx_.vehicle(), d);
  const DofPlanningProblem::TrialModel& tm = ctx_.ModelFor(d);
  const model::DofModel& m = *tm.model;
  const int ik = m.ParameterIndex(model::param::kLinearDrag);
  const int iq = m.ParameterIndex(model::param::kQuadraticDrag);
  const int ib = m.ParameterIndex(model::param::kBias);
  const int mi = ctx_.vehicle().MappingIndex(leg.mapping);
  const model::Direction dir = leg.force >= 0 ? model::Direction::kPos : model::Direction::kNeg;
  const int ie = mi >= 0 && !ctx_.vehicle().mappings[mi].IsOpenWater(dir)
                     ? m.ParameterIndex(model::EtaName(leg.mapping, dir))
                     : -1;
  auto steady = [&](const Eigen::VectorXd& th) {
    const double f = (ie >= 0 ? th[ie] : 1.0) * leg.force + (ib >= 0 ? th[ib] : 0.0);
    const double k = ik >= 0 ? th[ik] : 0.0, kq = iq >= 0 ? th[iq] : 0.0;
    return std::copysign(SteadySpeed(k, kq, std::abs(f)), f);
  };
  Timing out;
  out.settled = true;
  out.min_speed = std::numeric_limits<double>::infinity();
  out.centre_speed = steady(tm.design_thetas.front());
  const double dt = ctx_.step_s();
  std::vector<PositionTrace> traces;
  for (const auto& th : tm.check_thetas) {
    const double xs = steady(th);
    out.min_speed = std::min(out.min_speed, std::abs(xs));
    PositionTrace tr = TracePosition(m, th, *input, d.duration, dt, ctx_.step_s());
    // First sample after t0 from which the speed stays within the band.
    const double band = o_.settle_tolerance * std::abs(xs);
    std::size_t first = tr.velocity.size();
    for (std::size_t i = tr.velocity.size(); i-- > 0;) {
      if (i * dt < t0 - 1e-9) break;
      if (std::abs(tr.velocity[i] - xs) > band) break;
      first = i;
    }
    if (first >= tr.velocity.size() || first + 1 >= tr.velocity.size()) {
      out.settled = false;
    } else {
      out.settle_s = std::max(out.settle_s, first * dt - t0);
    }
    traces.push_back(std::move(tr));
  }
  if (!out.settled) return out;
  out.settle_s = std::ceil(out.settle_s - 1e-9);  // whole seconds for the pool team
  out.hold_s = std::ceil(HoldTime(out.min_speed) - 1e-9);
  const double end = t0 + out.settle_s + out.hold_s;
  for (const auto& tr : traces) {
    for (std::size_t i = 0; i < tr.position.size() && i * dt <= end + dt; ++i) {
      out.travel_lo = std::min(out.travel_lo, tr.position[i]);
      out.travel_hi = std::max(out.travel_hi, tr.position[i]);
    }
  }
  return out;
}

bool SteadyLegTimer::MakeLeg(const std::string& mapping, int sign, double force_abs,
                             SteadyLeg* leg) const {
  leg->mapping = mapping;
  leg->force = sign * force_abs;
  // Horizon: twice the settling time of the slowest linearised response (ref 000 eq. 13,
  // t_c = m/k_L at the heaviest, least-dragged box point) plus the longest hold; the full
  // trial limit only if that was not enough.
  const double t_max = ctx_.options().max_trial_duration_s;
  const int ik = ctx_.Index(model::param::kLinearDrag),
            iq = ctx_.Index(model::param::kQuadraticDrag);
  double tc = 0.0;
  for (const auto& th : ctx_.check_thetas()) {
    const double k = ik >= 0 ? th[ik] : 0.0, kq = iq >= 0 ? th[iq] : 0.0;
    const double kl = LinearisedDrag(k, kq, SteadySpeed(k, kq, 0.5 * force_abs));
    tc = std::max(tc, kl > 0 ? TimeConstant(th[0], kl) : t_max);
  }
  const double guess = 2.0 * tc * std::log(1.0 / o_.settle_tolerance) + 2.0 * o_.min_hold_s + 30.0;
  Timing t = TimeLeg({}, *leg, std::min(t_max, guess));
  if (!t.settled && guess < t_max) t = TimeLeg({}, *leg, t_max);
  if (!t.settled) return false;
  leg->settle_s = t.settle_s;
  leg->hold_s = t.hold_s;
  leg->speed = t.centre_speed;
  leg->travel = t.travel_hi - t.travel_lo;
  return true;
}

bool SteadyLegTimer::SmallestTimely(const std::string& mapping, int sign, double lo, double hi,
                                    double t_max, double* force, SteadyLeg* leg) const {
  const auto timely = [&](double f, SteadyLeg* l) {
    return MakeLeg(mapping, sign, f, l) && l->duration() <= t_max;
  };
  *force = lo;
  if (timely(lo, leg)) return true;
  if (!timely(hi, leg)) return false;
  double a = std::log(lo), b = std::log(hi);  // a fails, b succeeds (its leg in *leg)
  *force = hi;
  for (int it = 0; it < 8; ++it) {
    const double c = 0.5 * (a + b);
    SteadyLeg l;
    if (timely(std::exp(c), &l)) {
      b = c;
      *force = std::exp(c);
      *leg = l;
    } else {
      a = c;
    }
  }
  return true;
}

}  // namespace internal

using internal::DirName;

model::TrialDesign LegDesign(const SteadyLeg& leg, model::Dof dof, const std::string& id) {
  model::TrialDesign d;
  d.id = id;
  d.dof = dof;
  d.kind = model::TrialKind::kSteady;
  d.mapping = leg.mapping;
  d.force = leg.force;
  d.duration = leg.duration();
  return d;
}

SteadyCandidates MakeSteadyCandidates(const DofPlanningProblem& ctx, const SteadyDesignOptions& o) {
  SteadyCandidates out;
  const auto& v = ctx.vehicle();
  internal::SteadyLegTimer sp(ctx, o);
  const double avail = ctx.available();
  const double t_max = ctx.options().max_trial_duration_s;
  std::ostringstream infeasible;
  for (int mi : v.MappingsOf(ctx.dof())) {
    const std::string& name = v.mappings[mi].name;
    for (int s : {+1, -1}) {
      const ForceRange r = ctx.ForceRangeFor(mi, s);
      if (!r.feasible) {
        infeasible << " " << r.reason << ";";
        continue;
      }
      double lo = r.min_abs * 1.02;  // a 2% margin over min_thrust
      SteadyLeg smallest;
      if (!sp.SmallestTimely(name, s, lo, r.max_abs, t_max, &lo, &smallest)) {
        infeasible << " " << DirName(name, s) << ": no run from " << model::Significant(lo, 4)
                   << " to " << model::Significant(r.max_abs, 4) << " "
                   << model::ForceUnit(ctx.dof()) << " settles and holds within " << t_max << " s;";
        continue;
      }
      out.required_travel = std::max(out.required_travel, smallest.travel);
      if (smallest.travel > avail - kSteadyTravelMargin) {
        std::ostringstream m;
        const model::Dof dof = ctx.dof();
        const bool turns = model::IsRotational(dof);
        const std::string unit(model::PositionUnit(dof));
        m << DirName(name, s) << ": the smallest run (|phi| = " << model::Significant(lo, 4) << " "
          << model::ForceUnit(dof) << ", settles in " << model::Significant(smallest.settle_s, 3)
          << " s, holds " << model::Significant(smallest.hold_s, 3) << " s) travels "
          << model::Significant(smallest.travel, 4) << " " << unit << " over the box; the "
          << (turns ? "tether allows " : "pool has ") << model::Significant(avail, 4) << " " << unit
          << (turns ? "" : " free") << ": needs "
          << model::Significant(ctx.pool().ExtentFor(dof, smallest.travel), 4)
          << (turns ? " turns (max_turns)" : " m wall to wall");
        infeasible << " " << m.str() << ";";
        continue;
      }
      // Largest force whose run from rest fits the pool (bisection in log force).
      double hi = r.max_abs;
      SteadyLeg big;
      const bool big_ok = sp.MakeLeg(name, s, hi, &big);
      if (!big_ok || big.travel > avail - kSteadyTravelMargin || big.duration() > t_max) {
        double a = std::log(lo), b = std::log(hi);
        for (int it = 0; it < 8; ++it) {
          const double c = 0.5 * (a + b);
          SteadyLeg leg;
          const bool ok = sp.MakeLeg(name, s, std::exp(c), &leg) &&
                          leg.travel <= avail - kSteadyTravelMargin && leg.duration() <= t_max;
          (ok ? a : b) = c;
        }
        hi = std::exp(a);
      }
      const int K = hi > lo * 1.05 ? o.levels : 1;
      for (int k = 0; k < K; ++k) {
        const double f = K == 1 ? lo : lo * std::pow(hi / lo, static_cast<double>(k) / (K - 1));
        SteadyLeg leg;
        if (sp.MakeLeg(name, s, f, &leg) && leg.travel <= avail - kSteadyTravelMargin &&
            leg.duration() <= t_max) {
          out.legs.push_back(leg);
        }
      }
    }
  }
  out.infeasible = infeasible.str();
  return out;
}

}  // namespace uuvplan::planner
