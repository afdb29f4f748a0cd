// Robust optimal sinusoid trial (see sine_design.h).
#include "uuvplan/planner/design/sine_design.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "design/sine_family_objective.h"
#include "design/travel_margin.h"
#include "options_check.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/util/checked_count.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/fisher_information.h"
#include "uuvplan/planner/design/seed_rules.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner {

constexpr model::EnumNames<DesignStatus, 3> kDesignStatusNames{
    {{{DesignStatus::kOk, "ok"},
      {DesignStatus::kInfeasible, "infeasible"},
      {DesignStatus::kFailed, "failed"}}}};

std::string_view DesignStatusName(DesignStatus s) { return kDesignStatusNames.Name(s); }

bool SineDesignOptions::IsValid(std::string* error) const {
  internal::OptionsCheck check("SineDesignOptions", error);
  check.Require(fixed_duration_s >= 0, "fixed_duration_s", fixed_duration_s, ">= 0")
      .Require(max_duration_s >= 0, "max_duration_s", max_duration_s, ">= 0")
      .Require(min_periods >= 0, "min_periods", min_periods, ">= 0")
      .Require(min_amplitude_fraction >= 0 && min_amplitude_fraction <= 1, "min_amplitude_fraction",
               min_amplitude_fraction, "in [0, 1]")
      .Require(sign >= -1 && sign <= 1, "sign", sign, "-1, 0 or 1");
  return check.ok();
}

namespace {

// Hull of the travel over several parameter points as the trial goes on: the first time the
// span (max over points of position - min over points of position) exceeds `available`.
// The point with the fastest steady speed is traced first over [0, t_max]; the others only up
// to where it overflows (the hull overflows no later than any single point does).
double FirstOverflow(const DofPlanningProblem& ctx, const model::DofModel& model,
                     const std::vector<Eigen::VectorXd>& thetas, const model::Excitation& input,
                     double t_max) {
  const double dt = ctx.step_s();
  const int ik = model.ParameterIndex(model::param::kLinearDrag);
  const int iq = model.ParameterIndex(model::param::kQuadraticDrag);
  std::vector<std::size_t> order(thetas.size());
  for (std::size_t j = 0; j < order.size(); ++j) order[j] = j;
  auto speed = [&](const Eigen::VectorXd& th) {
    const double k = ik >= 0 ? th[ik] : 0.0, kq = iq >= 0 ? th[iq] : 0.0;
    return std::make_pair(-SteadySpeed(k, kq, 1.0), th[0]);  // fastest, then lightest, first
  };
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return speed(thetas[a]) < speed(thetas[b]); });
  const double avail = ctx.available() - kSineTravelMargin;
  std::vector<double> lo, hi;
  double horizon = t_max;
  for (std::size_t n = 0; n < order.size(); ++n) {
    const PositionTrace tr =
        TracePosition(model, thetas[order[n]], input, horizon, dt, ctx.step_s());
    if (lo.size() < tr.position.size()) {
      lo.resize(tr.position.size(), 0.0);
      hi.resize(tr.position.size(), 0.0);
    }
    double run_lo = 0.0, run_hi = 0.0;
    for (std::size_t i = 0; i < tr.position.size(); ++i) {
      run_lo = std::min(run_lo, tr.position[i]);
      run_hi = std::max(run_hi, tr.position[i]);
      lo[i] = std::min(lo[i], run_lo);
      hi[i] = std::max(hi[i], run_hi);
    }
    if (n == 0) {
      for (std::size_t i = 1; i < lo.size(); ++i) {
        if (hi[i] - lo[i] > avail) {
          horizon = std::min(t_max, (i + 1) * dt);
          break;
        }
      }
    }
  }
  const std::size_t n_valid =
      model::CheckedCount<std::size_t>(horizon / dt, "sine design horizon samples",
                                       model::limits::kMaxTrialRows, "a shorter trial") +
      1;
  for (std::size_t i = 1; i < lo.size() && i < n_valid; ++i) {
    const double s1 = hi[i] - lo[i];
    if (s1 > avail) {
      const double s0 = hi[i - 1] - lo[i - 1];
      const double t0 = (i - 1) * dt, t1 = std::min(i * dt, t_max);
      const double f = s1 > s0 ? (avail - s0) / (s1 - s0) : 0.0;
      return t0 + std::clamp(f, 0.0, 1.0) * (t1 - t0);
    }
  }
  return horizon < t_max ? horizon : t_max;
}

struct Candidate {
  int mapping = -1;
  int sign = 1;
  ForceRange range;
};

