// Mapping-switched inertia trials (issue #17) on ROMEO (cases/romeo, seed 000): the planned
// family against the paper's design at the same duration and pool, every planned profile
// replayed over the box's corners, and the switched trial identified.
#include "uuvplan/planner/switched_design.h"

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

#include "planner_test_util.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/model/campaign_builder.h"
#include "uuvplan/planner/criteria.h"
#include "uuvplan/planner/fisher_information.h"
#include "uuvplan/planner/schedule_planner.h"
#include "uuvplan/planner/thrust_limits.h"
#include "uuvplan/planner/trial_envelope.h"

namespace uuvplan::planner {
namespace {

using testing::PaperSurgeSine;

// The trial as its schedule entry gives it to another tool: the sampled profile, held between
// samples (the profile is ≤ 0.1 s apart and samples both sides of every jump).
std::unique_ptr<model::Excitation> Replay(const model::Vehicle& v, const PlannedTrial& t) {
  std::vector<int> mapping;
  for (const auto& name : t.profile.mapping) mapping.push_back(v.MappingIndex(name));
  return model::MakeHeldExcitation(t.profile.t, t.profile.force, mapping, t.design.duration);
}

// Every box corner (m at its bounds × drag at 1 ± rel_sigma) and the centre: the replayed
// profile, simulated by model::Simulate at 0.02 s from the planned start, stays within the
// free length (margins kept), and no working thruster reverses, drops below min_thrust or
// exceeds its range.
void ExpectReplayFeasible(const model::Vehicle& v, const model::Pool& pool, const DofContext& ctx,
                          const PlannedTrial& t) {
  ASSERT_FALSE(t.profile.t.empty()) << t.design.id;
  for (std::size_t i = 1; i < t.profile.t.size(); ++i) {
    ASSERT_LE(t.profile.t[i] - t.profile.t[i - 1], 0.1 + 1e-9) << t.design.id;  // issue: ≤ 0.1 s
  }
  const auto input = Replay(v, t);
  const auto& tm = ctx.ModelFor(t.design);
  const ThrustCheck tc = CheckThrust(v, *input, t.design.duration);
  EXPECT_TRUE(tc.ok()) << t.design.id << ": " << (tc.reasons.empty() ? "" : tc.reasons.front());
  const auto mb = v.InertiaBounds(t.design.dof);
  const auto& drag = *v.priors.at(t.design.dof).drag;
  ASSERT_EQ(t.start.unit, "m");
  for (double m : {mb[0], 0.5 * (mb[0] + mb[1]), mb[1]}) {
    for (double f : {1 - drag.rel_sigma, 1.0, 1 + drag.rel_sigma}) {
      Eigen::VectorXd th = tm.design_thetas.front();
      th[0] = m;
      th[1] = drag.k * f;
      th[2] = drag.kq * f;
      const TrialResponse r = SimulateExcursion(*tm.model, th, *input, t.design.duration, 0.02);
      // 1 mm: the planner keeps 5 mm inside; the two integrations differ by far less.
      EXPECT_GE(t.start.value + r.position_min, pool.margin - 1e-3) << t.design.id << " m " << m;
      EXPECT_LE(t.start.value + r.position_max, pool.length - pool.margin + 1e-3)
          << t.design.id << " m " << m << " drag ×" << f;
    }
  }
}

class RomeoSurgeFamilies : public ::testing::Test {
 protected:
  void SetUp() override {
    ctx_ = DofContext::APriori(v_, pool_, model::Dof::kSurge, PlannerOptions{}, nullptr);
  }
  model::Vehicle v_ = testing::Romeo();
  model::Pool pool_ = testing::RomeoPool();
  std::unique_ptr<DofContext> ctx_;
};

TEST_F(RomeoSurgeFamilies, SwitchPairIsFrontForwardRearBackward) {
  // Seed 000 Table I: surge-front pushes forward, surge-rear backward in open water; no other
  // pair alternates without a thruster reversing.
  const std::vector<SwitchPair> pairs = SwitchPairs(*ctx_);
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(v_.mappings[pairs[0].pos].name, "surge-front");
  EXPECT_EQ(v_.mappings[pairs[0].neg].name, "surge-rear");
}

TEST_F(RomeoSurgeFamilies, ScheduleAt52sBeatsThePaperThreeTimesOverAndReplaysFeasibly) {
  ScheduleOptions o;
  o.dofs = {model::Dof::kSurge};
  o.steady_runs = false;
  o.max_completion_trials = 0;
  o.planner.max_trial_duration_s = 52.0;
  const ScheduleResult r = PlanSchedule(v_, pool_, o);
  ASSERT_FALSE(r.schedule.trials.empty()) << r.message;
  const PlannedTrial& t = r.schedule.trials.front();
  const double planned = testing::WorstSigmaM(*ctx_, ctx_->Information(t.design));
  const double paper = testing::WorstSigmaM(*ctx_, ctx_->Information(PaperSurgeSine()));
  std::cout << "[ romeo surge ] " << t.design.id << " (" << model::InputFamilyName(t.design.family)
            << "): worst sigma(m)/m " << planned << ", paper " << paper << ", ratio "
            << planned / paper << "\n";
  RecordProperty("sigma_m_ratio_family_over_paper", std::to_string(planned / paper));
  EXPECT_LE(planned / paper, 0.3);  // issue #17's requirement
  EXPECT_NEAR(t.design.duration, 52.0, 1e-9);
  for (const PlannedTrial& trial : r.schedule.trials) ExpectReplayFeasible(v_, pool_, *ctx_, trial);
}

TEST_F(RomeoSurgeFamilies, SwitchedTrialIsIdentifiedWithinThreeSigma) {
  SineDesignOptions o;
  o.fixed_duration_s = 52.0;
  const SineDesignResult r =
      DesignSwitched(*ctx_, model::InputFamily::kSwitchedSquare, o, {}, "surge-switched");
  ASSERT_EQ(r.status, DesignStatus::kOk) << r.message;
  const model::Truth truth = io::ReadTruth(testing::RomeoPath("truth.yaml"));
  model::VirtualCampaignOptions vo;
  vo.seed = 17;
  const model::Campaign campaign = model::BuildVirtualCampaign(truth, {r.trial.design}, vo);
  ident::IdentifyOptions io;
  io.dofs = {model::Dof::kSurge};
  const ident::IdentifyResult id = ident::Identify(campaign, io);
  ASSERT_EQ(id.dofs.size(), 1u) << id.message;
  const auto& d = id.dofs.front();
  ASSERT_EQ(d.parameter_names.front(), "m");
  const double m = d.theta[0], sigma = std::sqrt(d.covariance(0, 0));
  const double m_true = truth.dofs.at(model::Dof::kSurge).params.at("m");
  std::cout << "[ romeo surge ] switched trial: m " << m << " ± " << sigma << " kg (truth "
            << m_true << ")\n";
  EXPECT_LE(std::abs(m - m_true), 3 * sigma);  // 3σ: a 0.27% chance of a false failure
  EXPECT_LT(sigma / m_true, 0.05);             // and the trial determines it
}

}  // namespace
}  // namespace uuvplan::planner

