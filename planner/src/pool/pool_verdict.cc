// The one feasibility verdict (pool_verdict.h).
#include "uuvplan/planner/pool/pool_verdict.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "design/travel_margin.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/util/numbers.h"
#include "uuvplan/model/util/parallel.h"

namespace uuvplan::planner {
namespace {

using model::kInf;

constexpr model::EnumNames<PoolLimit, 10> kLimitNames{
    {{{PoolLimit::kNone, "none"},
      {PoolLimit::kLength, "length"},
      {PoolLimit::kWidth, "width"},
      {PoolLimit::kDepth, "depth"},
      {PoolLimit::kTether, "tether"},
      {PoolLimit::kThrust, "thrust range"},
      {PoolLimit::kNoReversal, "no reversal"},
      {PoolLimit::kDuration, "duration"},
      {PoolLimit::kInformation, "information"},
      {PoolLimit::kRotationRate, "rotation rate"}}}};

constexpr model::EnumNames<Hostability, 3> kHostabilityNames{
    {{{Hostability::kAll, "all"}, {Hostability::kPart, "part"}, {Hostability::kNone, "none"}}}};

PoolLimit SpaceLimit(model::Dof dof) {
  switch (dof) {
    case model::Dof::kSurge:
      return PoolLimit::kLength;
    case model::Dof::kSway:
      return PoolLimit::kWidth;
    case model::Dof::kHeave:
      return PoolLimit::kDepth;
    default:
      return PoolLimit::kTether;
  }
}

bool Has(const std::string& s, const char* what) { return s.find(what) != std::string::npos; }

// The limit the planner's own message names (DofPlan::message: the designs say what stops
// them in words only).
PoolLimit LimitOfMessage(model::Dof dof, const std::string& text) {
  if (Has(text, "travel") || Has(text, "rotation ")) return SpaceLimit(dof);
  if (Has(text, "reverses")) return PoolLimit::kNoReversal;
  if (Has(text, "min_thrust") || Has(text, "speed limit") || Has(text, "thrust")) {
    return PoolLimit::kThrust;
  }
  if (Has(text, "duration") || Has(text, "trial limit") || Has(text, "settle")) {
    return PoolLimit::kDuration;
  }
  return PoolLimit::kInformation;
}

// The limit a given plan's trial check names (DofPlanningProblem::Check), the pool's space first.
PoolLimit LimitOfCheck(model::Dof dof, const TrialCheck& check) {
  if (check.exceeds_travel) return SpaceLimit(dof);
  if (check.reversal) return PoolLimit::kNoReversal;
  if (check.thrust_out_of_range) return PoolLimit::kThrust;
  if (check.exceeds_duration) return PoolLimit::kDuration;
  return PoolLimit::kInformation;
}

// The pool with `free` of free travel along `dof` (a larger side, or more turns).
model::Pool Offering(const model::Pool& pool, model::Dof dof, double free) {
  model::Pool p = pool;
  p.name = pool.name + "-enlarged";
  const double wall = pool.WallToWallFor(free + kLargestTravelMargin);
  switch (dof) {
    case model::Dof::kSurge:
      p.length = std::max(p.length, wall);
      break;
    case model::Dof::kSway:
      p.width = std::max(p.width, wall);
      break;
    case model::Dof::kHeave:
      p.depth = std::max(p.depth, wall);
      break;
    default:
      p.max_turns = std::max(p.max_turns, (free + kLargestTravelMargin) / (2 * M_PI));
  }
  return p;
}

// The need of a DOF the pool's space limits, confirmed by planning it in a pool offering it,
// then the smallest such pool by bisection between this pool's free travel (not hosted) and
// the confirmed one: the planner fills the room it is given, so the first pool that hosts it
// is no minimum (a 1.8 m pool was told 5.6 m where 3 m hosts). Each probe is a PlanSchedule;
// the answer is always a pool that was planned and hosts the DOF: the free travel offered, not
// the span its trials used (up to the planner's 5 mm safety more; a pool that much larger is
// planned anew and, near the target's reach, need not host: payload60 surge, 21.2% per trial
// against 20.7% needed).
void ConfirmNeed(const model::Vehicle& vehicle, const model::Pool& pool,
                 const ScheduleOptions& options, const VerdictOptions& vo, DofVerdict* v) {
  ScheduleOptions so = options;
  so.dofs = {v->dof};
  const auto plan_offering = [&](double free) {
    return PlanSchedule(vehicle, Offering(pool, v->dof, free), so);
  };
  double hi = kInf;
  for (int i = 0; i <= vo.need_checks && !std::isfinite(hi); ++i) {
    const ScheduleResult r = plan_offering(v->need);
    if (r.status == PlanStatus::kOk) {
      hi = v->need;
    } else if (i < vo.need_checks) {
      v->need *= 1.5;
    }
  }
  if (!std::isfinite(hi)) return;
  v->need_verified = true;
  double lo = std::isfinite(pool.FreeTravel(v->dof)) ? pool.FreeTravel(v->dof) : 0.0;
  for (int i = 0; i < vo.need_bisections && hi - lo > vo.need_tolerance * hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    const ScheduleResult r = plan_offering(mid);
    if (r.status == PlanStatus::kOk) {
      hi = mid;
    } else {
      lo = mid;
    }
  }
  v->need = hi;
  v->need_refuted = lo;
  v->need_searched = vo.need_bisections > 0;
}

// Which of `points` a schedule planned there as a known vehicle hosts.
std::vector<char> HostedPoints(const model::Vehicle& vehicle, const model::Pool& pool,
                               const ScheduleOptions& so, model::Dof dof,
                               const std::vector<BoxPoint>& points) {
  std::vector<char> hosted(points.size(), 0);  // each point on its own (PlannerOptions::threads)
  model::ParallelFor(points.size(), so.planner.Threads(), [&](std::size_t i) {
    hosted[i] =
        PlanSchedule(VehicleAt(vehicle, dof, points[i]), pool, so).status == PlanStatus::kOk;
  });
  return hosted;
}

// A DOF not hosted over the whole box, planned again at the box's centre and corners
// (box_points.h): hosted at some, it is hosted for part of the box (the first trials decide).
// Hosted at none, the points are planned once more with each trial's start known, an upper
// bound of the information (fisher_information.h): "none" is claimed only when even that hosts
// no point. The loop re-plans at its estimates, so its trials can do better than the a priori
// schedule judged here; without the bound, four pools of loop_validation's 54 were judged
// "none" (`loop` refuses) where the loop converges (docs/planning.md, "Initial state").
void JudgePoints(const model::Vehicle& vehicle, const model::Pool& pool,
                 const ScheduleOptions& options, DofVerdict* v) {
  ScheduleOptions so = options;
  so.dofs = {v->dof};
  const std::vector<BoxPoint> points = VerdictPoints(vehicle, v->dof, options.planner.box);
  std::vector<char> hosted = HostedPoints(vehicle, pool, so, v->dof, points);
  const bool none = std::none_of(hosted.begin(), hosted.end(), [](char h) { return h != 0; });
  if (none && !points.empty() && !options.planner.start_known) {
    so.planner.start_known = true;
    hosted = HostedPoints(vehicle, pool, so, v->dof, points);
    v->points_start_known = true;
  }
  for (std::size_t i = 0; i < points.size(); ++i) {
    v->points.push_back({points[i], hosted[i] != 0});
    if (hosted[i]) v->hostability = Hostability::kPart;
  }
}

// The pool's hostability: all when every DOF is hosted, none when one is hosted nowhere.
Hostability Overall(const std::vector<DofVerdict>& dofs) {
  if (dofs.empty()) return Hostability::kNone;
  Hostability h = Hostability::kAll;
  for (const auto& d : dofs) {
    if (d.hostability == Hostability::kNone) return Hostability::kNone;
    if (d.hostability == Hostability::kPart) h = Hostability::kPart;
  }
  return h;
}

// The verdict of one DOF from the planner's own plan of it in this pool.
DofVerdict JudgeOwn(const DofPlan& p, const model::Pool& pool) {
  DofVerdict v;
  v.dof = p.dof;
  v.determinacy = p.determinacy;
  v.reach = p.reach;
  for (const auto& t : p.trials) v.extent = std::max(v.extent, t.travel[1] - t.travel[0]);
  v.hosted = p.status == DesignStatus::kOk && p.complete;
  v.need = v.extent;
  if (v.hosted) {
    v.hostability = Hostability::kAll;
    return v;
  }
  v.message = p.message;
  const double free = pool.FreeTravel(p.dof);
  v.below_target = p.determinacy.determined && !p.reach.reached;
  if (v.below_target) {
    // Longer runs and swings inform the drag more: a larger pool, confirmed by planning
    // (ConfirmNeed); else the loop's own stuck limits (BelowTargetUnlifted).
    v.limit = SpaceLimit(p.dof);
    v.need = std::max(v.extent, std::isfinite(free) ? free : v.extent) * 1.5;
    return v;
  }
  const double asked = std::isfinite(p.required_travel) ? p.required_travel : free;
  bool space_note = Has(p.message, "travels");
  for (const auto& n : p.notes) space_note = space_note || Has(n, "travels");
  if (space_note) {
    v.limit = SpaceLimit(p.dof);
    v.need = std::max({v.extent, asked, free});
  } else {
    v.limit = LimitOfMessage(p.dof, p.message);
    const bool space = v.limit == SpaceLimit(p.dof) || v.limit == PoolLimit::kInformation;
    // Trials that fit but do not determine: more room gives longer runs and swings.
    v.need = space ? std::max(v.extent, std::isfinite(free) ? free : v.extent) * 1.5 : kInf;
  }
  return v;
}

// A DOF short of the target that no larger pool planned lifts: the loop's stuck rule names
// what is left (stuck_limit.cc): the rotation-rate limit of a rotation, the no-reversal
// limit of a translation (its drag seen over one speed range per direction).
void BelowTargetUnlifted(DofVerdict* v) {
  if (!v->below_target || v->need_verified) return;
  v->unlifted = true;
  v->unlifted_travel = v->need;
  v->limit = model::IsRotational(v->dof) ? PoolLimit::kRotationRate : PoolLimit::kNoReversal;
  v->need = kInf;
}

// A given plan's trials of `v.dof`: each must pass DofPlanningProblem::Check in this pool. False
// when one fails (the failing checks are the verdict's plan_checks).
bool JudgePlanTrials(const std::vector<TrialPoolCheck>& checks, DofVerdict* v) {
  bool fits = true;
  for (const auto& c : checks) {
    if (c.dof != v->dof) continue;
    v->extent = std::max(v->extent, c.check.span);  // the plan's own need (Required); `need`
                                                    // stays the planner's, searched as without it
    if (c.check.feasible) continue;
    fits = false;
    if (v->hosted || v->limit == PoolLimit::kNone) v->limit = LimitOfCheck(v->dof, c.check);
    v->hosted = false;
    v->hostability = Hostability::kNone;
    if (v->limit != SpaceLimit(v->dof)) v->need = kInf;
  }
  return fits;
}

RequiredPool Required(const model::Pool& pool, const std::vector<DofVerdict>& dofs) {
  double free[model::kNumDofs] = {0, 0, 0, 0, 0, 0};
  RequiredPool r;
  for (const auto& d : dofs) {
    double& f = free[model::Index(d.dof)];
    f = std::max({f, d.extent, std::isfinite(d.need) ? d.need : 0.0});
    if (!std::isfinite(d.need)) r.exists = false;
  }
  r.length = pool.WallToWallFor(free[model::Index(model::Dof::kSurge)]);
  r.width = pool.WallToWallFor(free[model::Index(model::Dof::kSway)]);
  r.depth = pool.WallToWallFor(free[model::Index(model::Dof::kHeave)]);
  for (model::Dof d : {model::Dof::kRoll, model::Dof::kPitch, model::Dof::kYaw}) {
    r.turns = std::max(r.turns, pool.ExtentFor(d, free[model::Index(d)]));
  }
  return r;
}

}  // namespace

std::string_view PoolLimitName(PoolLimit limit) { return kLimitNames.Name(limit); }

std::string_view HostabilityName(Hostability h) { return kHostabilityNames.Name(h); }

PoolVerdict JudgePool(const model::Vehicle& vehicle, const model::Pool& pool,
                      const ScheduleOptions& options, const ScheduleResult& own,
                      const Schedule* plan, const VerdictOptions& vo) {
  if (plan == nullptr) return JudgePoolOnChecks(vehicle, pool, options, own, nullptr, vo);
  PoolCheckOptions pco;
  pco.schedule = options;
  pco.plan_alternative = false;
  const std::vector<TrialPoolCheck> checks = CheckPool(vehicle, pool, *plan, pco).trials;
  return JudgePoolOnChecks(vehicle, pool, options, own, &checks, vo);
}

PoolVerdict JudgePoolOnChecks(const model::Vehicle& vehicle, const model::Pool& pool,
                              const ScheduleOptions& options, const ScheduleResult& own,
                              const std::vector<TrialPoolCheck>* plan_checks,
                              const VerdictOptions& vo) {
  PoolVerdict out;
  out.goal = options.precision;
  out.plan_given = plan_checks != nullptr;
  if (plan_checks != nullptr) out.plan_checks = *plan_checks;
  out.hosted = !own.dofs.empty();
  for (const auto& p : own.dofs) {
    const auto m = vehicle.models.find(p.dof);
    if (m == vehicle.models.end() || !m->second.identified()) continue;
    out.identified_box = true;
    out.derived_box = out.derived_box || !m->second.origin.empty();
  }
  std::vector<char> plan_fits;
  std::vector<std::size_t> not_hosted;
  for (const auto& p : own.dofs) {
    DofVerdict& v = out.dofs.emplace_back(JudgeOwn(p, pool));
    const bool own_hosted = v.hosted;
    plan_fits.push_back(JudgePlanTrials(out.plan_checks, &v));
    v.only_plan_fails = own_hosted && !v.hosted;
    if (!v.hosted) not_hosted.push_back(out.dofs.size() - 1);
  }
  // The DOFs not hosted, each searched on its own (PlannerOptions::threads, only those: one
  // left alone plans its trials' families on both cores; each writes only its verdict, so the
  // answer does not depend on the threads).
  model::ParallelFor(not_hosted.size(), options.planner.Threads(), [&](std::size_t k) {
    const std::size_t i = not_hosted[k];
    DofVerdict& v = out.dofs[i];
    // Only a given plan's trials failing: no larger pool to search for the planner (the
    // plan's own need is its travel, Required).
    if (!v.only_plan_fails && std::isfinite(v.need) && vo.need_checks >= 0) {
      ConfirmNeed(vehicle, pool, options, vo, &v);
      BelowTargetUnlifted(&v);
    }
    // A given plan that fails its own checks is judged as given: no other point rescues it.
    if (vo.judge_points && plan_fits[i]) JudgePoints(vehicle, pool, options, &v);
  });
  for (const DofVerdict& v : out.dofs) out.hosted = out.hosted && v.hosted;
  out.required = Required(pool, out.dofs);
  out.hostability = Overall(out.dofs);
  if (own.dofs.empty()) out.unplanned = own.message;
  return out;
}

PoolVerdict JudgePool(const model::Vehicle& vehicle, const model::Pool& pool,
                      const ScheduleOptions& options, const Schedule* plan,
                      const VerdictOptions& vo) {
  return JudgePool(vehicle, pool, options, PlanSchedule(vehicle, pool, options), plan, vo);
}

void ReadLoopEnd(const PoolVerdict& verdict, LoopResult* result) {
  if (verdict.hostability != Hostability::kPart || result->status != LoopStatus::kStuck) return;
  std::vector<model::Dof> outside;
  for (const auto& p : result->progress) {
    if (p.converged) continue;
    for (const auto& d : verdict.dofs) {
      if (d.dof == p.dof && d.hostability == Hostability::kPart) outside.push_back(p.dof);
    }
  }
  if (outside.empty()) return;
  result->status = LoopStatus::kInfeasible;
  result->outside_part = outside;
}

}  // namespace uuvplan::planner