class SineProblem {
 public:
  SineProblem(const DofPlanningProblem& ctx, const SineDesignOptions& o,
              const std::vector<Eigen::MatrixXd>& prior, const Candidate& c, double t_max)
      : ctx_(ctx),
        o_(o),
        objective_(ctx, o, prior, 0.5 * (c.range.min_abs + c.range.max_abs),
                   o.fixed_duration_s > 0 ? o.fixed_duration_s : t_max),
        c_(c),
        t_max_(t_max) {
    const double x_mid[3] = {0.5, 0.5, 0.5};
    tm_ = &ctx.ModelFor(Decode(x_mid));  // one direction throughout: the same model for all x
  }

  // x = (u, r, v) -> the trial (duration not yet set).
  model::TrialDesign Decode(const double* x) const {
    model::TrialDesign d;
    d.dof = ctx_.dof();
    d.kind = model::TrialKind::kSine;
    d.mapping = ctx_.vehicle().mappings[c_.mapping].name;
    const double lo = c_.range.min_abs, hi = c_.range.max_abs, rho = o_.min_amplitude_fraction;
    const double o_max = (hi + rho * lo) / (1.0 + rho);
    const double off = lo + std::clamp(x[0], 0.0, 1.0) * (o_max - lo);
    const double depth = off - lo;
    const double top = std::max(rho * depth, std::min(depth, hi - off));
    d.offset = c_.sign * off;
    d.amplitude = rho * depth + std::clamp(x[1], 0.0, 1.0) * (top - rho * depth);
    d.omega = objective_.Omega(x[2]);
    return d;
  }

  // Duration of a decoded trial: fixed, or the longest that fits the pool.
  double Duration(const model::TrialDesign& d) const {
    if (o_.fixed_duration_s > 0) return o_.fixed_duration_s;
    if (!std::isfinite(ctx_.available())) return t_max_;
    const auto input = model::MakeExcitation(ctx_.vehicle(), d);
    return FirstOverflow(ctx_, *tm_->model, tm_->design_thetas, *input, t_max_);
  }

  bool resolvable() const { return objective_.Resolvable(); }

  int num_constraints() const {
    return 1 + (o_.fixed_duration_s > 0 && std::isfinite(ctx_.available()) ? 1 : 0);
  }

  bool Evaluate(const double* x, double* phi, double* g) const {
    model::TrialDesign d = Decode(x);
    d.duration = Duration(d);
    if (!(d.duration > 0)) return false;
    const auto input = model::MakeExcitation(ctx_.vehicle(), d);
    // g0: at least min_periods periods, scaled by the longest trial.
    g[0] = (o_.min_periods * 2 * M_PI / d.omega - d.duration) / t_max_;
    const double span = objective_.Criteria(*tm_, *input, d.duration, phi);
    if (num_constraints() > 1) g[1] = objective_.TravelExcess(span);
    return true;
  }

  std::vector<double> Start() const {
    // Ref 000 eq. 14-15: mid-range offset, the largest amplitude without reversal, ω_opt at
    // the box centre for that force.
    const double mid = 0.5 * (c_.range.min_abs + c_.range.max_abs);
    const auto& th = ctx_.design_thetas().front();
    const int ik = ctx_.Index(model::param::kLinearDrag),
              iq = ctx_.Index(model::param::kQuadraticDrag);
    const double k = ik >= 0 ? th[ik] : 0.0, kq = iq >= 0 ? th[iq] : 0.0;
    const double kl = LinearisedDrag(k, kq, SteadySpeed(k, kq, mid));
    const std::array<double, 2>& range = objective_.omega_range();
    const double w = kl > 0 ? DOptimalSineFrequency(TimeConstant(th[0], kl)) : range[0];
    const double v = std::clamp(std::log(w / range[0]) / std::log(range[1] / range[0]), 0.0, 1.0);
    return {0.5, 1.0, v};
  }

 private:
  const DofPlanningProblem& ctx_;
  const SineDesignOptions& o_;
  SineFamilyObjective objective_;
  Candidate c_;
  double t_max_;
  const DofPlanningProblem::TrialModel* tm_ = nullptr;
};

