// A vehicle file that carries an identified model (`identify --write-vehicle`): the planner's
// box is its estimates ± 3σ (parameter_box.h PlanningBox), and what a schedule planned there
// predicts is what identification then achieves on the vehicle.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>

#include "planner_test_util.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/model/campaign_builder.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/design/parameter_box.h"
#include "uuvplan/planner/pool/pool_verdict.h"
#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::planner {
namespace {

using ::testing::HasSubstr;

model::Vehicle WithIdentifiedSurge(model::Vehicle v, const model::DofParameters& surge) {
  v.models[model::Dof::kSurge] = surge;
  return v;
}

TEST(PlanningBox, AnIdentifiedModelCentresTheBoxAtThreeSigma) {
  model::DofParameters surge;
  surge.params = {{"m", 900.0}, {"k", 45.0}, {"kq", 300.0}};
  surge.sigma = {{"m", 30.0}, {"k", 3.0}, {"kq", 20.0}};
  const model::Vehicle v = WithIdentifiedSurge(testing::Romeo(), surge);
  const std::vector<std::string> names = {"m", "k", "kq", "bias"};
  std::vector<std::string> notes;
  const ParameterBox box = PlanningBox(v, model::Dof::kSurge, names, BoxOptions{}, &notes);
  EXPECT_EQ(box.Nominal("m"), 900.0);
  EXPECT_EQ(box.Nominal("k"), 45.0);
  EXPECT_EQ(box.Nominal("kq"), 300.0);
  ASSERT_EQ(box.axes[0].name, "m");
  EXPECT_NEAR(box.axes[0].lo, 1.0 - 3.0 * 30.0 / 900.0, 1e-12);
  EXPECT_NEAR(box.axes[0].hi, 1.0 + 3.0 * 30.0 / 900.0, 1e-12);
  ASSERT_EQ(box.axes[1].name, "drag");  // k and kq together: the wider of 3σ/|θ|
  EXPECT_NEAR(box.axes[1].hi, 1.0 + 3.0 * 20.0 / 300.0, 1e-12);
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_THAT(notes[0], HasSubstr("surge: planned about the identified model"));
  EXPECT_THAT(notes[0], HasSubstr("m = 900 ± 30 kg"));

  // An insignificant k (± 3σ = ± 200%) does not widen the drag axis beyond the vehicle file's
  // a priori ± rel_sigma (cases/romeo: 0.3): an estimate only narrows what was known.
  surge.sigma["k"] = 30.0;
  const ParameterBox capped = PlanningBox(WithIdentifiedSurge(testing::Romeo(), surge),
                                          model::Dof::kSurge, names, BoxOptions{}, nullptr);
  EXPECT_NEAR(capped.axes[1].lo, 0.7, 1e-12);
  EXPECT_NEAR(capped.axes[1].hi, 1.3, 1e-12);

  // Without σ (a hand-written model) the box stays the a priori one.
  surge.sigma.clear();
  const model::Vehicle plain = WithIdentifiedSurge(testing::Romeo(), surge);
  const ParameterBox apriori = PlanningBox(plain, model::Dof::kSurge, names, BoxOptions{}, nullptr);
  const auto bounds = plain.InertiaBounds(model::Dof::kSurge);
  EXPECT_NEAR(apriori.Nominal("m"), 0.5 * (bounds[0] + bounds[1]), 1e-9);
}

// A translation's m is at least the dry mass (added mass is positive, Fossen 2011 §6.3.1): a box
// about an estimate reaching below it starts there, its centre moved inside; one entirely below
// it is the a priori box (a diverged fit, which would otherwise be planned over time constants
// of milliseconds), with a note.
TEST(PlanningBox, NoInertiaBelowTheLeastPhysical) {
  const model::Vehicle romeo = testing::Romeo();
  const double dry = romeo.mass;
  const std::vector<std::string> names = {"m", "k", "kq", "bias"};
  model::DofParameters surge;
  surge.params = {{"m", 0.96 * dry}, {"k", 45.0}, {"kq", 300.0}};
  surge.sigma = {{"m", 0.02 * dry}, {"k", 3.0}, {"kq", 20.0}};
  std::vector<std::string> notes;
  const ParameterBox part = PlanningBox(WithIdentifiedSurge(romeo, surge), model::Dof::kSurge,
                                        names, BoxOptions{}, &notes);
  ASSERT_EQ(part.axes[0].name, "m");
  // ± 3σ is [0.9, 1.02] dry masses (narrower than the a priori box); what is left, [1, 1.02],
  // centred at 1.01.
  EXPECT_NEAR(part.Nominal("m"), 1.01 * dry, 1e-9 * dry);
  EXPECT_NEAR(part.Nominal("m") * part.axes[0].lo, dry, 1e-9 * dry);
  EXPECT_NEAR(part.Nominal("m") * part.axes[0].hi, 1.02 * dry, 1e-9 * dry);

  surge.params["m"] = 0.3 * dry;
  surge.sigma["m"] = 0.05 * dry;
  notes.clear();
  const ParameterBox below = PlanningBox(WithIdentifiedSurge(romeo, surge), model::Dof::kSurge,
                                         names, BoxOptions{}, &notes);
  const auto bounds = romeo.InertiaBounds(model::Dof::kSurge);
  EXPECT_NEAR(below.Nominal("m") * below.axes[0].lo, bounds[0], 1e-9 * dry);
  EXPECT_NEAR(below.Nominal("m") * below.axes[0].hi, bounds[1], 1e-9 * dry);
  EXPECT_THAT(notes.back(), HasSubstr("below the least physical"));

  // A rotation's inertia in a vehicle file is computed, not weighed: half of it is the floor.
  EXPECT_DOUBLE_EQ(LeastInertia(romeo, model::Dof::kYaw),
                   0.5 * romeo.RigidInertia(model::Dof::kYaw));
  EXPECT_DOUBLE_EQ(LeastInertia(romeo, model::Dof::kSurge), dry);
}

// A box whose fastest time constant is under the planner's least (an inertia in the wrong unit)
// is refused at once, naming the time constant, instead of simulated in microsecond steps.
TEST(PlanningBox, ATimeConstantOfMicrosecondsIsRefusedAtOnce) {
  model::Vehicle v = testing::Romeo();
  v.inertia[model::Dof::kYaw] = 1e-6;  // kg·m² as if given in tonne·m²
  try {
    DofPlanningProblem::APriori(v, testing::RomeoPool(), model::Dof::kYaw, PlannerOptions{},
                                nullptr);
    FAIL() << "the planning problem was built";
  } catch (const model::InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("reaches a time constant of"));
    EXPECT_THAT(e.what(), HasSubstr("under the planner's least 2 ms"));
  }
}

