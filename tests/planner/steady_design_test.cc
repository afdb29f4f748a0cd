// Steady-state runs and legs (ref 000 §III-A, Table I) on ROMEO: every leg settles and holds
// its speed for every point of the a priori box, no thruster reverses, legs fit the pool, and
// the pool that cannot host a run says so with the size it would need.
#include "uuvplan/planner/design/steady_design.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numeric>

#include "planner_test_util.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/mapping.h"
#include "uuvplan/planner/design/fisher_information.h"
#include "uuvplan/planner/design/seed_rules.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner {
namespace {

TEST(EfficientRounding, ApportionsExactlyAndKeepsTheSupport) {
  EXPECT_EQ(EfficientRounding({0.5, 0.3, 0.2}, 10), (std::vector<int>{5, 3, 2}));
  // Pukelsheim & Rieder: ceil((N - p/2)·w) then adjust; N = 5, w = (0.6, 0.2, 0.2):
  // ceil(3.5·w) = (3, 1, 1) already sums to 5.
  EXPECT_EQ(EfficientRounding({0.6, 0.2, 0.2}, 5), (std::vector<int>{3, 1, 1}));
  // Tiny weights (< 1e-3 of the largest) are not support points.
  const std::vector<int> n = EfficientRounding({0.49, 1e-6, 0.51}, 7);
  EXPECT_EQ(std::accumulate(n.begin(), n.end(), 0), 7);
  EXPECT_EQ(n[1], 0);
  // No support at all (a failed approximate design): no runs, rather than an index of -1.
  EXPECT_EQ(EfficientRounding({0.0, 0.0}, 4), (std::vector<int>{0, 0}));
}

class RomeoSteady : public ::testing::Test {
 protected:
  // For each check point of the box (m, drag and eta axes): in every leg of `d`, the speed over
  // the leg's last min_hold_s seconds stays within settle_tolerance of the steady speed of
  // ref 000 eq. 7 (k·ξ + kq·ξ|ξ| = η·φ + bias).
  void ExpectEveryLegHolds(const DofPlanningProblem& ctx, const model::TrialDesign& d,
                           const SteadyDesignOptions& o) {
    std::vector<model::SegmentDesign> segs = d.segments;
    if (d.kind == model::TrialKind::kSteady) segs = {{d.force, d.duration, d.mapping}};
    const auto& tm = ctx.ModelFor(d);
    const auto input = model::MakeExcitation(v_, d);
    const double dt = 0.05;
    for (const auto& th : tm.check_thetas) {
      const PositionTrace tr = TracePosition(*tm.model, th, *input, d.duration, dt, 0.05);
      double t0 = 0.0;
      for (const auto& s : segs) {
        const std::string mapping = s.mapping.empty() ? d.mapping : s.mapping;
        const int mi = v_.MappingIndex(mapping);
        const auto dir = s.force >= 0 ? model::Direction::kPos : model::Direction::kNeg;
        const int ie = v_.mappings[mi].IsOpenWater(dir)
                           ? -1
                           : tm.model->ParameterIndex(model::EtaName(mapping, dir));
        const double f = (ie >= 0 ? th[ie] : 1.0) * s.force;
        const double xs = std::copysign(SteadySpeed(th[1], th[2], std::abs(f)), f);
        const double t1 = t0 + s.duration;
        for (std::size_t i = 0; i < tr.velocity.size(); ++i) {
          const double t = i * dt;
          if (t < t1 - o.min_hold_s + 1e-9 || t > t1 - 1e-9) continue;
          // The band the planner settles to, plus the 0.5% the hold-window placement on the
          // planner's coarser grid may add.
          EXPECT_LE(std::abs(tr.velocity[i] - xs), (o.settle_tolerance + 0.005) * std::abs(xs))
              << d.id << " leg " << s.force << " " << mapping << " at t " << t << " m " << th[0];
        }
        t0 = t1;
      }
    }
  }
  model::Vehicle v_ = testing::Romeo();
  model::Pool pool_ = testing::RomeoPool();
};

TEST_F(RomeoSteady, SurgeLegsSettleHoldFitAndNeverReverse) {
  const auto ctx = DofPlanningProblem::APriori(v_, pool_, model::Dof::kSurge, {}, nullptr);
  const SteadyDesignOptions o;
  const SteadyDesignResult r = DesignSteady(*ctx, o, {}, "surge-steady");
  ASSERT_EQ(r.status, DesignStatus::kOk) << r.message;
  ASSERT_FALSE(r.trials.empty());
  // Auto size: 7 parameters besides m (k, kq, bias, four eta) + 2 = 9 legs from the rounding,
  // plus one for any direction the approximate design weighs but the rounding left out
  // (6 directions at most).
  EXPECT_GE(r.legs.size(), 9u);
  EXPECT_LE(r.legs.size(), 15u);
  double weight = 0.0;
  for (double w : r.weights) weight += w;
  EXPECT_NEAR(weight, 1.0, 1e-4);  // Σw <= 1 is active: more runs are always more information
  int segments = 0;
  for (std::size_t i = 0; i < r.trials.size(); ++i) {
    const auto& d = r.trials[i].design;
    EXPECT_TRUE(r.checks[i].feasible) << d.id;
    EXPECT_LE(r.checks[i].span, 20.0 + 1e-9) << d.id;
    const auto input = model::MakeExcitation(v_, d);
    const ThrustCheck tc = CheckThrust(v_, *input, d.duration);
    EXPECT_TRUE(tc.ok()) << d.id << ": " << (tc.reasons.empty() ? "" : tc.reasons.front());
    EXPECT_LE(d.duration, 240.0);
    if (d.kind == model::TrialKind::kSegments) {
      ++segments;
      for (std::size_t k = 1; k < d.segments.size(); ++k) {  // legs go back and forth
        EXPECT_LT(d.segments[k].force * d.segments[k - 1].force, 0.0) << d.id;
      }
    }
    ExpectEveryLegHolds(*ctx, d, o);
  }
  EXPECT_GE(segments, 1) << "a forward and a backward leg in different mappings share a trial";
  // Every eta of the DOF is reached: every mapping and direction has a leg.
  std::vector<int> informed =
      InformedParameters(RelativeInformation(r.information[0], ctx->design_thetas()[0]));
  EXPECT_EQ(informed.size(), static_cast<std::size_t>(ctx->model().num_parameters()));
}

TEST_F(RomeoSteady, YawLegsChainWithoutAPoolLimit) {
  const auto ctx = DofPlanningProblem::APriori(v_, pool_, model::Dof::kYaw, {}, nullptr);
  const SteadyDesignOptions o;
  const SteadyDesignResult r = DesignSteady(*ctx, o, {}, "yaw-steady");
  ASSERT_EQ(r.status, DesignStatus::kOk) << r.message;
  bool chained = false;
  for (std::size_t i = 0; i < r.trials.size(); ++i) {
    const auto& d = r.trials[i].design;
    chained = chained || d.segments.size() >= 2;
    EXPECT_TRUE(r.checks[i].feasible) << d.id;
    ExpectEveryLegHolds(*ctx, d, o);
  }
  EXPECT_TRUE(chained);
}

TEST_F(RomeoSteady, HeaveDoesNotFitTwoMetresAndSaysWhatWould) {
  // Free depth 5 - 2·1.5 = 2 m. The smallest no-reversal force (min_thrust 2 N / share 0.25 =
  // 8 N) still drives ROMEO about 5 m before its speed settles and is held 10 s.
  const auto ctx = DofPlanningProblem::APriori(v_, pool_, model::Dof::kHeave, {}, nullptr);
  const SteadyDesignResult r = DesignSteady(*ctx, SteadyDesignOptions{}, {}, "heave-steady");
  EXPECT_EQ(r.status, DesignStatus::kInfeasible);
  EXPECT_NE(r.message.find("vertical-all"), std::string::npos) << r.message;
  EXPECT_NE(r.message.find("needs"), std::string::npos) << r.message;
  EXPECT_GT(r.required_travel, 2.0);
  // In a pool deep enough for that travel, the steady runs of heave can be planned.
  model::Pool deep = pool_;
  deep.depth = r.required_travel + 2 * deep.margin + 0.1;
  const auto ctx2 = DofPlanningProblem::APriori(v_, deep, model::Dof::kHeave, {}, nullptr);
  const SteadyDesignResult r2 = DesignSteady(*ctx2, SteadyDesignOptions{}, {}, "heave-steady");
  EXPECT_EQ(r2.status, DesignStatus::kOk) << r2.message;
}

}  // namespace
}  // namespace uuvplan::planner
