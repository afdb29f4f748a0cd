// The one pool verdict (planner/pool/pool_verdict.h): on ROMEO (own pool and a 6 × 6 × 3 m
// pool), VSOR, URIS and seeded random vehicles, the verdict of the planner's own schedule and of
// that schedule given back as a plan agree; `required` covers every trial's extent and every
// DOF's need; and every planned trial stays inside the pool and the tether's turns when
// simulated INDEPENDENTLY (model::Simulate at the corners of the prior box, not
// DofPlanningProblem).
#include "uuvplan/planner/pool/pool_verdict.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <string>
#include <vector>

#include "planner_test_util.h"
#include "support/random_vehicle.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/model_structure.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/prior.h"
#include "uuvplan/model/simulator.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/text/verdict_text.h"

namespace uuvplan::planner {
namespace {

using model::Dof;

// Span of the position over the trial at every corner of the a priori box: m at its inertia
// bounds, k and kq together at DragOf × (1 ± rel_sigma) (floored at 0.05, as the box's
// documented axis), every η at 0.5 and 1 (BoxOptions::eta_range). RK4 at 0.02 s, sampled at
// 0.05 s.
double IndependentSpan(const model::Vehicle& v, const model::TrialDesign& d) {
  std::vector<std::string> mappings;
  for (int i : v.MappingsOf(d.dof)) mappings.push_back(v.mappings[i].name);
  const model::DofModel dm(v, model::ModelStructure::Standard(v, d.dof, mappings, false));
  const auto mb = v.InertiaBounds(d.dof);
  const model::APrioriDrag drag = model::DragOf(v, d.dof, BoxOptions{}.fallback_drag_rel_sigma);
  const double rel = drag.drag.rel_sigma;
  const auto input = model::MakeExcitation(v, d);
  model::TrialConditions c;
  c.input = input.get();
  std::vector<double> times;
  for (double t = 0.0; t <= d.duration + 1e-9; t += 0.05) times.push_back(t);
  model::SimulationOptions so;
  so.step_s = 0.02;
  double lo = 0.0, hi = 0.0;
  for (double m : {mb[0], mb[1]}) {
    for (double f : {std::max(0.05, 1.0 - rel), 1.0 + rel}) {
      for (double eta : {0.5, 1.0}) {
        std::map<std::string, double> values;
        for (const auto& n : dm.parameter_names()) values[n] = model::NullValue(n);
        for (const auto& n : dm.parameter_names()) {
          if (n.rfind(model::param::kEtaPrefix, 0) == 0) values[n] = eta;
        }
        values[model::param::kMass] = m;
        values[model::param::kLinearDrag] = f * drag.drag.k;
        values[model::param::kQuadraticDrag] = f * drag.drag.kq;
        const model::Trajectory tr = model::Simulate(dm, dm.Theta(values), c, times, so);
        lo = std::min(lo, tr.x.col(0).minCoeff());
        hi = std::max(hi, tr.x.col(0).maxCoeff());
      }
    }
  }
  return hi - lo;
}

// The verdict's promises for one vehicle, pool and DOF list.
void CheckVerdict(const model::Vehicle& v, const model::Pool& pool, const std::vector<Dof>& dofs,
                  const std::string& what) {
  ScheduleOptions so;
  so.dofs = dofs;
  const ScheduleResult own = PlanSchedule(v, pool, so);
  const PoolVerdict verdict = JudgePool(v, pool, so, own, nullptr);
  VerdictOptions no_recheck;
  no_recheck.need_checks = -1;  // the needs were confirmed above; `hosted` does not use them
  const PoolVerdict with_plan = JudgePool(v, pool, so, own, &own.schedule, no_recheck);
  // schedule and check-pool --plan of that schedule: one answer.
  EXPECT_EQ(verdict.hosted, with_plan.hosted)
      << what << ": " << text::VerdictSentence(verdict, pool);
  EXPECT_EQ(verdict.hosted, own.status == PlanStatus::kOk) << what;
  ASSERT_EQ(verdict.dofs.size(), dofs.size()) << what;  // every DOF asked for is judged
  const RequiredPool& r = verdict.required;
  for (const DofVerdict& d : verdict.dofs) {
    EXPECT_EQ(d.hosted, d.hostability == Hostability::kAll) << what;
    // Not hosted over the box: judged at its centre and four corners; part iff one hosts.
    if (!d.hosted) {
      EXPECT_EQ(d.points.size(), 5u) << what;
      bool any = false;
      for (const auto& p : d.points) any = any || p.hosted;
      EXPECT_EQ(any, d.hostability == Hostability::kPart) << what;
    }
    // Hosted: determined and the loop's target reachable (ReachTarget), nothing else.
    EXPECT_EQ(d.hosted, d.determinacy.determined && d.reach.reached)
        << what << " " << model::DofName(d.dof);
    EXPECT_EQ(d.below_target, d.determinacy.determined && !d.reach.reached) << what;
    EXPECT_EQ(d.hosted, d.limit == PoolLimit::kNone) << what << " " << d.message;
    const double need = std::isfinite(d.need) ? std::max(d.need, d.extent) : d.extent;
    // `required` ≥ every DOF's need and its trials' extent (1 µm: the sum of the margins).
    if (model::IsRotational(d.dof)) {
      EXPECT_GE(r.turns + 1e-9, pool.ExtentFor(d.dof, need)) << what;
    } else {
      const double wall = d.dof == Dof::kSurge ? r.length : d.dof == Dof::kSway ? r.width : r.depth;
      EXPECT_GE(wall + 1e-6, pool.WallToWallFor(need)) << what << " " << model::DofName(d.dof);
    }
    if (!std::isfinite(d.need)) EXPECT_FALSE(r.exists) << what;
  }
  for (const PlannedTrial& t : own.schedule.trials) {
    // Independent simulation; 0.5% + 1 mm: RK4 at 0.02 s against the planner's 0.1 s, and the
    // designs keep 5-10 mm inside the free travel.
    const double span = IndependentSpan(v, t.design);
    const double free = pool.FreeTravel(t.design.dof);
    EXPECT_LE(span, free * 1.005 + 1e-3) << what << " trial " << t.design.id;
    EXPECT_LE(t.design.duration, so.planner.max_trial_duration_s + 1e-9) << what;
  }
}

// The 6 × 6 × 3 m pool (margin 1 m: 1.5 m would leave no depth to move in).
model::Pool SixBySixByThree() { return model::Pool{"six", 6.0, 6.0, 3.0, 1.0}; }

model::Vehicle CaseVehicle(const std::string& c) {
  return io::ReadVehicle(std::string(UUVPLAN_SOURCE_DIR) + "/cases/" + c + "/vehicle.yaml");
}
model::Pool CasePool(const std::string& c) {
  return io::ReadPool(std::string(UUVPLAN_SOURCE_DIR) + "/cases/" + c + "/pool.yaml");
}

TEST(PoolVerdict, RomeoOwnPoolAgreesAcrossCommands) {
  const model::Vehicle v = testing::Romeo();
  CheckVerdict(v, testing::RomeoPool(), {Dof::kSurge, Dof::kSway, Dof::kHeave, Dof::kYaw}, "romeo");
}

TEST(PoolVerdict, RomeoSixMetrePoolIsRefusedWithAConfirmedLargerNeed) {
  const model::Vehicle v = testing::Romeo();
  const model::Pool six = SixBySixByThree();
  CheckVerdict(v, six, {Dof::kSurge, Dof::kSway, Dof::kHeave, Dof::kYaw}, "romeo-six");
  ScheduleOptions so;
  so.dofs = {Dof::kSurge};
  const PoolVerdict verdict = JudgePool(v, six, so);
  ASSERT_FALSE(verdict.hosted);
  const DofVerdict& surge = verdict.dofs.at(0);
  EXPECT_EQ(surge.limit, PoolLimit::kLength) << surge.message;
  EXPECT_TRUE(surge.need_verified);
  // The required pool is not the tiny pool itself (the bug): longer than 6 m.
  EXPECT_GT(verdict.required.length, six.length + 1.0);
}

// check-pool --plan: a plan made for a larger pool (ROMEO's own, 20 m free) judged in a 3 m
// one. The plan as given needs its trials' travel (Required, the JSON's `required`); the
// planner's own need is searched as without a plan (one answer: before, the plan's 19.8 m
// started the search and `check-pool --plan` proposed another pool than `check-pool`), and the
// text tells the two apart instead of calling the plan's travel "planned there".
TEST(PoolVerdict, APlanForALargerPoolNeedsItsTravelAndThePlannersNeedIsUnchanged) {
  const model::Vehicle v = testing::Romeo();
  const model::Pool tiny{"tiny", 3.0, 6.0, 3.0, 1.0};
  ScheduleOptions so;
  so.dofs = {Dof::kSurge};
  const ScheduleResult made_for_romeo = PlanSchedule(v, testing::RomeoPool(), so);
  const ScheduleResult own = PlanSchedule(v, tiny, so);
  VerdictOptions confirm_only;
  confirm_only.judge_points = false;
  const PoolVerdict alone = JudgePool(v, tiny, so, own, nullptr, confirm_only);
  const PoolVerdict with_plan = JudgePool(v, tiny, so, own, &made_for_romeo.schedule, confirm_only);
  ASSERT_FALSE(with_plan.hosted);
  EXPECT_EQ(with_plan.dofs.at(0).need, alone.dofs.at(0).need);
  EXPECT_EQ(with_plan.dofs.at(0).need_verified, alone.dofs.at(0).need_verified);
  EXPECT_GT(with_plan.required.length, 20.0);  // the plan's surge runs span ~19.8 m
  EXPECT_LT(alone.required.length, with_plan.required.length);
  const std::string lines = model::Join(text::VerdictLines(with_plan, tiny), "\n");
  EXPECT_NE(lines.find("a pool that hosts the plan as given: length " +
                       model::Significant(with_plan.required.length, 4)),
            std::string::npos)
      << lines;
  EXPECT_NE(lines.find("the planner's own schedule is hosted from " +
                       model::Significant(tiny.WallToWallFor(alone.dofs.at(0).need), 4) + " m"),
            std::string::npos)
      << lines;
}

// The other way round: a plan made for a 40 m pool judged in ROMEO's own (20 m free), where the
// planner's own schedule is hosted. Only the plan fails: no larger pool is searched for the
// planner (its schedule fits here), the DOF line and the pool line say so, and `required` is
// the plan's travel.
TEST(PoolVerdict, APlanTooLongForAPoolThatHostsThePlannerIsThePlansFailureOnly) {
  const model::Vehicle v = testing::Romeo();
  const model::Pool romeo = testing::RomeoPool();
  model::Pool long_pool = romeo;
  long_pool.length = 40.0;
  ScheduleOptions so;
  so.dofs = {Dof::kSurge};
  const ScheduleResult made_for_40 = PlanSchedule(v, long_pool, so);
  const PoolVerdict verdict = JudgePool(v, romeo, so, &made_for_40.schedule);
  ASSERT_FALSE(verdict.hosted) << text::VerdictSentence(verdict, romeo);
  const DofVerdict& surge = verdict.dofs.at(0);
  EXPECT_FALSE(surge.need_verified);  // nothing planned for it: the planner is hosted here
  EXPECT_LE(surge.need, romeo.FreeTravel(Dof::kSurge));
  EXPECT_GT(verdict.required.length, romeo.length);
  const std::string lines = model::Join(text::VerdictLines(verdict, romeo), "\n");
  EXPECT_NE(lines.find("the planner's own schedule is hosted here; the plan's trials need"),
            std::string::npos)
      << lines;
  EXPECT_NE(lines.find("a pool that hosts the plan as given"), std::string::npos) << lines;
  EXPECT_NE(lines.find("(the planner's own schedule is hosted in this pool)"), std::string::npos)
      << lines;
}

// "To this precision": the verdict judges at the loop's target. ROMEO heave in its
// own pool (2 m of free depth), over the whole a priori box, reaches 15% (hosted) but not 5%:
// at some point of the box the loop's next trial gives the parameters still above the target
// (η, kq) less than the target needs per trial, so the loop would
// need more than max_trials_to_target = 5 of them: the verdict says so, with the limit (depth)
// and a deeper pool that lifts it, confirmed by planning it there. (Before each trial's initial
// state was profiled out of its information, docs/planning.md, the short trials counted a known
// start as information and 5% was reached; 2% was the example then.)
TEST(PoolVerdict, JudgedAtTheLoopsTarget) {
  const model::Vehicle v = testing::Romeo();
  ScheduleOptions so;
  so.dofs = {Dof::kHeave};
  VerdictOptions no_points;
  no_points.judge_points = false;
  so.precision.target_percent = 15.0;
  const PoolVerdict at15 = JudgePool(v, testing::RomeoPool(), so, nullptr, no_points);
  const std::string sentence15 = text::VerdictSentence(at15, testing::RomeoPool());
  EXPECT_EQ(at15.hostability, Hostability::kAll) << sentence15;
  EXPECT_NE(sentence15.find(" to 15% "), std::string::npos) << sentence15;
  so.precision.target_percent = 5.0;
  const PoolVerdict at5 = JudgePool(v, testing::RomeoPool(), so, nullptr, no_points);
  ASSERT_EQ(at5.dofs.size(), 1u);
  const DofVerdict& heave = at5.dofs[0];
  EXPECT_FALSE(heave.hosted);
  EXPECT_TRUE(heave.below_target);
  const std::string reason = text::DofReason(at5, heave, testing::RomeoPool());
  EXPECT_EQ(heave.limit, PoolLimit::kDepth) << reason;
  EXPECT_TRUE(heave.need_verified) << reason;
  EXPECT_GT(heave.need, testing::RomeoPool().FreeTravel(Dof::kHeave));
  // The loop's rule: the trial it would run next needs more than max_trials_to_target such
  // trials, so its per-trial σ is above what the target needs.
  EXPECT_GT(heave.reach.trials, so.precision.max_trials_to_target);
  EXPECT_GT(heave.reach.per_trial_percent, heave.reach.needed_percent);
  EXPECT_NE(reason.find("not to the target 5%"), std::string::npos) << reason;
  const std::string sentence5 = text::VerdictSentence(at5, testing::RomeoPool());
  EXPECT_NE(sentence5.find(" to 5% "), std::string::npos) << sentence5;
}

TEST(PoolVerdict, VsorAndUrisAgree) {
  CheckVerdict(CaseVehicle("vsor"), CasePool("vsor"),
               {Dof::kSurge, Dof::kSway, Dof::kHeave, Dof::kYaw}, "vsor");
  CheckVerdict(CaseVehicle("uris"), CasePool("uris"),
               {Dof::kSurge, Dof::kHeave, Dof::kPitch, Dof::kYaw}, "uris");
}

// The verdict of a pool that hosts a DOF for part of the a priori box says so, and a
// point it calls hosted is hosted for that very vehicle (a degenerate box: every DOF kAll).
void ExpectPart(const model::Vehicle& v, const model::Pool& pool, Dof dof,
                const std::string& what) {
  ScheduleOptions so;
  so.dofs = {dof};
  const PoolVerdict verdict = JudgePool(v, pool, so);
  const std::string sentence = text::VerdictSentence(verdict, pool);
  EXPECT_EQ(verdict.hostability, Hostability::kPart) << what << ": " << sentence;
  EXPECT_NE(sentence.find("for PART of the a priori box"), std::string::npos);
  EXPECT_TRUE(LoopMayRun(verdict));
  ASSERT_EQ(verdict.dofs.size(), 1u);
  VerdictOptions plain;
  plain.need_checks = -1;
  plain.judge_points = false;
  // Points judged on the start-known bound are checked on it too.
  so.planner.start_known = verdict.dofs[0].points_start_known;
  for (const PointVerdict& p : verdict.dofs[0].points) {
    const PoolVerdict at = JudgePool(VehicleAt(v, dof, p.point), pool, so, nullptr, plain);
    EXPECT_EQ(at.hosted, p.hosted) << what << " at " << text::BoxPointLabel(p.point, dof);
  }
}

// "none" is judged on the start-known upper bound of the information (docs/planning.md, "Initial
// state"): ROMEO heave in a 6 × 6 × 3 m pool (1 m of free depth) is hosted at no point of the box
// with each trial's start estimated, at some with it known: part, and its line says which.
TEST(PoolVerdict, HeaveInASixMetrePoolIsPartOnlyOnTheStartKnownBound) {
  const model::Vehicle v = testing::Romeo();
  ExpectPart(v, SixBySixByThree(), Dof::kHeave, "romeo-six heave");
  ScheduleOptions so;
  so.dofs = {Dof::kHeave};
  const PoolVerdict verdict = JudgePool(v, SixBySixByThree(), so);
  ASSERT_EQ(verdict.dofs.size(), 1u);
  const DofVerdict& heave = verdict.dofs[0];
  EXPECT_TRUE(heave.points_start_known);
  const std::string lines = model::Join(text::VerdictLines(verdict, SixBySixByThree()), "\n");
  EXPECT_NE(lines.find("hosted at none with each trial's start estimated"), std::string::npos)
      << lines;
  VerdictOptions plain;
  plain.need_checks = -1;
  plain.judge_points = false;
  for (const PointVerdict& p : heave.points) {  // none hosted with the start estimated
    const PoolVerdict at =
        JudgePool(VehicleAt(v, Dof::kHeave, p.point), SixBySixByThree(), so, nullptr, plain);
    EXPECT_FALSE(at.hosted) << text::BoxPointLabel(p.point, Dof::kHeave);
  }
}

TEST(PoolVerdict, PartOfTheBoxVsorHeaveAndAllOfPayload60) {
  // VSOR's tank made 2.2 m deep (0.2 m of free depth) hosts heave for part of the box: its
  // 1 s sine about a downward offset fits there, the completion sine of the open-water
  // direction (η of vertical-all.pos) not at every corner. In its own tank (1.5 m free) both fit
  // over the whole box (the loop at the light-drag corners converges in 2 trials). The issue's
  // 60 kg payload in a 12 × 8 × 4 m pool: every DOF over the whole box. Heave's completion sine
  // runs down, the direction its first sine does not, so η of heave-all's negative direction is
  // determined (`uuvplan loop` on the case's truth converges in 14 trials).
  model::Pool shallow = CasePool("vsor");
  shallow.depth = 2.2;
  ExpectPart(CaseVehicle("vsor"), shallow, Dof::kHeave, "vsor");
  ScheduleOptions heave;
  heave.dofs = {Dof::kHeave};
  EXPECT_EQ(JudgePool(CaseVehicle("vsor"), CasePool("vsor"), heave).hostability, Hostability::kAll);
  EXPECT_EQ(
      JudgePool(CaseVehicle("payload60"), CasePool("payload60"), ScheduleOptions{}).hostability,
      Hostability::kAll);
}

// The pool it proposes is the smallest found that hosts, not the first guess that does (a
// tester's case: payload60 surge in a 1.8 m pool was told 5.57 m while 3 m pools passed). The
// proposal hosts the DOF; the largest pool it planned that does not host it (printed beside)
// indeed does not, and lies within the 5% bisection tolerance (VerdictOptions::need_tolerance)
// below it. Planning is deterministic; hosting is not strictly monotone in the room given (the
// designs change with it), so "smallest found", not "smallest".
TEST(PoolVerdict, TheProposedPoolIsTheSmallestFoundThatHosts) {
  const model::Vehicle v = CaseVehicle("payload60");
  ScheduleOptions so;
  so.dofs = {Dof::kSurge};
  VerdictOptions no_points;
  no_points.judge_points = false;
  VerdictOptions search = no_points;  // as check-pool searches
  search.need_bisections = kSmallestPoolBisections;
  const auto pool_of_free = [](double free) {  // as ConfirmNeed offers it (1 cm of safety)
    return model::Pool{"probe", 1.2 + free + 0.01, 8.0, 6.0, 0.6};
  };
  std::vector<double> found;
  for (double length : {1.8, 2.5}) {
    const PoolVerdict verdict =
        JudgePool(v, model::Pool{"small", length, 8.0, 6.0, 0.6}, so, nullptr, search);
    ASSERT_FALSE(verdict.hosted) << length;
    const DofVerdict& surge = verdict.dofs.at(0);
    ASSERT_TRUE(surge.need_verified && surge.need_searched) << surge.message;
    EXPECT_TRUE(JudgePool(v, pool_of_free(surge.need), so, nullptr, no_points).hosted);
    EXPECT_FALSE(JudgePool(v, pool_of_free(surge.need_refuted), so, nullptr, no_points).hosted);
    EXPECT_LE(surge.need - surge.need_refuted, 0.05 * surge.need) << length;
    EXPECT_NEAR(verdict.required.length, 1.2 + surge.need, 1e-9);
    found.push_back(surge.need);
  }
  // One answer, not one per pool tried (the tester's 5.57 m against 3.16 m): within 10%.
  EXPECT_NEAR(found[0], found[1], 0.1 * found[0]);
}

TEST(PoolVerdict, NoPointOfTheBoxMeansNoneAndTheLoopRefuses) {
  // ROMEO surge in a 3 m long pool (1 m of free length): no point of the box is hosted. (In
  // the 6 m pool the light, draggy corner is: part, and the loop converges there.)
  ScheduleOptions so;
  so.dofs = {Dof::kSurge};
  const model::Pool tiny{"tiny", 3.0, 6.0, 3.0, 1.0};
  const PoolVerdict verdict = JudgePool(testing::Romeo(), tiny, so);
  EXPECT_EQ(verdict.hostability, Hostability::kNone) << text::VerdictSentence(verdict, tiny);
  EXPECT_FALSE(LoopMayRun(verdict));
}

TEST(PoolVerdict, AStuckLoopInAPartPoolIsOutsideTheHostablePart) {
  PoolVerdict verdict;
  verdict.hostability = Hostability::kPart;
  DofVerdict heave;
  heave.dof = Dof::kHeave;
  heave.hostability = Hostability::kPart;
  verdict.dofs = {heave};
  LoopResult r;
  r.status = LoopStatus::kStuck;
  r.message = "stuck: heave kq is stuck at 20%";
  DofProgress p;
  p.dof = Dof::kHeave;
  r.progress = {p};
  LoopResult converged = r;
  converged.status = LoopStatus::kConverged;
  ReadLoopEnd(verdict, &r);
  EXPECT_EQ(r.status, LoopStatus::kInfeasible);
  EXPECT_EQ(r.outside_part, std::vector<Dof>{Dof::kHeave});
  const std::string message = text::LoopEndMessage(r, verdict, model::Pool{"p", 6, 6, 3, 1});
  EXPECT_NE(message.find("outside the part of the a priori box"), std::string::npos) << message;
  EXPECT_NE(message.find("(the verdict before any trial: Pool p can host the identification of "
                         "heave"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("heave kq is stuck"), std::string::npos);  // the stop's own reason
  ReadLoopEnd(verdict, &converged);
  EXPECT_EQ(converged.status, LoopStatus::kConverged);
  EXPECT_TRUE(converged.outside_part.empty());
  verdict.hostability = Hostability::kAll;  // a hosted pool's stuck loop stays stuck
  LoopResult stuck;
  stuck.status = LoopStatus::kStuck;
  stuck.progress = {p};
  ReadLoopEnd(verdict, &stuck);
  EXPECT_EQ(stuck.status, LoopStatus::kStuck);
}

TEST(PoolVerdict, UrisRotationsPlanWithTheThrustScaledDrag) {
  // Without a drag prior URIS yaw fell back to k = 0.0041 (truth about 2) and
  // could not be planned; the fallback from its 8 N·m of yaw thrust (1 rad/s terminal rate)
  // gives k = 0.727, kq = 7.27 and a plannable yaw and pitch.
  const model::Vehicle v = CaseVehicle("uris");
  const model::APrioriDrag yaw = model::DragOf(v, Dof::kYaw, 0.5);
  EXPECT_EQ(yaw.source, model::DragSource::kThrustRange);
  EXPECT_NEAR(yaw.thrust, 8.0, 1e-9);  // XR reverse 16 N / share 2
  EXPECT_NEAR(yaw.drag.kq, 8.0 / 1.1, 1e-9);
  ScheduleOptions so;
  so.dofs = {Dof::kYaw, Dof::kPitch};
  const ScheduleResult r = PlanSchedule(v, CasePool("uris"), so);
  for (const DofPlan& d : r.dofs) EXPECT_TRUE(d.complete) << d.message;
}

TEST(PoolVerdict, YawTrialsStayWithinTheTetherTurns) {
  // ROMEO's 120 s yaw sine travelled 27.66 rad (4.4 turns); the default tether limit is 3 turns.
  model::Pool pool = testing::RomeoPool();
  ASSERT_DOUBLE_EQ(pool.max_turns, model::Pool::kDefaultMaxTurns);
  pool.max_turns = 1.5;
  ScheduleOptions so;
  so.dofs = {Dof::kYaw};
  const ScheduleResult r = PlanSchedule(testing::Romeo(), pool, so);
  ASSERT_FALSE(r.schedule.trials.empty());
  for (const PlannedTrial& t : r.schedule.trials) {
    EXPECT_LE(IndependentSpan(testing::Romeo(), t.design), 2 * M_PI * 1.5 * 1.005 + 1e-3)
        << t.design.id;
  }
}

// Seeded random vehicles (tests/support/random_vehicle.h): CI runs 4 seeds with 2 DOFs each;
// the full set (20 seeds, 4 DOFs) is `UUVPLAN_VERDICT_SEEDS=20 UUVPLAN_VERDICT_DOFS=4
// build/tests/planner/planner_tests --gtest_filter='PoolVerdict.Random*'` (docs/validation.md).
TEST(PoolVerdict, RandomVehiclesAgreeAndStayInside) {
  const char* seeds_env = std::getenv("UUVPLAN_VERDICT_SEEDS");
  const char* dofs_env = std::getenv("UUVPLAN_VERDICT_DOFS");
  const int seeds = seeds_env ? std::atoi(seeds_env) : 4;
  const int dofs = dofs_env ? std::atoi(dofs_env) : 2;
  int hosted = 0;
  for (int s = 1; s <= seeds; ++s) {
    const uuvplan::testing::RandomCase c = uuvplan::testing::MakeRandomCase(s, dofs);
    CheckVerdict(c.vehicle, c.pool, c.dofs, c.vehicle.name);
    ScheduleOptions so;
    so.dofs = c.dofs;
    hosted += JudgePool(c.vehicle, c.pool, so).hosted ? 1 : 0;
  }
  std::cout << hosted << " of " << seeds << " random pools host their vehicle\n";
}

}  // namespace
}  // namespace uuvplan::planner
