// Mapping-switched and one-way inertia trials: ROMEO's planned family against the
// paper's design at the same duration and pool, the best family against the single sine on
// ROMEO, URIS and VSOR, every case's planned profiles replayed from the schedule JSON over the
// box, and the switched trial identified.
#include "uuvplan/planner/design/switched_design.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <map>

#include "planner_test_util.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/model/campaign_builder.h"
#include "uuvplan/planner/design/criteria.h"
#include "uuvplan/planner/design/fisher_information.h"
#include "uuvplan/planner/design/thrust_limits.h"
#include "uuvplan/planner/design/trial_envelope.h"
#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::planner {
namespace {

using testing::PaperSurgeSine;

// The trial as its schedule JSON gives it to another tool: the sampled profile {t, force,
// mapping}, linear between samples; a jump is sampled on both sides (1e-9·t apart), held
// between them, and both are integration breakpoints (so that no RK4 stage of the step before
// a jump sees the value after it). Independent of the planner's excitations.
class ProfileReplay : public model::Excitation {
 public:
  static constexpr double kJump = 1e-6;  // s: samples closer than this are the two sides of a jump
  ProfileReplay(const model::Vehicle& v, const nlohmann::json& profile, double duration)
      : t_(profile.at("t").get<std::vector<double>>()),
        f_(profile.at("force").get<std::vector<double>>()),
        duration_(duration) {
    for (const auto& name : profile.at("mapping")) {
      mapping_.push_back(v.MappingIndex(name.get<std::string>()));
    }
    for (std::size_t i = 1; i < t_.size(); ++i) {
      if (t_[i] - t_[i - 1] < kJump) jumps_.insert(jumps_.end(), {t_[i - 1], t_[i]});
    }
  }
  double Force(double t) const override {
    const std::size_t i = Interval(t);
    if (i + 1 >= t_.size()) return f_.back();
    if (t_[i + 1] - t_[i] < kJump) return f_[i];  // the jump itself: the earlier value holds
    const double u = std::clamp((t - t_[i]) / (t_[i + 1] - t_[i]), 0.0, 1.0);
    return f_[i] + u * (f_[i + 1] - f_[i]);
  }
  int Mapping(double t) const override { return mapping_[Interval(t)]; }
  model::TimesView Breakpoints() const override { return jumps_; }
  double duration() const override { return duration_; }
  double sample_spacing() const {
    double h = 0.0;
    for (std::size_t i = 1; i < t_.size(); ++i) h = std::max(h, t_[i] - t_[i - 1]);
    return h;
  }