// Ref 000 eq. 14's ω_opt = 1/(√3·t_c), t_c = m/k_L (eq. 13) at a force level, over the box's
// design points, widened to [ω_min/4, 4·ω_max].
std::array<double, 2> OptimalFrequencyRange(const DofPlanningProblem& ctx, double force_abs) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0.0;
  const int ik = ctx.Index(model::param::kLinearDrag), iq = ctx.Index(model::param::kQuadraticDrag);
  for (const auto& th : ctx.design_thetas()) {
    const double k = ik >= 0 ? th[ik] : 0.0, kq = iq >= 0 ? th[iq] : 0.0;
    const double kl = LinearisedDrag(k, kq, SteadySpeed(k, kq, force_abs));
    if (!(kl > 0)) continue;
    const double w = DOptimalSineFrequency(TimeConstant(th[0], kl));
    lo = std::min(lo, w);
    hi = std::max(hi, w);
  }
  if (!std::isfinite(lo)) return {0.01, 10.0};
  return {lo / 4.0, hi * 4.0};
}

}  // namespace

std::array<double, 2> SineFrequencyRange(const DofPlanningProblem& ctx, double force_abs,
                                         double min_periods, double duration, int harmonics) {
  std::array<double, 2> w = OptimalFrequencyRange(ctx, force_abs);
  if (min_periods > 0) w[0] = std::max(w[0], 2 * M_PI * min_periods / duration);
  if (w[1] <= w[0]) w[1] = 2.0 * w[0];
  const double period = ctx.ShortestPeriod();
  if (period > 0 && harmonics > 0) w[1] = std::min(w[1], 2 * M_PI / (period * harmonics));
  return w;
}

double LongestFittingDuration(const DofPlanningProblem& ctx, const model::TrialDesign& design,
                              double t_max) {
  if (!std::isfinite(ctx.available())) return t_max;
  const auto input = model::MakeExcitation(ctx.vehicle(), design);
  const DofPlanningProblem::TrialModel& tm = ctx.ModelFor(design);
  return FirstOverflow(ctx, *tm.model, tm.check_thetas, *input, t_max);
}

