// One feasibility model, one verdict: can this pool host the identification of these DOFs
// (every parameter of interest determined, determinacy.h), and if not, what is the smallest pool
// that would. `schedule`, `check-pool` (with and without a plan), `next`, `demo` and the start of
// `loop` all print JudgePool's answer and exit on `hosted`.
//
// Per DOF: hosted when the planner's own schedule for the pool determines every parameter of
// interest (its steady runs, its sine and the loop's families, schedule_planner.h), lets the
// loop bring them to its target before its stuck rule stops it (ReachTarget, determinacy.h:
// "to this precision", ScheduleOptions::precision, `--target`) and, for a
// given plan, every trial of the plan passes the hard constraints (DofPlanningProblem::Check:
// thrusters, no reversal, free length/width/depth over the a priori box, tether turns, duration).
// Otherwise the limit that stops it and the DOF's need: the free travel (m, or rad of a rotation)
// with which it would be hosted, checked by planning it again in a pool that offers it. `required`
// covers EVERY DOF asked for, planned or not: per axis the largest of every trial's extent (planned
// and given) and every DOF's need, wall to wall (+ 2·margin); for rotations the tether's turns.
//
// Three-valued: the schedule is robust, planned for every vehicle of the a priori
// box. A DOF it cannot host over the whole box is planned again at the box's centre and at its
// four (m, drag) corners (box_points.h): hosted at some of them, it is hosted for PART of the
// box — the first trials decide, and `uuvplan loop` / `next` run there; at none, for none. A
// loop run in a part pool that ends stuck on a part DOF has met a vehicle outside the hostable
// part: ReadLoopEnd makes that the pool's answer (infeasible, exit 1). The verdict is data; its
// sentences are the text layer's (text/verdict_text.h).
#pragma once

#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/box_points.h"
#include "uuvplan/planner/loop/design_loop.h"
#include "uuvplan/planner/pool/pool_check.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::planner {

/// What stops a DOF: a side of the pool (free length/width/depth), the tether's turns, the
/// thrust range (min_thrust against the largest thrust or the speed limit), no propeller
/// reversal, the trial duration limit, information (trials fit but do not determine it), or
/// the rotation-rate limit (a rotation's drag, too slow to reach the target: the loop's stuck
/// rule names it, stuck_limit.cc).
enum class PoolLimit {
  kNone,
  kLength,
  kWidth,
  kDepth,
  kTether,
  kThrust,
  kNoReversal,
  kDuration,
  kInformation,
  kRotationRate
};
std::string_view PoolLimitName(PoolLimit limit);

/// For how much of the a priori box the pool hosts a DOF (or every DOF asked for): every
/// vehicle of the box, part of it (some of the points checked: the first trials decide), none.
enum class Hostability { kAll, kPart, kNone };
std::string_view HostabilityName(Hostability h);

/// One point of the box checked for a DOF not hosted over the whole box.
struct PointVerdict {
  BoxPoint point;
  bool hosted = false;
};

struct DofVerdict {
  model::Dof dof = model::Dof::kSurge;
  bool hosted = false;
  PoolLimit limit = PoolLimit::kNone;
  /// Why the planner's own schedule does not host it (DofPlan::message; empty when it does).
  /// A given plan's failing trials are the verdict's `plan_checks` of this DOF.
  std::string message;
  /// Largest travel span of the DOF's trials in this pool (planned and given), free travel:
  /// m for a translation, rad for a rotation.
  double extent = 0.0;
  /// Free travel (m or rad) with which the DOF is hosted: `extent` when hosted; +inf when no
  /// pool size lifts the limit (thrust range, no reversal, duration).
  double need = 0.0;
  bool need_verified = false;  ///< a pool offering `need` was planned and hosts the DOF
  /// The largest free travel planned that does not host it (ConfirmNeed's bisection; at
  /// least this pool's).
  double need_refuted = 0.0;
  bool need_searched = false;  ///< `need` is the smallest found (VerdictOptions::need_bisections)
  /// Short of the target, and a pool offering `unlifted_travel` (free travel, m or rad) was
  /// planned and does not lift it: the loop's stuck rule names what is left (`limit`: the
  /// rotation rate of a rotation, no reversal of a translation).
  bool unlifted = false;
  double unlifted_travel = 0.0;
  /// The planner's own schedule is hosted here; only a given plan's trials fail (no larger
  /// pool is searched: `need` is the planner's extent, `extent` the plan's).
  bool only_plan_fails = false;
  Determinacy determinacy;  ///< of the planner's own schedule in this pool
  /// Determined, but the loop's target is out of reach of its trials in this pool
  /// (TargetReach of the schedule: the loop would end stuck).
  bool below_target = false;
  TargetReach reach;  ///< of the planner's own schedule in this pool
  /// kAll exactly when `hosted`; else kPart or kNone by `points`.
  Hostability hostability = Hostability::kNone;
  std::vector<PointVerdict> points;  ///< centre and corners checked when not hosted
  /// `points` were planned with each trial's start known (PlannerOptions::start_known): no
  /// point is hosted with it estimated, so "none" is judged on that upper bound of the
  /// information — the loop's own trials, planned at its estimates, may still get there.
  bool points_start_known = false;
};