 private:
  std::size_t Interval(double t) const {  // the last sample at or before t
    const auto it = std::upper_bound(t_.begin(), t_.end(), t);
    return it == t_.begin() ? 0 : static_cast<std::size_t>(it - t_.begin()) - 1;
  }
  std::vector<double> t_, f_;
  std::vector<int> mapping_;
  std::vector<double> jumps_;
  double duration_;
};

// One trial of a schedule JSON, replayed from its profile and start: simulated by
// SimulateExcursion at 0.02 s over the whole check grid of the a priori box (every corner and
// the centre of m × drag × eta, 3 values per axis), its travel from the planned start stays
// within the pool's free length/width/depth or the tether's turns, and no working thruster
// reverses, drops below min_thrust or exceeds its range (CheckThrust).
void ExpectReplayFeasible(const model::Vehicle& v, const model::Pool& pool,
                          const nlohmann::json& trial) {
  const std::string id = trial.at("id").get<std::string>();
  ASSERT_TRUE(trial.contains("profile") && trial.contains("start")) << id;
  const double duration = trial.at("duration").get<double>();
  const ProfileReplay input(v, trial.at("profile"), duration);
  EXPECT_LE(input.sample_spacing(), 0.1 + 1e-9) << id;  // At most 0.1 s apart
  const ThrustCheck tc = CheckThrust(v, input, duration);
  EXPECT_TRUE(tc.ok()) << id << ": " << (tc.reasons.empty() ? "" : tc.reasons.front());
  const model::Dof dof = *model::ParseDof(trial.at("dof").get<std::string>());
  const auto ctx = DofPlanningProblem::APriori(v, pool, dof, PlannerOptions{}, nullptr);
  const PlannedTrial planned = io::TrialFromJson(io::JsonValue(trial, "schedule", id));
  const auto& tm = ctx->ModelFor(planned.design);
  const double free = pool.FreeTravel(dof);
  const auto& start = trial.at("start");
  // Metres from a wall (its margin included), or degrees from the tether's end.
  const double from_end = start.at("unit") == "deg" ? start.at("value").get<double>() * M_PI / 180
                                                    : start.at("value").get<double>() - pool.margin;
  for (const Eigen::VectorXd& theta : tm.check_thetas) {
    const TrialResponse r = SimulateExcursion(*tm.model, theta, input, duration, 0.02);
    // 1 mm (1e-3 rad): the planner keeps 5 mm inside; the two integrations differ by far less.
    EXPECT_GE(from_end + r.position_min, -1e-3) << id << " at theta " << theta.transpose();
    if (std::isfinite(free)) {
      EXPECT_LE(from_end + r.position_max, free + 1e-3) << id << " at theta " << theta.transpose();
    }
  }
}

class RomeoSurgeFamilies : public ::testing::Test {
 protected:
  void SetUp() override {
    ctx_ = DofPlanningProblem::APriori(v_, pool_, model::Dof::kSurge, PlannerOptions{}, nullptr);
  }
  model::Vehicle v_ = testing::Romeo();
  model::Pool pool_ = testing::RomeoPool();
  std::unique_ptr<DofPlanningProblem> ctx_;
};

TEST_F(RomeoSurgeFamilies, SwitchPairIsFrontForwardRearBackward) {
  // Ref 000 Table I: surge-front pushes forward, surge-rear backward in open water; no other
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
  EXPECT_LE(planned / paper, 0.3);  // the switched families' requirement
  EXPECT_NEAR(t.design.duration, 52.0, 1e-9);
  for (const auto& trial : io::ScheduleToJson(r.schedule).at("trials")) {
    ExpectReplayFeasible(v_, pool_, trial);
  }
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

// The best family's worst σ(m)/m over the single sine's at the sine's duration (printed);
// `reversible`: every thruster marked as built to reverse. The chosen trial to *chosen.
double FamilyOverSine(const FamilyCase& c, bool reversible = false,
                      model::TrialDesign* chosen = nullptr) {
  const std::string dir = std::string(UUVPLAN_SOURCE_DIR) + "/cases/" + c.vehicle + "/";
  model::Vehicle v = io::ReadVehicle(dir + "vehicle.yaml");
  for (auto& t : v.thrusters) t.reversible = reversible;
  const model::Pool pool = io::ReadPool(dir + "pool.yaml");
  const auto ctx = DofPlanningProblem::APriori(v, pool, c.dof, PlannerOptions{}, nullptr);
  SineDesignOptions o;
  o.families.clear();
  const SineDesignResult sine = DesignInertiaTrial(*ctx, o, {}, "sine");
  EXPECT_EQ(sine.status, DesignStatus::kOk) << sine.message;
  o = SineDesignOptions{};
  o.one_way_families = true;  // URIS surge, VSOR yaw: no switch pair
  o.fixed_duration_s = sine.trial.design.duration;
  const SineDesignResult best = DesignInertiaTrial(*ctx, o, {}, "best");
  EXPECT_EQ(best.status, DesignStatus::kOk) << best.message;
  const double s = testing::WorstSigmaM(*ctx, sine.information);
  const double b = testing::WorstSigmaM(*ctx, best.information);
  std::cout << "[ " << c.vehicle << " " << model::DofName(c.dof) << " ] "
            << sine.trial.design.duration << " s: single sine " << s << ", "
            << model::InputFamilyName(best.trial.design.family) << " " << b << ", ratio " << b / s
            << "\n";
  // The chosen trial as its schedule entry would give it, replayed over the box.
  PlannedTrial planned;
  planned.design = best.trial.design;
  planned.travel = best.check.travel;
  AddReplayFields(v, pool, &planned);
  ExpectReplayFeasible(v, pool, io::TrialToJson(planned));
  if (chosen) *chosen = best.trial.design;
  return b / s;
}

TEST_P(FamiliesAgainstTheSine, HalveTheWorstSigmaOfTheMass) {
  EXPECT_LE(FamilyOverSine(GetParam()), 0.5);  // the switched families' requirement
}

// URIS surge has no switch pair (XL, XR reverse for the other sign) and 3.7 m of free length
// binds a one-way design's mean force. Counted with a known start the two-level pulse halved
// σ(m) (0.480); with the initial state profiled out (docs/planning.md, "Initial state") it gives
// 0.557: the 0.5 requirement is not met here. What holds: it beats the single sine by more than the
// 1/√2 of a one-way square over the sine's own range (twice its power), i.e. the pulse gains
// from the pool's bound, not from power alone.
TEST(FamiliesAgainstTheSineUris, SurgePulseBeatsTwiceTheSinesPower) {
  EXPECT_LT(FamilyOverSine({"uris", model::Dof::kSurge}), 1.0 / std::sqrt(2.0));
}

// The same URIS surge with thrusters built to reverse (a T200-like XL, XR): surge-x alternates
// with itself, and the zero-mean families keep the vehicle in the 3.7 m of free length while
// the force swings both ways — the switched families' requirement (σ(m) halved against the
// single sine, which keeps the seeds' no-reversal rule) now holds: measured 0.091 against the
// one-way square's 0.557 (FamiliesAgainstTheSineUris). The winner pushes surge-x both ways
// and replays feasibly over the box (FamilyOverSine).
TEST(ReversibleThrusters, UrisSurgeSwingsAboutZeroAndHalvesTheSineSigma) {
  model::TrialDesign chosen;
  EXPECT_LE(FamilyOverSine({"uris", model::Dof::kSurge}, true, &chosen), 0.5);
  EXPECT_TRUE(chosen.Pushes("surge-x", +1) && chosen.Pushes("surge-x", -1))
      << model::InputFamilyName(chosen.family) << " in " << chosen.mapping;
}

// cases/bluerov2 (T200s, reversible): every mapping of every DOF alternates with itself, besides
// the pairs of its vectored thrusters; marked not reversible, no mapping does.
TEST(ReversibleThrusters, EveryBlueRov2MappingPairsWithItselfOnlyWhenReversible) {
  const std::string dir = std::string(UUVPLAN_SOURCE_DIR) + "/cases/bluerov2/";
  const model::Vehicle v = io::ReadVehicle(dir + "vehicle.yaml");
  const model::Pool pool = io::ReadPool(dir + "pool.yaml");
  const auto self_pairs = [&](const model::Vehicle& vehicle, model::Dof dof) {
    const auto ctx = DofPlanningProblem::APriori(vehicle, pool, dof, PlannerOptions{}, nullptr);
    int n = 0;
    for (const SwitchPair& p : SwitchPairs(*ctx)) n += p.pos == p.neg ? 1 : 0;
    return n;
  };
  model::Vehicle fixed = v;
  for (auto& t : fixed.thrusters) t.reversible = false;
  for (model::Dof dof :
       {model::Dof::kSurge, model::Dof::kSway, model::Dof::kHeave, model::Dof::kYaw}) {
    SCOPED_TRACE(model::DofName(dof));
    EXPECT_EQ(self_pairs(v, dof), static_cast<int>(v.MappingsOf(dof).size()));
    EXPECT_EQ(self_pairs(fixed, dof), 0);
  }
}

// VSOR yaw (ref 002 Table 3): one mapping, HT1 + HT7 for clockwise torque; counter-clockwise
// torque reverses both, so no pair switches and the families run one way, within
// [min_thrust, rate limit] = [3.11, 27.4] N·m. A one-way square swings that range at most:
// twice the sine's power, σ ×1/√2 at best — measured 0.76, the 0.5 is out of reach
// (docs/planning.md §1b). Slow (~15 s): run with --gtest_also_run_disabled_tests.
TEST(DISABLED_FamiliesVsorYaw, OneWayOnlyAndNoWorseThanTheSine) {
  const FamilyCase vsor{"vsor", model::Dof::kYaw};
  const std::string dir = std::string(UUVPLAN_SOURCE_DIR) + "/cases/vsor/";
  const model::Vehicle v = io::ReadVehicle(dir + "vehicle.yaml");
  const auto ctx = DofPlanningProblem::APriori(v, io::ReadPool(dir + "pool.yaml"), model::Dof::kYaw,
                                               PlannerOptions{}, nullptr);
  EXPECT_TRUE(SwitchPairs(*ctx).empty());
  EXPECT_LT(FamilyOverSine(vsor), 1.0);
}

// The DOFs of the switched-design table that have no switch pair: their only mapping reverses every
// thruster it uses for the other sign (URIS surge-x: XL + XR; VSOR yaw-ht1-ht7: HT1 + HT7).
TEST(FamiliesOneWay, UrisSurgeAndVsorYawHaveNoSwitchPairButOneWayRanges) {
  for (const FamilyCase c :
       {FamilyCase{"uris", model::Dof::kSurge}, FamilyCase{"vsor", model::Dof::kYaw}}) {
    const std::string dir = std::string(UUVPLAN_SOURCE_DIR) + "/cases/" + c.vehicle + "/";
    const model::Vehicle v = io::ReadVehicle(dir + "vehicle.yaml");
    const auto ctx = DofPlanningProblem::APriori(v, io::ReadPool(dir + "pool.yaml"), c.dof,
                                                 PlannerOptions{}, nullptr);
    EXPECT_TRUE(SwitchPairs(*ctx).empty()) << c.vehicle;
    const auto one_way = OneWayPairs(*ctx);
    ASSERT_FALSE(one_way.empty()) << c.vehicle;
    for (const SwitchPair& p : one_way) {
      EXPECT_EQ(p.pos, p.neg);
      EXPECT_NE(p.one_way, 0);
      EXPECT_TRUE(v.mappings[p.pos].IsOpenWater(p.one_way > 0 ? model::Direction::kPos
                                                              : model::Direction::kNeg));
    }
  }
}

// Every case with a pool: the inertia trial of every DOF its schedule plans, in whichever family
// won, written to the schedule JSON and replayed from there (ExpectReplayFeasible). The steady
// runs are left out for CI time (their legs are `steady`/`segments`, held exactly by the
// profile and checked by the same DofPlanningProblem::Check); the switched families are what
// docs/planning.md added (the one-way square, off by default, is replayed by
// FamiliesAgainstTheSine).
class ReplayEveryCase : public ::testing::TestWithParam<const char*> {};

TEST_P(ReplayEveryCase, EveryPlannedProfileHoldsOverTheBox) {
  const std::string dir = std::string(UUVPLAN_SOURCE_DIR) + "/cases/" + GetParam() + "/";
  const model::Vehicle v = io::ReadVehicle(dir + "vehicle.yaml");
  const model::Pool pool = io::ReadPool(dir + "pool.yaml");
  ScheduleOptions o;
  o.steady_runs = false;
  o.max_completion_trials = 0;
  const ScheduleResult r = PlanSchedule(v, pool, o);
  const nlohmann::json j = io::ScheduleToJson(r.schedule);
  ASSERT_FALSE(j.at("trials").empty()) << r.message;
  for (const auto& trial : j.at("trials")) {
    std::cout << "[ " << GetParam() << " ] replayed " << trial.at("id").get<std::string>() << "\n";
    ExpectReplayFeasible(v, pool, trial);
  }
}

INSTANTIATE_TEST_SUITE_P(Cases, ReplayEveryCase,
                         ::testing::Values("romeo", "vsor", "uris", "payload60"));

INSTANTIATE_TEST_SUITE_P(Cases, FamiliesAgainstTheSine,
                         ::testing::Values(FamilyCase{"romeo", model::Dof::kYaw},
                                           FamilyCase{"romeo", model::Dof::kSway}));

}  // namespace
}  // namespace uuvplan::planner
