// The one feasibility verdict (pool_verdict.h).
#include "uuvplan/planner/pool/pool_verdict.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "design/travel_margin.h"
#include "format.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/util/parallel.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::planner {
namespace {

using internal::Fmt;
constexpr double kInf = std::numeric_limits<double>::infinity();

constexpr model::EnumNames<PoolLimit, 10> kLimitNames{{{
    {PoolLimit::kNone, "none"}, {PoolLimit::kLength, "length"}, {PoolLimit::kWidth, "width"},
    {PoolLimit::kDepth, "depth"}, {PoolLimit::kTether, "tether"},
    {PoolLimit::kThrust, "thrust range"}, {PoolLimit::kNoReversal, "no reversal"},
    {PoolLimit::kDuration, "duration"}, {PoolLimit::kInformation, "information"},
    {PoolLimit::kRotationRate, "rotation rate"}}}};

constexpr model::EnumNames<Hostability, 3> kHostabilityNames{{{
    {Hostability::kAll, "all"}, {Hostability::kPart, "part"}, {Hostability::kNone, "none"}}}};

PoolLimit SpaceLimit(model::Dof dof) {
  switch (dof) {
    case model::Dof::kSurge: return PoolLimit::kLength;
    case model::Dof::kSway: return PoolLimit::kWidth;
    case model::Dof::kHeave: return PoolLimit::kDepth;
    default: return PoolLimit::kTether;
  }
}

bool Has(const std::string& s, const char* what) { return s.find(what) != std::string::npos; }

// The limit a failure text names (the planner's own messages, DofContext::Check's reasons).
PoolLimit LimitOfText(model::Dof dof, const std::string& text) {
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

// The pool with `free` of free travel along `dof` (a larger side, or more turns).
model::Pool Offering(const model::Pool& pool, model::Dof dof, double free) {
  model::Pool p = pool;
  p.name = pool.name + "-enlarged";
  const double wall = pool.WallToWallFor(free + kLargestTravelMargin);
  switch (dof) {
    case model::Dof::kSurge: p.length = std::max(p.length, wall); break;
    case model::Dof::kSway: p.width = std::max(p.width, wall); break;
    case model::Dof::kHeave: p.depth = std::max(p.depth, wall); break;
    default: p.max_turns = std::max(p.max_turns, (free + kLargestTravelMargin) / (2 * M_PI));
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
    hosted[i] = PlanSchedule(VehicleAt(vehicle, dof, points[i]), pool, so).status ==
                PlanStatus::kOk;
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
DofVerdict JudgeOwn(const DofPlan* p, model::Dof dof, const model::Pool& pool) {
  DofVerdict v;
  v.dof = dof;
  if (p == nullptr) {
    v.limit = PoolLimit::kInformation;
    v.reason = std::string(model::DofName(dof)) + " was not planned";
    v.need = kInf;
    return v;
  }
  v.determinacy = p->determinacy;
  v.reach = p->reach;
  for (const auto& t : p->trials) v.extent = std::max(v.extent, t.travel[1] - t.travel[0]);
  v.hosted = p->status == DesignStatus::kOk && p->complete;
  v.need = v.extent;
  if (v.hosted) {
    v.hostability = Hostability::kAll;
    return v;
  }
  v.reason = p->message;
  const double free = pool.FreeTravel(dof);
  v.below_target = p->determinacy.determined && !p->reach.reached;
  if (v.below_target) {
    // Longer runs and swings inform the drag more: a larger pool, confirmed by planning
    // (ConfirmNeed); else the loop's own stuck limits (BelowTargetUnlifted).
    v.limit = SpaceLimit(dof);
    v.need = std::max(v.extent, std::isfinite(free) ? free : v.extent) * 1.5;
    return v;
  }
  const double asked = std::isfinite(p->required_travel) ? p->required_travel : free;
  bool space_note = Has(p->message, "travels");
  for (const auto& n : p->notes) space_note = space_note || Has(n, "travels");
  if (space_note) {
    v.limit = SpaceLimit(dof);
    v.need = std::max({v.extent, asked, free});
  } else {
    v.limit = LimitOfText(dof, p->message);
    const bool space = v.limit == SpaceLimit(dof) || v.limit == PoolLimit::kInformation;
    // Trials that fit but do not determine: more room gives longer runs and swings.
    v.need = space ? std::max(v.extent, std::isfinite(free) ? free : v.extent) * 1.5 : kInf;
  }
  return v;
}

// "9.66 m of free depth (12.66 m wall to wall)" or "1080° (3 turns)" (angles for people in
// degrees, docs/cli.md).
std::string Travel(const model::Pool& pool, model::Dof dof, double free) {
  std::ostringstream s;
  if (model::IsRotational(dof)) {
    s << model::AngleText(free);
  } else {
    s << Fmt(free, 4) << " m of free " << model::Pool::SideName(dof) << " ("
      << Fmt(pool.WallToWallFor(free), 4) << " m wall to wall)";
  }
  return s.str();
}

// A DOF short of the target that no larger pool planned lifts: the loop's stuck rule names
// what is left (stuck_limit.cc): the rotation-rate limit of a rotation, the no-reversal
// limit of a translation (its drag seen over one speed range per direction).
void BelowTargetUnlifted(const model::Pool& pool, DofVerdict* v) {
  if (!v->below_target || v->need_verified) return;
  const std::string tried = Travel(pool, v->dof, v->need);
  v->limit = model::IsRotational(v->dof) ? PoolLimit::kRotationRate : PoolLimit::kNoReversal;
  v->need = kInf;
  v->reason += " A pool offering " + tried + " does not lift it either: " +
               (model::IsRotational(v->dof)
                    ? "the designs keep below the rotation-rate limit, where the drag hardly acts"
                    : "the trials never reverse a thruster, so the drag is seen over one speed "
                      "range per direction") +
               ".";
}

// A given plan's trials of `v.dof`: each must pass DofContext::Check in this pool. False when
// one fails.
bool JudgePlanTrials(const std::vector<TrialPoolCheck>& checks, DofVerdict* v) {
  bool fits = true;
  for (const auto& c : checks) {
    if (c.dof != v->dof) continue;
    v->extent = std::max(v->extent, c.check.span);  // the plan's own need (Required); `need`
                                                    // stays the planner's, searched as without it
    if (c.check.feasible) continue;
    fits = false;
    const std::string why = model::Join(c.check.reasons, "; ");
    if (v->hosted || v->limit == PoolLimit::kNone) v->limit = LimitOfText(v->dof, why);
    v->hosted = false;
    v->hostability = Hostability::kNone;
    v->reason += (v->reason.empty() ? "" : " ") + std::string("plan trial '") + c.id + "': " + why;
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

std::string DofList(const std::vector<DofVerdict>& dofs, Hostability h) {
  std::vector<std::string> names;
  for (const auto& d : dofs) {
    if (d.hostability == h) names.emplace_back(model::DofName(d.dof));
  }
  return model::Join(names);
}

// " to 5% (every parameter of interest's 100·σ/|θ|)": the precision judged at.
std::string Goal(const PoolVerdict& v) {
  return " to " + Fmt(v.goal.target_percent) + "% (every parameter of interest's 100·σ/|θ|)";
}

// "Pool P CAN host …", "… can host … for PART of the a priori box …", "… CANNOT host …".
std::string Sentence(const PoolVerdict& v, const model::Pool& pool) {
  std::ostringstream s;
  s << "Pool " << pool.name;
  switch (v.hostability) {
    case Hostability::kAll:
      s << " CAN host the identification of " << DofList(v.dofs, Hostability::kAll) << Goal(v);
      break;
    case Hostability::kPart:
      s << " can host the identification of " << DofList(v.dofs, Hostability::kPart) << Goal(v)
        << " for PART of the a priori box only (the first trials decide: `loop` and `next` run "
           "and stop when the estimates fall outside it)";
      break;
    case Hostability::kNone:
      s << " CANNOT host the identification of " << DofList(v.dofs, Hostability::kNone)
        << Goal(v);
      if (!v.dofs.empty() && !v.dofs.front().points.empty()) {
        s << " for any vehicle of the a priori box checked (its centre and corners)";
      }
      break;
  }
  return s.str();
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
  std::vector<char> plan_fits;
  std::vector<std::size_t> not_hosted;
  for (const auto& p : own.dofs) {
    DofVerdict& v = out.dofs.emplace_back(JudgeOwn(&p, p.dof, pool));
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
      BelowTargetUnlifted(pool, &v);
    }
    // A given plan that fails its own checks is judged as given: no other point rescues it.
    if (vo.judge_points && plan_fits[i]) JudgePoints(vehicle, pool, options, &v);
  });
  for (const DofVerdict& v : out.dofs) out.hosted = out.hosted && v.hosted;
  out.required = Required(pool, out.dofs);
  out.hostability = Overall(out.dofs);
  out.sentence = Sentence(out, pool);
  if (own.dofs.empty()) out.sentence += ": " + own.message;
  return out;
}

PoolVerdict JudgePool(const model::Vehicle& vehicle, const model::Pool& pool,
                      const ScheduleOptions& options, const Schedule* plan,
                      const VerdictOptions& vo) {
  return JudgePool(vehicle, pool, options, PlanSchedule(vehicle, pool, options), plan, vo);
}

namespace {

std::string DofLine(const DofVerdict& v, const model::Pool& pool) {
  std::ostringstream s;
  s << "  " << model::DofName(v.dof) << ": ";
  if (v.hosted) {
    const double free = pool.FreeTravel(v.dof);
    s << "hosted; its trials span "
      << (model::IsRotational(v.dof) ? model::AngleText(v.extent) : Fmt(v.extent, 4)) << " of the "
      << Travel(pool, v.dof, free)
      << (model::IsRotational(v.dof) ? " the tether allows" : "");
    return s.str();
  }
  s << (v.hostability == Hostability::kPart ? "hosted for PART of the a priori box ("
                                             : "NOT hosted (")
    << PoolLimitName(v.limit) << "): ";
  if (v.only_plan_fails) {
    s << "the planner's own schedule is hosted here; the plan's trials need "
      << Travel(pool, v.dof, v.extent) << ". ";
  } else if (std::isfinite(v.need)) {
    s << (v.need_verified ? "needs " : "needs at least ") << Travel(pool, v.dof, v.need)
      << (v.need_verified ? ", confirmed by planning it there" : "");
    if (v.need_verified && v.need_searched) {
      if (v.need_refuted > pool.FreeTravel(v.dof)) {
        s << " (planned with " << (model::IsRotational(v.dof) ? model::AngleText(v.need_refuted)
                                                             : Fmt(v.need_refuted, 4) + " m free")
          << ", not hosted)";
      }
    } else if (v.need_verified) {
      s << " (not searched for the smallest: `uuvplan check-pool` does)";
    }
    s << ". ";
  } else {
    s << "no pool size lifts this limit. ";
  }
  s << v.reason;
  if (v.points.empty()) return s.str();
  std::vector<std::string> at, not_at;
  for (const auto& p : v.points) (p.hosted ? at : not_at).push_back(p.point.label);
  s << " Planned at the box's centre and corners"
    << (v.points_start_known ? " (hosted at none with each trial's start estimated; below, "
                               "counting it known, the upper bound of the information)"
                             : "")
    << ": hosted " << (at.empty() ? "at none" : "at " + model::Join(at, "; "))
    << (not_at.empty() ? "" : "; not at " + model::Join(not_at, "; ")) << ".";
  if (not_at.empty()) {
    s << " Each is hosted when planned as a known vehicle; no one schedule hosts the whole box "
         "(the robust design above), so the first trials decide which to run.";
  }
  return s.str();
}

// The pool to book instead: along each DOF not hosted whose limit a larger pool lifts, the
// smallest found (ConfirmNeed); the other sides as this pool. A hosted pool gets no such line
// (its trials fill the room they are given: not a minimum).
std::string RequiredLine(const PoolVerdict& v, const model::Pool& pool) {
  std::ostringstream r;
  const RequiredPool& q = v.required;
  std::vector<std::string> sides;
  bool rotation = false, searched = false, planned = false;
  double bracket = 0.0;  // the widest (need − refuted) / need of the sides searched
  for (const auto& d : v.dofs) {
    if (d.hosted || !std::isfinite(d.need)) continue;
    // A given plan's own travel beyond what planning found: the plan as given needs that
    // side (Required), the planner's own schedule less — say which is which.
    const bool plan_side = v.plan_given && d.extent > d.need;
    planned = planned || !plan_side;
    if (d.need_searched && d.need > 0 && !plan_side) {
      searched = true;
      bracket = std::max(bracket, (d.need - d.need_refuted) / d.need);
    }
    if (model::IsRotational(d.dof)) {
      rotation = true;
      continue;
    }
    const double wall = d.dof == model::Dof::kSurge ? q.length
                        : d.dof == model::Dof::kSway ? q.width : q.depth;
    std::string side = std::string(model::Pool::SideName(d.dof)) +
                       (d.need_verified || plan_side ? " " : " at least ") + Fmt(wall, 4) +
                       " m wall to wall (" + Fmt(wall - 2 * pool.margin, 4) + " m free)";
    if (plan_side) {
      side += ", the plan's trials' travel over the box (the planner's own schedule " +
              (d.only_plan_fails
                   ? std::string("is hosted in this pool")
                   : std::string(d.need_verified ? "is hosted from " : "needs at least ") +
                         Fmt(pool.WallToWallFor(d.need), 4) + " m wall to wall") +
              ")";
    }
    sides.push_back(side);
  }
  if (rotation) sides.push_back("tether " + Fmt(q.turns, 4) + " turns");
  if (sides.empty()) return "  no pool size lifts the limits above";
  if (!planned) {
    r << "  a pool that hosts the plan as given";
  } else if (searched) {
    r << "  smallest pool found that hosts every DOF asked for";
    if (bracket > 0) {
      r << " (each side planned there; " << Fmt(100 * bracket, 2)
        << "% less free travel, or less, was planned and does not host)";
    }
  } else {
    r << "  a pool that hosts every DOF asked for (planned there; not the smallest: `uuvplan "
         "check-pool` searches for it)";
  }
  r << ": " << model::Join(sides, "; ")
    << (q.exists ? "; the rest as this pool" : "; but some DOF is limited by what no pool size lifts");
  return r.str();
}

}  // namespace

std::vector<std::string> VerdictLines(const PoolVerdict& v, const model::Pool& pool) {
  std::vector<std::string> out = {v.sentence};
  std::ostringstream p;
  p << "  pool: " << Fmt(pool.length, 4) << " x " << Fmt(pool.width, 4) << " x "
    << Fmt(pool.depth, 4) << " m wall to wall, margin " << Fmt(pool.margin, 4) << " m: free "
    << Fmt(pool.FreeTravel(model::Dof::kSurge), 4) << " x "
    << Fmt(pool.FreeTravel(model::Dof::kSway), 4) << " x "
    << Fmt(pool.FreeTravel(model::Dof::kHeave), 4) << " m; tether " << Fmt(pool.max_turns, 4)
    << " turns";
  out.push_back(p.str());
  for (const auto& d : v.dofs) out.push_back(DofLine(d, pool));
  if (!v.hosted) out.push_back(RequiredLine(v, pool));
  std::vector<std::string> tilts;
  for (const auto& d : v.dofs) {
    if (d.dof == model::Dof::kRoll || d.dof == model::Dof::kPitch) {
      tilts.emplace_back(model::DofName(d.dof));
    }
  }
  if (!tilts.empty()) {
    out.push_back("  assumption: " + model::Join(tilts) +
                  " planned as a free rotation, like yaw: the decoupled model (seed 004 eq. 2) "
                  "has no hydrostatic restoring moment (its bias is a constant moment), so a "
                  "vehicle stable in " + model::Join(tilts) +
                  " (metacentric height > 0) cannot make these turns; plan them only for a "
                  "vehicle without one");
  }
  const bool bound = std::any_of(v.dofs.begin(), v.dofs.end(), [](const DofVerdict& d) {
    return d.points_start_known;
  });
  if (v.hostability == Hostability::kPart) {
    out.push_back(
        "  assumption: judged over the whole a priori box (the vehicle file's inertia bounds and "
        "drag prior); the pool hosts the vehicles at the points listed" +
        std::string(bound ? " (for a DOF so marked, only counting each trial's start known: "
                            "the loop's trials at its estimates must do better than the a "
                            "priori schedule there)"
                          : "") +
        ", so the first trials decide: `loop` and `next` run, and a loop that then ends stuck "
        "on a DOF above has met a vehicle outside the hostable part (status infeasible, exit "
        "1)");
  } else if (!v.hosted) {
    out.push_back(
        "  assumption: judged over the whole a priori box (its centre and four (m, drag) "
        "corners each planned as a known vehicle, and again counting each trial's start "
        "known, the upper bound of the information): no vehicle of the box is hosted, `loop` "
        "refuses before any trial");
  }
  return out;
}

void ReadLoopEnd(const PoolVerdict& verdict, LoopResult* result) {
  if (verdict.hostability != Hostability::kPart || result->status != LoopStatus::kStuck) return;
  std::vector<std::string> outside;
  for (const auto& p : result->progress) {
    if (p.converged) continue;
    for (const auto& d : verdict.dofs) {
      if (d.dof == p.dof && d.hostability == Hostability::kPart) {
        outside.emplace_back(model::DofName(p.dof));
      }
    }
  }
  if (outside.empty()) return;
  result->status = LoopStatus::kInfeasible;
  result->message = "the first trials place " + model::Join(outside) +
                    " outside the part of the a priori box the pool hosts (the verdict "
                    "before any trial: " + verdict.sentence + "); " + result->message;
}

}  // namespace uuvplan::planner