/// The pool that hosts every DOF asked for (wall to wall, m) and the tether turns: along a
/// DOF not hosted, the smallest found (ConfirmNeed's bisection, to VerdictOptions::
/// need_tolerance); along a hosted DOF, the room its trials use in this pool (the planner
/// fills the room it is given: a smaller pool may host it too, not searched).
struct RequiredPool {
  double length = 0.0, width = 0.0, depth = 0.0;  ///< m, wall to wall (free + 2·margin)
  double turns = 0.0;                             ///< full turns about roll, pitch or yaw
  bool exists = true;  ///< false: some DOF is limited by something no pool size lifts
};

struct PoolVerdict {
  bool hosted = false;  ///< every DOF hosted over the whole a priori box
  PrecisionGoal goal;   ///< the precision judged at (ScheduleOptions::precision)
  /// kAll when hosted; kNone when some DOF is hosted at no point checked; else kPart.
  Hostability hostability = Hostability::kNone;
  std::vector<DofVerdict> dofs;
  RequiredPool required;
  bool plan_given = false;
  std::vector<TrialPoolCheck> plan_checks;  ///< the given plan's trials, checked in this pool
  /// Why nothing was planned (ScheduleResult::message when it planned no DOF).
  std::string unplanned;
  /// Some DOF's box is centred on the vehicle file's identified model (PlanningBox), not its
  /// a priori bounds: "the a priori box" of the fields above is that box for such a DOF.
  bool identified_box = false;
  /// That model is derived from a base vehicle's estimates with a payload's rules
  /// (model/payload.h; DofParameters::origin), not identified on this vehicle.
  bool derived_box = false;
};

/// CHOSEN 6 with a 5% tolerance: the bracket shrinks up to 64×, to 5% for a first guess up to
/// 4× this pool's free travel.
inline constexpr int kSmallestPoolBisections = 6;

struct VerdictOptions {
  /// Re-plan a non-hosted DOF in a pool offering its need to confirm it (up to this many
  /// enlargements by 1.5×). CHOSEN 2: the first guess (the largest failing run) usually holds.
  /// Negative: no confirmation (`need` stays the first guess, need_verified false).
  int need_checks = 2;
  /// Then the smallest pool between this one and the confirmed one, by bisection of the free
  /// travel to `need_tolerance` of it (at most `need_bisections` plannings): the answer is
  /// the smallest pool found that hosts, with the largest planned that does not
  /// (DofVerdict::need_refuted). 0: no search (the confirmed pool, said to be no minimum).
  /// `check-pool`, the command that answers "what would host it", searches with
  /// kSmallestPoolBisections; the others print the confirmed pool and point to it (the search
  /// costs up to 6 plannings of each DOF not hosted, 0.1–2.5 s each).
  int need_bisections = 0;
  double need_tolerance = 0.05;
  /// Plan a DOF not hosted over the box again at the box's centre and corners (Hostability).
  /// false: a DOF not hosted is kNone without checking.
  bool judge_points = true;
};

/// The verdict for `own`, the planner's schedule of these DOFs in `pool` (PlanSchedule with
/// `options`), and optionally a given plan (null: none).
PoolVerdict JudgePool(const model::Vehicle& vehicle, const model::Pool& pool,
                      const ScheduleOptions& options, const ScheduleResult& own,
                      const Schedule* plan, const VerdictOptions& verdict = {});

/// The same for a given plan whose trials CheckPool has already checked in this pool
/// (`plan_checks`, null: no plan), so that check-pool simulates each trial once.
PoolVerdict JudgePoolOnChecks(const model::Vehicle& vehicle, const model::Pool& pool,
                              const ScheduleOptions& options, const ScheduleResult& own,
                              const std::vector<TrialPoolCheck>* plan_checks,
                              const VerdictOptions& verdict = {});

/// The same, planning `own` first.
PoolVerdict JudgePool(const model::Vehicle& vehicle, const model::Pool& pool,
                      const ScheduleOptions& options, const Schedule* plan = nullptr,
                      const VerdictOptions& verdict = {});

/// Whether `uuvplan loop` (and `next`) may run trials: the pool hosts the DOFs for all or part
/// of the box.
inline bool LoopMayRun(const PoolVerdict& v) { return v.hostability != Hostability::kNone; }

/// A loop's end read against the verdict it ran under: in a pool hosted for part of the box, a
/// loop stuck with a part DOF short of the target has met a vehicle outside the hostable part —
/// status kInfeasible (the pool cannot host this vehicle), those DOFs in
/// `result->outside_part`.
void ReadLoopEnd(const PoolVerdict& verdict, LoopResult* result);

}  // namespace uuvplan::planner
