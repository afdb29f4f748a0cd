// The one feasibility verdict (pool_verdict.h).
#include "uuvplan/planner/pool_verdict.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "format.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::planner {
namespace {

using internal::Fmt;
constexpr double kInf = std::numeric_limits<double>::infinity();
// The designs keep 5-10 mm inside the free travel (sine_design.cc, steady_design.cc): a need
// within this of the free travel is a space limit.
constexpr double kTravelSafety = 0.01;

constexpr model::EnumNames<PoolLimit, 9> kLimitNames{{{
    {PoolLimit::kNone, "none"}, {PoolLimit::kLength, "length"}, {PoolLimit::kWidth, "width"},
    {PoolLimit::kDepth, "depth"}, {PoolLimit::kTether, "tether"},
    {PoolLimit::kThrust, "thrust range"}, {PoolLimit::kNoReversal, "no reversal"},
    {PoolLimit::kDuration, "duration"}, {PoolLimit::kInformation, "information"}}}};

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
  const double wall = pool.WallToWallFor(free + kTravelSafety);
  switch (dof) {
    case model::Dof::kSurge: p.length = std::max(p.length, wall); break;
    case model::Dof::kSway: p.width = std::max(p.width, wall); break;
    case model::Dof::kHeave: p.depth = std::max(p.depth, wall); break;
    default: p.max_turns = std::max(p.max_turns, (free + kTravelSafety) / (2 * M_PI));
  }
  return p;
}

// The need of a DOF the pool's space limits, confirmed by planning it in a pool offering it.
void ConfirmNeed(const model::Vehicle& vehicle, const model::Pool& pool,
                 const ScheduleOptions& options, const VerdictOptions& vo, DofVerdict* v) {
  ScheduleOptions so = options;
  so.dofs = {v->dof};
  for (int i = 0; i <= vo.need_checks; ++i) {
    const ScheduleResult r = PlanSchedule(vehicle, Offering(pool, v->dof, v->need), so);
    if (r.status == PlanStatus::kOk) {
      v->need_verified = true;
      for (const auto& t : r.schedule.trials) {
        v->need = std::max(v->need, t.travel[1] - t.travel[0]);
      }
      return;
    }
    if (i < vo.need_checks) v->need *= 1.5;
  }
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
  for (const auto& t : p->trials) v.extent = std::max(v.extent, t.travel[1] - t.travel[0]);
  v.hosted = p->status == DesignStatus::kOk && p->complete;
  v.need = v.extent;
  if (v.hosted) return v;
  v.reason = p->message;
  const double free = pool.FreeTravel(dof);
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

// A given plan's trials of `v.dof`: each must pass DofContext::Check in this pool.
void JudgePlanTrials(const std::vector<TrialPoolCheck>& checks, DofVerdict* v) {
  for (const auto& c : checks) {
    if (c.dof != v->dof) continue;
    v->extent = std::max(v->extent, c.check.span);
    v->need = std::max(v->need, c.check.span);
    if (c.check.feasible) continue;
    const std::string why = model::Join(c.check.reasons, "; ");
    if (v->hosted || v->limit == PoolLimit::kNone) v->limit = LimitOfText(v->dof, why);
    v->hosted = false;
    v->reason += (v->reason.empty() ? "" : " ") + std::string("plan trial '") + c.id + "': " + why;
    if (v->limit != SpaceLimit(v->dof)) v->need = kInf;
  }
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

std::string DofList(const std::vector<DofVerdict>& dofs, bool hosted) {
  std::vector<std::string> names;
  for (const auto& d : dofs) {
    if (d.hosted == hosted) names.emplace_back(model::DofName(d.dof));
  }
  return model::Join(names);
}

}  // namespace

std::string_view PoolLimitName(PoolLimit limit) { return kLimitNames.Name(limit); }

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
  out.plan_given = plan_checks != nullptr;
  if (plan_checks != nullptr) out.plan_checks = *plan_checks;
  out.hosted = !own.dofs.empty();
  for (const auto& p : own.dofs) {
    DofVerdict v = JudgeOwn(&p, p.dof, pool);
    JudgePlanTrials(out.plan_checks, &v);
    if (!v.hosted && std::isfinite(v.need) && vo.need_checks >= 0) {
      ConfirmNeed(vehicle, pool, options, vo, &v);
    }
    out.hosted = out.hosted && v.hosted;
    out.dofs.push_back(std::move(v));
  }
  out.required = Required(pool, out.dofs);
  std::ostringstream s;
  s << "Pool " << pool.name << (out.hosted ? " CAN" : " CANNOT") << " host the identification of "
    << (out.hosted ? DofList(out.dofs, true) : DofList(out.dofs, false));
  if (own.dofs.empty()) s << ": " << own.message;
  out.sentence = s.str();
  return out;
}