namespace {

model::Direction DirectionOf(int sign) {
  return sign > 0 ? model::Direction::kPos : model::Direction::kNeg;
}

// Mirror images: the standard model is odd in xi and phi (k·xi + kq·xi|xi|), so with no bias
// and eta = 1 an open-water direction whose force range equals an earlier open-water
// candidate's opposite direction has the same information; it is not designed twice.
bool IsMirror(const DofPlanningProblem& ctx, const std::vector<Candidate>& earlier,
              const Candidate& c) {
  const auto& v = ctx.vehicle();
  bool mirror = false;
  for (const Candidate& e : earlier) {
    mirror = mirror || (e.sign == -c.sign && std::abs(e.range.min_abs - c.range.min_abs) < 1e-9 &&
                        std::abs(e.range.max_abs - c.range.max_abs) < 1e-9 &&
                        v.mappings[e.mapping].IsOpenWater(DirectionOf(e.sign)));
  }
  const int ib = ctx.Index(model::param::kBias);
  for (const auto& th : ctx.design_thetas()) mirror = mirror && (ib < 0 || th[ib] == 0.0);
  return mirror && v.mappings[c.mapping].IsOpenWater(DirectionOf(c.sign));
}

// The (mapping, direction) pairs that can hold a sine without reversal, as the options allow;
// why others cannot goes to `notes`.
std::vector<Candidate> SineCandidates(const DofPlanningProblem& ctx, const SineDesignOptions& o,
                                      std::vector<std::string>* notes) {
  const auto& v = ctx.vehicle();
  std::vector<Candidate> candidates;
  for (int mi : v.MappingsOf(ctx.dof())) {
    const auto& m = v.mappings[mi];
    if (!o.mappings.empty() &&
        std::find(o.mappings.begin(), o.mappings.end(), m.name) == o.mappings.end()) {
      continue;
    }
    for (int s : {+1, -1}) {
      if (o.sign != 0 && s != o.sign) continue;
      if (o.open_water_only && !m.IsOpenWater(DirectionOf(s))) continue;
      Candidate c{mi, s, ctx.ForceRangeFor(mi, s)};
      if (!c.range.feasible) {
        notes->push_back(c.range.reason);
        continue;
      }
      if (IsMirror(ctx, candidates, c)) {
        notes->push_back(m.name + (s > 0 ? " +" : " -") +
                         ": mirror image of a candidate already designed (same force "
                         "range, no bias, open water): same information, not repeated");
        continue;
      }
      candidates.push_back(c);
    }
  }
  return candidates;
}

// The best sine over every candidate (robust criterion); false if no candidate gave one.
bool OptimiseSine(const DofPlanningProblem& ctx, const SineDesignOptions& o,
                  const std::vector<Eigen::MatrixXd>& prior,
                  const std::vector<Candidate>& candidates, double t_max, const std::string& id,
                  SineDesignResult* result) {
  const int J = static_cast<int>(ctx.design_thetas().size());
  double best = -std::numeric_limits<double>::infinity();
  for (const Candidate& c : candidates) {
    SineProblem sp(ctx, o, prior, c, t_max);
    if (!sp.resolvable()) {
      result->notes.push_back(
          ctx.vehicle().mappings[c.mapping].name + (c.sign > 0 ? " +" : " -") +
          ": the sensors resolve no wave of " + model::Significant(o.min_periods, 3) +
          " periods in " +
          model::Significant(o.fixed_duration_s > 0 ? o.fixed_duration_s : t_max, 4) + " s (" +
          model::Significant(ctx.options().samples_per_period, 3) + " samples per period)");
      continue;
    }
    DesignProblem p;
    p.num_variables = 3;
    p.lower = {0.0, 0.0, 0.0};
    p.upper = {1.0, 1.0, 1.0};
    p.x0 = sp.Start();
    p.num_scenarios = J;
    p.num_constraints = sp.num_constraints();
    p.evaluate = [&sp](const double* x, double* phi, double* g) { return sp.Evaluate(x, phi, g); };
    SolverOptions so = ctx.options().solver;
    so.robustness = ctx.options().robustness;
    so.extra_starts.push_back(p.x0);
    const SolverSummary summary = Solve(ctx.options().sine_backend, p, so);
    if (!summary.is_success()) {
      result->notes.push_back(ctx.vehicle().mappings[c.mapping].name + (c.sign > 0 ? " +" : " -") +
                              ": " + summary.BriefReport());
    }
    if (!summary.is_success() || summary.objective <= best) continue;
    best = summary.objective;
    result->summary = summary;
    result->criterion = summary.objective;
    result->criterion_per_point = summary.phi;
    model::TrialDesign d = sp.Decode(summary.x.data());
    d.id = id;
    d.duration = sp.Duration(d);
    result->trial.design = d;
  }
  return std::isfinite(best);
}

// A "sine" whose amplitude vanishes is a steady run from rest: the force range left between
// min_thrust and the speed limit is too narrow for a swing that adds more than the start from
// rest does (VSOR yaw: [3.11, 4.25] N·m). Report it as what it is, and say why.
void PlanFlatSineAsSteady(const DofPlanningProblem& ctx, SineDesignResult* result) {
  model::TrialDesign& d = result->trial.design;
  if (d.amplitude > 1e-3 * std::abs(d.offset)) return;
  const ForceRange range =
      ctx.ForceRangeFor(ctx.vehicle().MappingIndex(d.mapping), d.offset > 0 ? 1 : -1);
  std::ostringstream s;
  const std::string unit(model::ForceUnit(d.dof));
  s << d.mapping << ": the best sine has no amplitude — a steady run from rest at "
    << model::Significant(d.offset, 4) << " " << unit << " for "
    << model::Significant(d.duration, 4)
    << " s carries more information than any swing within the force range ["
    << model::Significant(range.min_abs, 4) << ", " << model::Significant(range.max_abs, 4) << "] "
    << unit
    << " that min_thrust and the speed limit leave; planned as that steady run (a wider "
       "range — lower min_thrust, a larger max_rotation_rate / max_translation_speed — would "
       "allow a true sine)";
  result->notes.push_back(s.str());
  d.kind = model::TrialKind::kSteady;
  d.force = d.offset;
  d.offset = d.amplitude = d.omega = 0.0;
  const std::string suffix = "-sine";
  if (d.id.size() > suffix.size() && model::EndsWith(d.id, suffix)) {
    d.id = d.id.substr(0, d.id.size() - suffix.size()) + "-long-steady";
  }
}

// The reported information and criterion: the real sensors (design_sensors() approximates).
void Score(const DofPlanningProblem& ctx, const SineDesignOptions& o,
           const std::vector<Eigen::MatrixXd>& prior, SineDesignResult* result) {
  result->information = ctx.Information(result->trial.design);
  result->criterion_per_point = ctx.CriterionValues(WithPrior(result->information, prior),
                                                    o.criterion, ctx.Indices(o.interest));
  result->criterion = Aggregate(ctx.options().robustness, result->criterion_per_point);
}

// A sine shortened to fit the check grid, with fewer than min_periods periods left: ω raised
// until they fit the duration that fits at that ω (the fixed point of ω = 2π·min_periods /
// T_fit(ω), reached by iterating it: T_fit changes little with ω — measured elasticity 0.16 —
// as the travel is mostly the offset's drift). Bounded by the sensors' shortest period; a wave
// that still has too few periods is left for SetStatus to refuse.
void RestoreLeastPeriods(const DofPlanningProblem& ctx, const SineDesignOptions& o,
                         model::TrialDesign* d) {
  const double longest = d->duration;
  const double period = ctx.ShortestPeriod();
  const double omega_max = period > 0 ? 2 * M_PI / period : std::numeric_limits<double>::infinity();
  for (int step = 0; step < 8 && d->duration < o.min_periods * 2 * M_PI / d->omega; ++step) {
    const double omega = o.min_periods * 2 * M_PI / d->duration * (1.0 + 1e-4);
    if (omega > omega_max) return;
    d->omega = omega;
    d->duration = LongestFittingDuration(ctx, *d, longest) * (1.0 - 1e-6);
  }
}

// Hard constraints over the check grid; the design points bound the travel when it is
// monotone in m and drag, else shorten the trial until the check grid fits too.
void CheckAndFit(const DofPlanningProblem& ctx, const SineDesignOptions& o,
                 const std::vector<Eigen::MatrixXd>& prior, SineDesignResult* result) {
  model::TrialDesign& d = result->trial.design;
  result->check = ctx.Check(d);
  if (!result->check.feasible && o.fixed_duration_s == 0 && std::isfinite(ctx.available()) &&
      result->check.span > ctx.available()) {
    d.duration = LongestFittingDuration(ctx, d, d.duration) * (1.0 - 1e-6);
    if (d.kind == model::TrialKind::kSine) RestoreLeastPeriods(ctx, o, &d);
    result->check = ctx.Check(d);
    Score(ctx, o, prior, result);
  }
  result->trial.travel = result->check.travel;
  result->trial.thrust_min = result->check.thrust_min;
}

void SetStatus(const DofPlanningProblem& ctx, const SineDesignOptions& o,
               const std::vector<Eigen::MatrixXd>& prior, SineDesignResult* result) {
  const model::TrialDesign& d = result->trial.design;
  bool singular = false;
  ctx.CriterionValues(WithPrior(result->information, prior), o.criterion, ctx.Indices(o.interest),
                      &singular);
  if (!result->check.feasible) {
    result->status = DesignStatus::kInfeasible;
    std::ostringstream s;
    s << "the best sine design violates a hard constraint:";
    for (const auto& r : result->check.reasons) s << " " << r << ";";
    result->message = s.str();
  } else if (singular) {
    result->status = DesignStatus::kInfeasible;
    result->message =
        "the information of this trial (with the prior) is singular: its parameters cannot all "
        "be told apart (add steady runs in other mappings, or prior information on eta)";
  } else if (d.kind == model::TrialKind::kSine &&
             d.duration < o.min_periods * 2 * M_PI / d.omega - 1e-6) {
    result->status = DesignStatus::kInfeasible;
    std::ostringstream s;
    s << "only " << d.duration * d.omega / (2 * M_PI) << " periods fit the pool (at least "
      << o.min_periods << " wanted)";
    result->message = s.str();
  } else {
    result->status = DesignStatus::kOk;
  }
}

}  // namespace