// ROMEO's surge truth (cases/romeo/truth.yaml) as if identified with 5% σ, written and read
// back as a vehicle file; the surge schedule planned about it, run in the virtual pool and
// identified: every parameter's σ as identification reports it lies within a factor 2 of the
// schedule's prediction (the Cramér–Rao σ, worst over the ± 3σ box), for each seed. A factor
// 2 because the prediction is the worst case over the box and identification fits the
// initial state and prunes, while the box is narrow (± 15%), so the two differ by tens of
// percent, not by factors.
TEST(IdentifiedVehicleSchedule, AchievedSigmaIsWithinAFactorTwoOfThePredicted) {
  const model::Truth truth = io::ReadTruth(testing::RomeoPath("truth.yaml"));
  model::DofParameters surge;
  surge.params = truth.dofs.at(model::Dof::kSurge).params;
  for (const char* name : {"m", "k", "kq"}) {
    surge.sigma[name] = 0.05 * surge.params.at(name);
  }
  const std::string file = (std::filesystem::temp_directory_path() /
                            ("uuvplan-identified-" + std::to_string(::getpid()) + ".yaml"))
                               .string();
  io::WriteVehicleYaml(file, WithIdentifiedSurge(truth.vehicle, surge), "test");
  const model::Vehicle vehicle = io::ReadVehicle(file);
  std::filesystem::remove(file);

  ScheduleOptions o;
  o.dofs = {model::Dof::kSurge};
  const ScheduleResult plan = PlanSchedule(vehicle, testing::RomeoPool(), o);
  ASSERT_EQ(plan.status, PlanStatus::kOk) << plan.message;
  EXPECT_THAT(plan.dofs[0].notes, ::testing::Contains(HasSubstr("identified model")));
  // The verdict names the box it judged: the one about the estimates, for this file only.
  EXPECT_TRUE(
      JudgePoolOnChecks(vehicle, testing::RomeoPool(), o, plan, nullptr, {}).identified_box);
  EXPECT_FALSE(
      JudgePoolOnChecks(truth.vehicle, testing::RomeoPool(), o, plan, nullptr, {}).identified_box);
  const PredictedPrecision& predicted = plan.schedule.predicted.at(model::Dof::kSurge);
  std::vector<model::TrialDesign> designs;
  for (const PlannedTrial& t : plan.schedule.trials) designs.push_back(t.design);

  for (std::uint64_t seed : {1u, 2u, 3u}) {
    model::VirtualCampaignOptions vo;
    vo.seed = seed;
    const model::Campaign campaign = model::BuildVirtualCampaign(truth, designs, vo);
    ident::IdentifyOptions options;
    options.dofs = {model::Dof::kSurge};
    const ident::IdentifyResult r = ident::Identify(campaign, options);
    ASSERT_NE(r.status, ident::IdentifyStatus::kFailed) << r.message;
    int compared = 0;
    for (const ident::ParameterEstimate& p : r.dofs.at(0).params) {
      if (p.state != ident::ParameterState::kEstimated || !predicted.sigma.count(p.name)) continue;
      const double ratio = p.sigma / predicted.sigma.at(p.name);
      EXPECT_GT(ratio, 0.5) << p.name << " seed " << seed;
      EXPECT_LT(ratio, 2.0) << p.name << " seed " << seed;
      ++compared;
    }
    EXPECT_GE(compared, 3) << "seed " << seed;  // m, k and kq at least
  }
}

}  // namespace
}  // namespace uuvplan::planner