PoolVerdict JudgePool(const model::Vehicle& vehicle, const model::Pool& pool,
                      const ScheduleOptions& options, const Schedule* plan,
                      const VerdictOptions& vo) {
  return JudgePool(vehicle, pool, options, PlanSchedule(vehicle, pool, options), plan, vo);
}

namespace {

// "9.66 m of free depth (12.66 m wall to wall)" or "18.85 rad (3 turns of the tether)".
std::string Travel(const model::Pool& pool, model::Dof dof, double free) {
  std::ostringstream s;
  if (model::IsRotational(dof)) {
    s << Fmt(free, 4) << " rad (" << Fmt(pool.ExtentFor(dof, free), 4) << " turns)";
  } else {
    s << Fmt(free, 4) << " m of free " << model::Pool::SideName(dof) << " ("
      << Fmt(pool.WallToWallFor(free), 4) << " m wall to wall)";
  }
  return s.str();
}

std::string DofLine(const DofVerdict& v, const model::Pool& pool) {
  std::ostringstream s;
  s << "  " << model::DofName(v.dof) << ": ";
  if (v.hosted) {
    const double free = pool.FreeTravel(v.dof);
    s << "hosted; its trials span " << Fmt(v.extent, 4) << " of the "
      << Travel(pool, v.dof, free)
      << (model::IsRotational(v.dof) ? " the tether allows" : "");
    return s.str();
  }
  s << "NOT hosted (" << PoolLimitName(v.limit) << "): ";
  if (std::isfinite(v.need)) {
    s << (v.need_verified ? "needs " : "needs at least ") << Travel(pool, v.dof, v.need)
      << (v.need_verified ? ", confirmed by planning it there" : "") << ". ";
  } else {
    s << "no pool size lifts this limit. ";
  }
  s << v.reason;
  return s.str();
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
  std::ostringstream r;
  const RequiredPool& q = v.required;
  r << "  smallest pool that hosts every DOF asked for:";
  bool rotation = false;
  for (const auto& d : v.dofs) {
    const double wall = d.dof == model::Dof::kSurge ? q.length
                        : d.dof == model::Dof::kSway ? q.width : q.depth;
    rotation = rotation || model::IsRotational(d.dof);
    if (model::IsRotational(d.dof)) continue;
    r << " " << model::Pool::SideName(d.dof) << " " << Fmt(wall, 4) << " m wall to wall ("
      << Fmt(wall - 2 * pool.margin, 4) << " m free);";
  }
  if (rotation) r << " tether " << Fmt(q.turns, 4) << " turns;";
  r << (q.exists ? " the rest as this pool" : " but some DOF is limited by what no pool size lifts");
  out.push_back(r.str());
  if (!v.hosted) {
    // The verdict is robust (docs/planning.md): every trial must hold for every vehicle of the
    // a priori box. A sequential loop designs at its estimates instead, so it may get further.
    out.push_back(
        "  assumption: judged over the whole a priori box (the vehicle file's inertia bounds and "
        "drag prior); a vehicle away from the box's worst corner may still be identified here by "
        "running the trials that fit and re-planning with `next`, but that cannot be promised "
        "before the first estimates");
  }
  return out;
}

}  // namespace uuvplan::planner
