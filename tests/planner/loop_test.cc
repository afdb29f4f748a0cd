// The design–identify loop (planner/loop/design_loop.h) and ref 000's procedure as its yardstick
// (planner/design/paper_procedure.h) on the virtual ROMEO of cases/romeo:
//  - the loop reaches 5% percentile error on m, the drag of interest and every η of surge,
//    heave and yaw in no more pool time than ref 000's procedure, whose own estimators (steady
//    state LS + integral method, §III) leave at least one parameter above 5%;
//  - the loop's estimates agree with the truth within their σ, are deterministic for a seed,
//    and its pool time is Σ durations + pauses;
//  - `next` takes ref 000's order on an empty campaign and reports convergence; budget and
//    bad input are reported (CLI exit codes 4 and 2);
//  - the stop rules: a loop stuck in a small pool stops with its own status naming
//    the pool, never running a design more than twice without new information; URIS surge
//    (whose first trial's m is an a priori fallback) converges within 3σ or refuses; VSOR's
//    overconfident intermediate estimates do not end the loop; the physical ranges and the χ²
//    consistency test on hand-made identifications.
// Runtime: the whole 3-DOF loop and the seed procedure take a few seconds (bench/loop_bench.cc
// prints the same comparison with every iteration, for any seed).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include "planner_test_util.h"
#include "uuvplan/ident/stats/monte_carlo.h"
#include "uuvplan/io/io.h"
#include "uuvplan/planner/design/paper_procedure.h"
#include "uuvplan/planner/design/thrust_limits.h"
#include "uuvplan/planner/determinacy.h"
#include "uuvplan/planner/loop/design_loop.h"

