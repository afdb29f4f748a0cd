// The pool verdict in words (verdict_text.h).
#include "uuvplan/text/verdict_text.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::text {

using model::Significant;
using planner::DofVerdict;
using planner::Hostability;
using planner::PoolVerdict;
using planner::RequiredPool;

namespace {

// "9.66 m of free depth (12.66 m wall to wall)" or "1080° (3 turns)" (angles for people in
// degrees, docs/cli.md).
std::string Travel(const model::Pool& pool, model::Dof dof, double free) {
  std::ostringstream s;
  if (model::IsRotational(dof)) {
    s << model::AngleText(free);
  } else {
    s << Significant(free, 4) << " m of free " << model::Pool::SideName(dof) << " ("
      << Significant(pool.WallToWallFor(free), 4) << " m wall to wall)";
  }
  return s.str();
}

std::string DofList(const std::vector<planner::DofVerdict>& dofs, Hostability h) {
  std::vector<std::string> names;
  for (const auto& d : dofs) {
    if (d.hostability == h) names.emplace_back(model::DofName(d.dof));
  }
  return model::Join(names);
}

// " to 5% (every parameter of interest's 100·σ/|θ|)": the precision judged at.
std::string Goal(const PoolVerdict& v) {
  return " to " + Significant(v.goal.target_percent, 3) +
         "% (every parameter of interest's 100·σ/|θ|)";
}

// "a priori box", or the box about the vehicle file's estimates the planner used instead.
std::string Box(bool identified_box, bool derived_box) {
  if (derived_box) return "box about the base's estimates with the payload";
  return identified_box ? "box about the identified model" : "a priori box";
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
        << " for PART of the " << Box(v.identified_box, v.derived_box)
        << " only (the first trials decide: `loop` and `next` run and stop when the estimates "
           "fall outside it)";
      break;
    case Hostability::kNone:
      s << " CANNOT host the identification of " << DofList(v.dofs, Hostability::kNone) << Goal(v);
      if (!v.dofs.empty() && !v.dofs.front().points.empty()) {
        s << " for any vehicle of the " << Box(v.identified_box, v.derived_box)
          << " checked (its centre and corners)";
      }
      break;
  }
  return s.str();
}

// One DOF: hosted and the room its trials use, or the limit, the need and the reason.
std::string DofLine(const PoolVerdict& verdict, const DofVerdict& v, const model::Pool& pool) {
  std::ostringstream s;
  s << "  " << model::DofName(v.dof) << ": ";
  if (v.hosted) {
    const double free = pool.FreeTravel(v.dof);
    s << "hosted; its trials span "
      << (model::IsRotational(v.dof) ? model::AngleText(v.extent) : Significant(v.extent, 4))
      << " of the " << Travel(pool, v.dof, free)
      << (model::IsRotational(v.dof) ? " the tether allows" : "");
    return s.str();
  }
  s << (v.hostability == Hostability::kPart
            ? "hosted for PART of the " + Box(verdict.identified_box, verdict.derived_box) + " ("
            : std::string("NOT hosted ("))
    << planner::PoolLimitName(v.limit) << "): ";
  if (v.only_plan_fails) {
    s << "the planner's own schedule is hosted here; the plan's trials need "
      << Travel(pool, v.dof, v.extent) << ". ";
  } else if (std::isfinite(v.need)) {
    s << (v.need_verified ? "needs " : "needs at least ") << Travel(pool, v.dof, v.need)
      << (v.need_verified ? ", confirmed by planning it there" : "");
    if (v.need_verified && v.need_searched) {
      if (v.need_refuted > pool.FreeTravel(v.dof)) {
        s << " (planned with "
          << (model::IsRotational(v.dof) ? model::AngleText(v.need_refuted)
                                         : Significant(v.need_refuted, 4) + " m free")
          << ", not hosted)";
      }
    } else if (v.need_verified) {
      s << " (not searched for the smallest: `uuvplan check-pool` does)";
    }
    s << ". ";
  } else {
    s << "no pool size lifts this limit. ";
  }
  s << DofReason(verdict, v, pool);
  if (v.points.empty()) return s.str();
  std::vector<std::string> at, not_at;
  for (const auto& p : v.points) {
    (p.hosted ? at : not_at).push_back(BoxPointLabel(p.point, v.dof));
  }
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
    const double wall = d.dof == model::Dof::kSurge  ? q.length
                        : d.dof == model::Dof::kSway ? q.width
                                                     : q.depth;
    std::string side = std::string(model::Pool::SideName(d.dof)) +
                       (d.need_verified || plan_side ? " " : " at least ") + Significant(wall, 4) +
                       " m wall to wall (" + Significant(wall - 2 * pool.margin, 4) + " m free)";
    if (plan_side) {
      side += ", the plan's trials' travel over the box (the planner's own schedule " +
              (d.only_plan_fails
                   ? std::string("is hosted in this pool")
                   : std::string(d.need_verified ? "is hosted from " : "needs at least ") +
                         Significant(pool.WallToWallFor(d.need), 4) + " m wall to wall") +
              ")";
    }
    sides.push_back(side);
  }
  if (rotation) sides.push_back("tether " + Significant(q.turns, 4) + " turns");
  if (sides.empty()) return "  no pool size lifts the limits above";
  if (!planned) {
    r << "  a pool that hosts the plan as given";
  } else if (searched) {
    r << "  smallest pool found that hosts every DOF asked for";
    if (bracket > 0) {
      r << " (each side planned there; " << Significant(100 * bracket, 2)
        << "% less free travel, or less, was planned and does not host)";
    }
  } else {
    r << "  a pool that hosts every DOF asked for (planned there; not the smallest: `uuvplan "
         "check-pool` searches for it)";
  }
  r << ": " << model::Join(sides, "; ")
    << (q.exists ? "; the rest as this pool"
                 : "; but some DOF is limited by what no pool size lifts");
  return r.str();
}