SineDesignResult DesignSine(const DofPlanningProblem& ctx, const SineDesignOptions& o,
                            const std::vector<Eigen::MatrixXd>& prior, const std::string& id) {
  SineDesignResult result;
  std::string error;
  if (!o.IsValid(&error) || !ctx.options().IsValid(&error)) {
    result.message = error;
    return result;
  }
  const double t_max = o.max_duration_s > 0
                           ? std::min(o.max_duration_s, ctx.options().max_trial_duration_s)
                           : ctx.options().max_trial_duration_s;
  if (o.fixed_duration_s > ctx.options().max_trial_duration_s) {
    result.status = DesignStatus::kInfeasible;
    result.message = "fixed duration beyond the trial duration limit";
    return result;
  }
  const std::vector<Candidate> candidates = SineCandidates(ctx, o, &result.notes);
  if (candidates.empty()) {
    result.status = DesignStatus::kInfeasible;
    result.message = std::string("no mapping and direction of ") +
                     std::string(model::DofName(ctx.dof())) +
                     " can hold a sine without propeller reversal" +
                     (o.open_water_only ? " in open water" : "") +
                     (result.notes.empty() ? "" : " within the speed limit (see the notes)");
    return result;
  }
  if (!OptimiseSine(ctx, o, prior, candidates, t_max, id, &result)) {
    result.status = DesignStatus::kFailed;
    result.message = "no candidate mapping gave a feasible sine design";
    return result;
  }
  PlanFlatSineAsSteady(ctx, &result);
  Score(ctx, o, prior, &result);
  CheckAndFit(ctx, o, prior, &result);
  SetStatus(ctx, o, prior, &result);
  return result;
}

}  // namespace uuvplan::planner