namespace uuvplan::planner {
namespace {

using model::Dof;
using testing::RomeoPath;
using testing::RomeoPool;

// The contract's target: 5% percentile error on every parameter of interest.
constexpr double kTarget = 5.0;

model::Truth RomeoTruth() { return io::ReadTruth(RomeoPath("truth.yaml")); }

const std::vector<Dof>& RomeoDofs() {
  static const std::vector<Dof> dofs = {Dof::kSurge, Dof::kHeave, Dof::kYaw};
  return dofs;
}

// One run of the loop on ROMEO surge, heave and yaw (seed 1), shared by the tests.
const LoopResult& RomeoLoop() {
  static const LoopResult r = [] {
    LoopOptions o;
    o.step.dofs = RomeoDofs();
    o.step.target_percent = kTarget;
    o.seed = 1;
    return RunLoop(RomeoTruth(), RomeoPool(), o);
  }();
  return r;
}

// Ref 000's procedure with its own estimators (Identify without the output-error stage: the
// steady-state LS of eqs. 7-12/20 and the integral method of eqs. 16-19).
const PaperProcedureResult& RomeoPaper() {
  static const PaperProcedureResult r = [] {
    PaperProcedureOptions o;
    o.dofs = RomeoDofs();
    o.seed = 1;
    o.identify.refine = false;
    return RunPaperProcedure(RomeoTruth(), RomeoPool(), o);
  }();
  return r;
}

const DofProgress* Find(const std::vector<DofProgress>& progress, Dof dof) {
  for (const auto& p : progress) {
    if (p.dof == dof) return &p;
  }
  return nullptr;
}

// The information of independent trials adds: 1/σ² = 1/σ_now² + n·(1/σ_after² − 1/σ_now²).
// With nothing known yet (σ_now = ∞; `next` on an insignificant η once said "σ - → 28, about
// 0 such trials to the target") it takes n = (σ_after/σ_target)² of them, not 0.
TEST(TrialsToTargetTest, InformationAddsAndNothingKnownIsItsLimit) {
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_DOUBLE_EQ(TrialsToTarget(2.0, 1.0, 1.0), 1.0);  // one trial takes 2 to 1
  EXPECT_DOUBLE_EQ(TrialsToTarget(2.0, 1.0, 0.5), 5.0);  // (4/0.25 − 1)/(4 − 1)
  EXPECT_DOUBLE_EQ(TrialsToTarget(inf, 28.0, 0.016), std::pow(28.0 / 0.016, 2));
  EXPECT_DOUBLE_EQ(TrialsToTarget(inf, 0.01, 0.02), 0.25);  // one trial is more than enough
  EXPECT_EQ(TrialsToTarget(0.5, 0.5, 0.1), inf);            // adds nothing
  EXPECT_EQ(TrialsToTarget(0.05, 0.04, 0.1), 0.0);          // already there
}

TEST(DesignLoopTest, RomeoReachesFivePercentInLessPoolTimeThanSeedProcedure) {
  const LoopResult& loop = RomeoLoop();
  const PaperProcedureResult& paper = RomeoPaper();
  ASSERT_EQ(loop.status, LoopStatus::kConverged) << loop.message;
  EXPECT_TRUE(loop.converged);
  // Every parameter of interest of every DOF estimated, below the target.
  ASSERT_EQ(loop.progress.size(), RomeoDofs().size());
  for (const auto& p : loop.progress) {
    EXPECT_TRUE(p.converged) << model::DofName(p.dof) << " " << p.worst;
    for (const auto& q : p.interest) {
      EXPECT_TRUE(q.estimated) << q.name;
      EXPECT_LE(q.percent, kTarget) << model::DofName(p.dof) << " " << q.name;
    }
  }
  // The seed's procedure with its own estimators leaves at least one parameter of interest
  // above 5% (on seed 1: heave η pulling up near 20%, ref 000 Table II reports 4.1% from the
  // real heave data; the virtual one has only 2 m of depth and short legs).
  int above = 0;
  std::string worst;
  for (const auto& p : paper.progress) {
    for (const auto& q : p.interest) {
      if (!(q.percent <= kTarget)) {
        ++above;
        worst += std::string(model::DofName(p.dof)) + " " + q.name + " " +
                 std::to_string(q.percent) + "%; ";
      }
    }
  }
  EXPECT_GE(above, 1) << "the seed procedure met the target everywhere";
  // The loop needs no more pool time (trial durations + 60 s pauses, same accounting).
  EXPECT_LE(loop.pool_time, paper.pool_time) << "loop " << loop.pool_time << " s, seed procedure "
                                             << paper.pool_time << " s (" << worst << ")";
  // And per DOF too.
  for (Dof dof : RomeoDofs()) {
    ASSERT_TRUE(loop.dof_pool_time.count(dof));
    ASSERT_TRUE(paper.dof_pool_time.count(dof));
    EXPECT_LE(loop.dof_pool_time.at(dof), paper.dof_pool_time.at(dof)) << model::DofName(dof);
  }
}

TEST(DesignLoopTest, LoopEstimatesAgreeWithTheTruth) {
  const LoopResult& loop = RomeoLoop();
  const model::Truth truth = RomeoTruth();
  for (const auto& p : loop.progress) {
    for (const auto& q : p.interest) {
      ASSERT_TRUE(q.estimated) << q.name;
      const double v = ident::TrueParameter(truth, p.dof, q.name);
      // 4σ: 16 parameters, a Gaussian error beyond 4σ has probability 6e-5 each; the σ are
      // the identification's (checked against Monte Carlo by the ident tests). A diverged fit
      // or a design that confounds η with m would show here as many σ off.
      EXPECT_LE(std::abs(q.value - v), 4.0 * q.sigma)
          << model::DofName(p.dof) << " " << q.name << " = " << q.value << " ± " << q.sigma
          << ", true " << v;
    }
  }
}

TEST(DesignLoopTest, DragOfInterestFollowsSignificance) {
  // Yaw's true kq is 0 (Table III, low speed): its drag of interest is k. Surge and heave have
  // a significant kq (Tables II, IV): kq.
  const LoopResult& loop = RomeoLoop();
  const DofProgress* yaw = Find(loop.progress, Dof::kYaw);
  const DofProgress* surge = Find(loop.progress, Dof::kSurge);
  const DofProgress* heave = Find(loop.progress, Dof::kHeave);
  ASSERT_TRUE(yaw && surge && heave);
  EXPECT_EQ(yaw->interest[1].name, "k");
  EXPECT_EQ(surge->interest[1].name, "kq");
  EXPECT_EQ(heave->interest[1].name, "kq");
  // Every installation coefficient of the DOF's mappings is of interest (Table I directions
  // that are not open water): surge 4, heave 1, yaw 4.
  EXPECT_EQ(surge->interest.size(), 2u + 4u);
  EXPECT_EQ(heave->interest.size(), 2u + 1u);
  EXPECT_EQ(yaw->interest.size(), 2u + 4u);
}

TEST(DesignLoopTest, PoolTimeIsDurationsPlusPauses) {
  const LoopResult& loop = RomeoLoop();
  ASSERT_FALSE(loop.iterations.empty());
  const double pause = PlannerOptions{}.pause_s;
  double t = 0.0;
  for (std::size_t i = 0; i < loop.iterations.size(); ++i) {
    const auto& it = loop.iterations[i];
    EXPECT_DOUBLE_EQ(it.start, i == 0 ? 0.0 : t + pause);
    t = it.start + it.trial.design.duration;
    EXPECT_DOUBLE_EQ(it.pool_time, t);
    EXPECT_EQ(it.index, static_cast<int>(i));
  }
  EXPECT_DOUBLE_EQ(loop.pool_time, t);
  // Trial ids are unique: they name the trials' log files.
  std::set<std::string> ids;
  for (const auto& it : loop.iterations) EXPECT_TRUE(ids.insert(it.trial.design.id).second);
}

TEST(DesignLoopTest, SeedOrderFirstThenSequentialDesign) {
  // Each DOF starts with a trial of its a priori schedule (ref 000 §III: steady runs first);
  // at least one later trial is designed from the estimates.
  const LoopResult& loop = RomeoLoop();
  std::set<Dof> seen;
  int sequential = 0;
  for (const auto& it : loop.iterations) {
    if (seen.insert(it.dof).second) EXPECT_EQ(it.source, "a priori schedule") << it.trial.design.id;
    if (it.source == "sequential design") ++sequential;
  }
  EXPECT_GE(sequential, 1);
}

TEST(DesignLoopTest, DeterministicForASeed) {
  LoopOptions o;
  o.step.dofs = {Dof::kSurge};
  o.seed = 7;
  const model::Truth truth = RomeoTruth();
  const LoopResult a = RunLoop(truth, RomeoPool(), o);
  const LoopResult b = RunLoop(truth, RomeoPool(), o);
  ASSERT_EQ(a.iterations.size(), b.iterations.size());
  for (std::size_t i = 0; i < a.iterations.size(); ++i) {
    EXPECT_EQ(a.iterations[i].trial.design.id, b.iterations[i].trial.design.id);
    const auto& pa = a.iterations[i].params.at(Dof::kSurge);
    const auto& pb = b.iterations[i].params.at(Dof::kSurge);
    ASSERT_EQ(pa.size(), pb.size());
    for (std::size_t j = 0; j < pa.size(); ++j) {
      EXPECT_EQ(pa[j].value, pb[j].value) << pa[j].name;  // bit for bit
    }
  }
  // Another seed draws other noise: the first estimates differ.
  o.seed = 8;
  const LoopResult c = RunLoop(truth, RomeoPool(), o);
  ASSERT_FALSE(c.iterations.empty());
  EXPECT_NE(c.iterations[0].params.at(Dof::kSurge)[0].value,
            a.iterations[0].params.at(Dof::kSurge)[0].value);
}

TEST(DesignLoopTest, BudgetSpentIsReported) {
  LoopOptions o;
  o.step.dofs = {Dof::kSurge};
  o.budget = 2;  // surge needs at least 4 trials: every η needs its mapping and direction
  const LoopResult r = RunLoop(RomeoTruth(), RomeoPool(), o);
  EXPECT_EQ(r.status, LoopStatus::kBudgetSpent);
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(r.iterations.size(), 2u);
  EXPECT_NE(r.message.find("budget"), std::string::npos) << r.message;
}

TEST(DesignLoopTest, NextOnAnEmptyCampaignStartsWithAnOpenWaterRun) {
  model::Campaign c;
  c.path = "<memory>";
  c.vehicle = testing::Romeo();
  DesignLoopOptions o;
  o.dofs = {Dof::kSurge};
  const NextStepResult r = NextStep(c, RomeoPool(), o);
  ASSERT_EQ(r.status, NextStatus::kTrial) << r.message;
  EXPECT_EQ(r.dof, Dof::kSurge);
  EXPECT_EQ(r.source, "a priori schedule");
  ASSERT_EQ(r.progress.size(), 1u);
  EXPECT_TRUE(std::isinf(r.progress[0].worst_percent));
  // Ref 000 §II-A: η must be known for one mapping — the first run pushes forward in
  // surge-front or backward in surge-rear (Table I's open-water directions).
  const model::TrialDesign& d = r.trial.design;
  bool open_water = false;
  auto check = [&](const std::string& m, double f) {
    open_water |= (m == "surge-front" && f > 0) || (m == "surge-rear" && f < 0);
  };
  if (d.kind == model::TrialKind::kSegments) {
    for (const auto& s : d.segments) check(s.mapping.empty() ? d.mapping : s.mapping, s.force);
  } else {
    check(d.mapping, d.kind == model::TrialKind::kSine ? d.offset : d.force);
  }
  EXPECT_TRUE(open_water) << d.id;
}

TEST(DesignLoopTest, NextAfterConvergenceAsksForNothing) {
  const LoopResult& loop = RomeoLoop();
  DesignLoopOptions o;
  o.dofs = RomeoDofs();
  const NextStepResult r = NextStep(loop.campaign, RomeoPool(), o);
  // NextStep identifies the whole campaign at once; the loop identified DOF by DOF: the same
  // estimates, so the same verdict.
  EXPECT_EQ(r.status, NextStatus::kConverged) << r.message;
}

TEST(PaperProcedureTest, EncodesSeedSectionIVD) {
  const model::Vehicle v = testing::Romeo();
  const model::Pool pool = RomeoPool();
  PaperProcedureOptions o;
  std::vector<std::string> notes;
  // Surge: steady legs in all six mapping directions, then the 35 + 25 sin(2π t / 26 s) sine
  // in surge-front (§IV-D).
  const auto surge = PaperProcedureDesigns(v, pool, Dof::kSurge, o, &notes);
  ASSERT_FALSE(surge.empty());
  std::set<std::pair<std::string, int>> directions;
  for (const auto& d : surge) {
    if (d.kind == model::TrialKind::kSteady) directions.insert({d.mapping, d.force > 0 ? 1 : -1});
    for (const auto& s : d.segments) directions.insert({s.mapping, s.force > 0 ? 1 : -1});
  }
  EXPECT_EQ(directions.size(), 6u);
  const auto& sine = surge.back();
  ASSERT_EQ(sine.kind, model::TrialKind::kSine);
  EXPECT_EQ(sine.mapping, "surge-front");
  EXPECT_DOUBLE_EQ(sine.offset, 35.0);
  EXPECT_DOUBLE_EQ(sine.amplitude, 25.0);
  EXPECT_NEAR(2 * M_PI / sine.omega, 26.0, 1e-12);
  // "a couple of sinusoidal periods in a maneuvering space of about 20 m"
  EXPECT_GE(sine.duration * sine.omega / (2 * M_PI), 2.0);
  // Heave: five experiments with 0..4 ballast steps, up and down legs, no sine.
  const auto heave = PaperProcedureDesigns(v, pool, Dof::kHeave, o, &notes);
  std::set<int> ballast;
  for (const auto& d : heave) {
    EXPECT_NE(d.kind, model::TrialKind::kSine);
    ballast.insert(d.ballast_steps);
  }
  EXPECT_EQ(ballast, (std::set<int>{0, 1, 2, 3, 4}));
  // Yaw: -5 + 4 sin(2π t / 24 s) with the front-right/rear-left thrusters (open water
  // counter-clockwise), steady yaw rates within ±20 °/s.
  const auto yaw = PaperProcedureDesigns(v, pool, Dof::kYaw, o, &notes);
  ASSERT_FALSE(yaw.empty());
  EXPECT_EQ(yaw.back().mapping, "yaw-fr-rl");
  EXPECT_DOUBLE_EQ(yaw.back().offset, -5.0);
  EXPECT_DOUBLE_EQ(yaw.back().amplitude, 4.0);
  EXPECT_NEAR(2 * M_PI / yaw.back().omega, 24.0, 1e-12);
  // Steady torques: the a priori steady rate φ/k (linear a priori yaw drag, Table III) within
  // 20 °/s, unless the mapping's smallest working torque (min_thrust) is larger.
  const double k = v.priors.at(Dof::kYaw).drag->k;
  for (const auto& d : yaw) {
    std::vector<model::SegmentDesign> legs = d.segments;
    if (d.kind == model::TrialKind::kSteady) legs.push_back({d.force, d.duration, d.mapping});
    for (const auto& s : legs) {
      const int mi = v.MappingIndex(s.mapping.empty() ? d.mapping : s.mapping);
      const double min_abs = DirectionForceRange(v, mi, s.force > 0 ? 1 : -1).min_abs;
      EXPECT_LE(std::abs(s.force), std::max(k * 20.0 * M_PI / 180, min_abs) * (1 + 1e-9))
          << d.id << " " << s.force;
    }
  }
}

// ROMEO's pool shrunk to 5 × 5 × 5 m with a 1 m margin (3 m free each way).
model::Pool FiveMetrePool() {
  model::Pool small = RomeoPool();
  small.name = "5 m";
  small.length = small.width = small.depth = 5.0;
  small.margin = 1.0;
  return small;
}

// ROMEO surge in a 5 × 5 × 5 m pool (3 m of free length) once re-planned the same
// 2.8 N leg 22 times. Now: a distinct status whose sentence names the binding limit (the pool,
// checked by planning again in a pool with twice the free travel), and no design runs more
// than twice without new information. The case ran with ref 000's model selection in
// the identification (k dropped as insignificant, kq alone explaining the drag at the pool's
// low speeds; `--seed-selection` since the default keeps a k correlated with kq), which the
// loop no longer uses by default (LoopIdentifyOptions); it is kept here
// to exercise the stop rule on the issue's own case. ~1 s.
TEST(StopRulesTest, SmallPoolStopsStuckNamingThePool) {
  const model::Pool small = FiveMetrePool();
  LoopOptions o;
  o.step.dofs = {Dof::kSurge};
  o.step.identify.selection.prune_insignificant = true;
  // the seed's rule drops k although it is correlated
  o.step.identify.selection.drop_correlation = ident::kSeedDropCorrelation;
  // The families (single-mapping sines and legs): a mapping-switched trial
  // oscillates in place and determines surge in 3 m (the loop converges), so the pool limit this
  // test exercises exists only without them.
  o.step.schedule.sine.families.clear();
  const LoopResult r = RunLoop(RomeoTruth(), small, o);
  ASSERT_EQ(r.status, LoopStatus::kStuck) << r.message;
  EXPECT_FALSE(r.converged);
  EXPECT_NE(r.message.find("pool size"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("twice the free travel"), std::string::npos) << r.message;
  EXPECT_LT(r.iterations.size(), 12u);  // the old loop ran out its budget of 40
  for (std::size_t i = 0; i < r.iterations.size(); ++i) {
    int idle_repeats = 0;
    for (std::size_t j = 0; j < i; ++j) {
      const auto& a = r.iterations[j].trial.design;
      const auto& b = r.iterations[i].trial.design;
      if (!r.iterations[j].new_information && a.kind == b.kind && a.mapping == b.mapping &&
          std::abs(a.force - b.force) <= 0.05 * std::abs(b.force)) {
        ++idle_repeats;
      }
    }
    EXPECT_LE(idle_repeats, 2) << r.iterations[i].trial.design.id;
    if (r.iterations[i].source == "sequential design") {
      EXPECT_FALSE(r.iterations[i].sigma.empty()) << "predicted vs achieved σ reported";
      EXPECT_FALSE(r.iterations[i].candidates.empty()) << "the candidate's gain reported";
    }
  }
}

// The same 5 m pool with the loop's identification of the full model (no model selection,
// LoopIdentifyOptions): the trials that were stuck on kq determine k and kq together, and the
// loop converges on estimates within 3σ of the truth (m 902 ± 9.7 kg for 890, kq 295 ± 14 for
// 306 on seed 1). RunLoop is run although the pool verdict does not host surge there (the
// verdict judges over the a priori box; `loop` refuses before any trial, exit 1). ~1 s.
TEST(StopRulesTest, SmallPoolConvergesWithinThreeSigmaOnTheFullModel) {
  const model::Pool small = FiveMetrePool();
  LoopOptions o;
  o.step.dofs = {Dof::kSurge};
  const model::Truth truth = RomeoTruth();
  const LoopResult r = RunLoop(truth, small, o);
  ASSERT_EQ(r.status, LoopStatus::kConverged) << r.message;
  const DofProgress* p = Find(r.progress, Dof::kSurge);
  ASSERT_NE(p, nullptr);
  for (const auto& q : p->interest) {
    const double truth_value = truth.dofs.at(Dof::kSurge).params.at(q.name);
    EXPECT_LE(std::abs(q.value - truth_value), 3.0 * q.sigma) << q.name;  // 3σ
  }
}

// URIS surge used to "converge" after one 0.8 N trial on m = 184 ± 8 kg (true 59 kg)
// with k held at its prior. A held parameter is no information: converge within 3σ of the
// truth, or stop non-zero with a reason. ~0.4 s.
TEST(StopRulesTest, UrisSurgeConvergesWithinThreeSigmaOrRefuses) {
  const model::Truth truth = io::ReadTruth(testing::CasePath("uris", "truth.yaml"));
  LoopOptions o;
  o.step.dofs = {Dof::kSurge};
  const LoopResult r = RunLoop(truth, io::ReadPool(testing::CasePath("uris", "pool.yaml")), o);
  ASSERT_FALSE(r.iterations.empty());
  const DofProgress* first = Find(r.iterations.front().progress, Dof::kSurge);
  ASSERT_NE(first, nullptr);
  EXPECT_FALSE(first->converged) << "one trial with k held at its prior";
  if (!r.converged) {
    EXPECT_FALSE(r.message.empty());
    return;
  }
  const ident::ParameterEstimate* m = r.estimates.Find(Dof::kSurge)->Param("m");
  ASSERT_NE(m, nullptr);
  const double truth_m = ident::TrueParameter(truth, Dof::kSurge, "m");
  EXPECT_LE(std::abs(m->value - truth_m), 3 * m->sigma) << m->value << " ± " << m->sigma;
}

// VSOR's intermediate estimates are overconfident (yaw kq 2948 ± 39 for a true 683);
// the loop once converged on the trial after it. Convergence needs the newest trial consistent
// with the estimate before it, and then every final estimate is within 3σ of the truth. ~2 s.
TEST(StopRulesTest, VsorConvergesOnlyOnConsistentEstimates) {
  const model::Truth truth = io::ReadTruth(testing::CasePath("vsor", "truth.yaml"));
  const LoopResult r =
      RunLoop(truth, io::ReadPool(testing::CasePath("vsor", "pool.yaml")), LoopOptions{});
  ASSERT_TRUE(r.converged) << r.message;
  for (const auto& p : r.progress) {
    EXPECT_TRUE(p.consistency.tested && p.consistency.consistent) << model::DofName(p.dof);
    for (const auto& q : p.interest) {
      const double t = ident::TrueParameter(truth, p.dof, q.name);
      // 3σ: the criterion (a two-sided normal tail of 0.27%).
      EXPECT_LE(std::abs(q.value - t), 3 * q.sigma) << model::DofName(p.dof) << " " << q.name;
    }
  }
}

TEST(StopRulesTest, PhysicalRangesComeFromTheParameterFamilies) {
  const model::Vehicle v = testing::Romeo();  // 450 kg dry
  EXPECT_NE(NonPhysical(v, Dof::kSurge, "kq", -1.0), "");
  EXPECT_NE(NonPhysical(v, Dof::kSurge, "k", -0.1), "");
  EXPECT_EQ(NonPhysical(v, Dof::kSurge, "kq", 0.0), "");
  EXPECT_NE(NonPhysical(v, Dof::kSurge, "eta.surge-front.neg", 1.3), "");
  EXPECT_NE(NonPhysical(v, Dof::kSurge, "eta.surge-front.neg", 0.0), "");
  EXPECT_EQ(NonPhysical(v, Dof::kSurge, "eta.surge-front.neg", 1.1), "");
  EXPECT_NE(NonPhysical(v, Dof::kSurge, "m", 400.0), "");  // below the dry mass
  EXPECT_EQ(NonPhysical(v, Dof::kSurge, "m", 890.0), "");
  // A rotational inertia in a vehicle file is computed, not weighed: no bound (ROMEO's 93.75
  // kg·m² box against the seed's measured 84).
  EXPECT_EQ(NonPhysical(v, Dof::kYaw, "m", 84.0), "");
}

// A hand-made identification: m, kq estimated with σ, diagonal covariance.
ident::DofIdentification Identification(double m, double sm, double kq, double skq) {
  ident::DofIdentification id;
  id.dof = Dof::kSurge;
  id.status = ident::IdentifyStatus::kOk;
  id.parameter_names = {"m", "kq"};
  id.theta = Eigen::Vector2d(m, kq);
  id.covariance = Eigen::Vector2d(sm * sm, skq * skq).asDiagonal();
  id.params =
      ident::MakeEstimates(id.parameter_names, id.theta, id.covariance,
                           {ident::ParameterState::kEstimated, ident::ParameterState::kEstimated});
  return id;
}

TEST(StopRulesTest, ConsistencyTestAndRefusal) {
  // 450 kg dry, one open-water mapping: m and kq are the only parameters of interest.
  const model::Vehicle v = testing::SimpleVehicle(450, 0, 300, true, false);
  DesignLoopOptions o;
  const auto before = Identification(900, 10, 300, 10);
  // m moved 10 kg against a combined σ of 12.8 kg: χ² = 0.61 on 2 parameters, p = 0.74.
  const auto near = Identification(910, 8, 300, 8);
  const DofProgress ok = EvaluateProgress(v, Dof::kSurge, &near, 2, o, &before);
  EXPECT_TRUE(ok.consistency.tested && ok.consistency.consistent) << ok.consistency.text;
  // kq 2948 ± 39 then 642 ± 24 (VSOR yaw): 50 combined σ.
  const auto a = Identification(900, 10, 2948, 39), b = Identification(900, 10, 642, 24);
  const DofProgress bad = EvaluateProgress(v, Dof::kSurge, &b, 2, o, &a);
  EXPECT_TRUE(bad.consistency.tested);
  EXPECT_FALSE(bad.consistency.consistent);
  EXPECT_EQ(bad.consistency.worst, "kq");
  EXPECT_TRUE(bad.precise);
  EXPECT_FALSE(bad.converged);
  // Precise and consistent, but m below the 450 kg dry mass: refused, never converged.
  const auto light1 = Identification(400, 2, 300, 3), light2 = Identification(401, 2, 300, 3);
  const DofProgress light = EvaluateProgress(v, Dof::kSurge, &light2, 2, o, &light1);
  EXPECT_FALSE(light.converged);
  EXPECT_NE(light.refusal, "");
  // Without an earlier estimate nothing is confirmed yet.
  EXPECT_FALSE(EvaluateProgress(v, Dof::kSurge, &near, 1, o).converged);
}

}  // namespace
}  // namespace uuvplan::planner