namespace uuvplan::planner {
namespace {

// docs/planning.md's table: the single sine (its own duration, fitted to the pool) against the
// best family at the same duration and pool, worst σ(m)/m over the box; the issue asks ≤ 0.5.
struct FamilyCase {
  const char* vehicle;
  model::Dof dof;
};
class FamiliesAgainstTheSine : public ::testing::TestWithParam<FamilyCase> {};

TEST_P(FamiliesAgainstTheSine, HalveTheWorstSigmaOfTheMass) {
  const std::string dir = std::string(UUVPLAN_SOURCE_DIR) + "/cases/" + GetParam().vehicle + "/";
  const model::Vehicle v = io::ReadVehicle(dir + "vehicle.yaml");
  const model::Pool pool = io::ReadPool(dir + "pool.yaml");
  const auto ctx = DofContext::APriori(v, pool, GetParam().dof, PlannerOptions{}, nullptr);
  SineDesignOptions o;
  o.families.clear();
  const SineDesignResult sine = DesignInertiaTrial(*ctx, o, {}, "sine");
  ASSERT_EQ(sine.status, DesignStatus::kOk) << sine.message;
  o = SineDesignOptions{};
  o.fixed_duration_s = sine.trial.design.duration;
  const SineDesignResult best = DesignInertiaTrial(*ctx, o, {}, "best");
  ASSERT_EQ(best.status, DesignStatus::kOk) << best.message;
  const double s = testing::WorstSigmaM(*ctx, sine.information);
  const double b = testing::WorstSigmaM(*ctx, best.information);
  std::cout << "[ " << GetParam().vehicle << " " << model::DofName(GetParam().dof) << " ] "
            << sine.trial.design.duration << " s: single sine " << s << ", "
            << model::InputFamilyName(best.trial.design.family) << " " << b << ", ratio " << b / s
            << "\n";
  EXPECT_LE(b / s, 0.5);  // issue #17
}

INSTANTIATE_TEST_SUITE_P(Cases, FamiliesAgainstTheSine,
                         ::testing::Values(FamilyCase{"romeo", model::Dof::kYaw},
                                           FamilyCase{"romeo", model::Dof::kSway}));
// Not met (docs/planning.md §1b): VSOR yaw (no sine of any kind at a fixed duration: the force
// range between min_thrust and the rate limit is too narrow) and URIS surge (no switched design
// beats the single sine in its pool).

}  // namespace
}  // namespace uuvplan::planner