// Whether the pool hosts the identification, in words (VerdictAnswer).
constexpr model::EnumNames<Hostability, 3> kVerdictAnswers{{{
    {Hostability::kAll, "CAN host it"},
    {Hostability::kPart, "can host it for PART of the a priori box only"},
    {Hostability::kNone, "CANNOT host it"},
}}};

}  // namespace

std::string VerdictSentence(const PoolVerdict& v, const model::Pool& pool) {
  return v.dofs.empty() ? Sentence(v, pool) + ": " + v.unplanned : Sentence(v, pool);
}

std::string BoxPointLabel(const planner::BoxPoint& p, model::Dof dof) {
  return "m " + Significant(p.m, 3) + " " + model::Unit(model::param::kMass, dof) + ", drag ×" +
         Significant(p.drag_factor, 3) + " of the prior (kq " + Significant(p.kq, 3) + " " +
         model::Unit(model::param::kQuadraticDrag, dof) + ")";
}

std::string VerdictAnswer(Hostability h, bool identified_box, bool derived_box) {
  if (h == Hostability::kPart && identified_box) {
    return "can host it for PART of the " + Box(true, derived_box) + " only";
  }
  return std::string(kVerdictAnswers.Name(h));
}

std::string DofReason(const PoolVerdict& verdict, const DofVerdict& d, const model::Pool& pool) {
  std::string reason = d.message;
  for (const planner::TrialPoolCheck& c : verdict.plan_checks) {
    if (c.dof != d.dof || c.check.feasible) continue;
    reason += (reason.empty() ? "" : " ") + std::string("plan trial '") + c.id +
              "': " + model::Join(c.check.reasons, "; ");
  }
  if (d.unlifted) {
    reason += " A pool offering " + Travel(pool, d.dof, d.unlifted_travel) +
              " does not lift it either: " +
              (model::IsRotational(d.dof)
                   ? "the designs keep below the rotation-rate limit, where the drag hardly acts"
                   : "the trials never reverse a thruster, so the drag is seen over one speed "
                     "range per direction") +
              ".";
  }
  return reason;
}

std::vector<std::string> VerdictLines(const PoolVerdict& v, const model::Pool& pool) {
  std::vector<std::string> out = {VerdictSentence(v, pool)};
  std::ostringstream p;
  p << "  pool: " << Significant(pool.length, 4) << " x " << Significant(pool.width, 4) << " x "
    << Significant(pool.depth, 4) << " m wall to wall, margin " << Significant(pool.margin, 4)
    << " m: free " << Significant(pool.FreeTravel(model::Dof::kSurge), 4) << " x "
    << Significant(pool.FreeTravel(model::Dof::kSway), 4) << " x "
    << Significant(pool.FreeTravel(model::Dof::kHeave), 4) << " m; tether "
    << Significant(pool.max_turns, 4) << " turns";
  out.push_back(p.str());
  for (const auto& d : v.dofs) out.push_back(DofLine(v, d, pool));
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
                  "vehicle stable in " +
                  model::Join(tilts) +
                  " (metacentric height > 0) cannot make these turns; plan them only for a "
                  "vehicle without one");
  }
  const bool bound = std::any_of(v.dofs.begin(), v.dofs.end(),
                                 [](const DofVerdict& d) { return d.points_start_known; });
  if (v.hostability == Hostability::kPart) {
    out.push_back(
        "  assumption: judged over the whole " + Box(v.identified_box, v.derived_box) +
        (v.derived_box      ? " (the base's estimates with the payload's rules, ± their σ, "
                              "within the a priori bounds)"
         : v.identified_box ? " (the vehicle file's estimates ± their σ, within its a priori "
                              "bounds)"
                            : " (the vehicle file's inertia bounds and drag prior)") +
        "; the pool hosts the vehicles at the points listed" +
        std::string(bound ? " (for a DOF so marked, only counting each trial's start known: "
                            "the loop's trials at its estimates must do better than the a "
                            "priori schedule there)"
                          : "") +
        ", so the first trials decide: `loop` and `next` run, and a loop that then ends stuck "
        "on a DOF above has met a vehicle outside the hostable part (status infeasible, exit "
        "1)");
  } else if (!v.hosted) {
    out.push_back(
        "  assumption: judged over the whole " + Box(v.identified_box, v.derived_box) +
        " (its centre and four (m, drag) corners each planned as a known vehicle, and again "
        "counting each trial's start "
        "known, the upper bound of the information): no vehicle of the box is hosted, `loop` "
        "refuses before any trial");
  }
  return out;
}

void PrintVerdict(const PoolVerdict& verdict, const model::Pool& pool, std::ostream& out) {
  out << "\nVerdict: ";
  for (const auto& line : VerdictLines(verdict, pool)) out << line << "\n";
}

std::string LoopEndMessage(const planner::LoopResult& result, const PoolVerdict& verdict,
                           const model::Pool& pool) {
  if (result.outside_part.empty()) return result.message;
  std::vector<std::string> outside;
  for (const model::Dof dof : result.outside_part) outside.emplace_back(model::DofName(dof));
  return "the first trials place " + model::Join(outside) + " outside the part of the " +
         Box(verdict.identified_box, verdict.derived_box) +
         " the pool hosts (the verdict before any trial: " + VerdictSentence(verdict, pool) +
         "); " + result.message;
}

}  // namespace uuvplan::text
