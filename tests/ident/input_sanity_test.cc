// The unit and sign checks of ident/prepare/input_sanity.h on campaigns in memory: correct logs
// (the seed cases' virtual campaigns, the two real campaigns of shared/data) raise nothing, and
// each mistake is named on its column. The command line's exit status 2 and --accept-units are
// tested in tests/cli/input_sanity_cli_test.cc.
#include "uuvplan/ident/prepare/input_sanity.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "ident_cases.h"
#include "support/real_data.h"
#include "uuvplan/model/campaign_builder.h"

namespace uuvplan::ident {
namespace {

using model::Dof;

model::Campaign Virtual(const std::string& name, const std::vector<model::TrialDesign>& designs,
                        Dof gyro_dof = Dof::kSurge, bool gyro = false) {
  model::Truth truth = testing::CaseTruth(name);
  if (gyro) truth.vehicle.sensors[gyro_dof].velocity = model::SensorSpec{20.0, 0.005};
  model::VirtualCampaignOptions vo;
  vo.seed = 5;
  vo.unwrap_headings = true;  // as the CSV reader does
  return model::BuildVirtualCampaign(truth, designs, vo);
}

std::string Texts(const std::vector<InputProblem>& problems) {
  std::string s;
  for (const auto& p : problems) s += p.Text() + "\n";
  return s;
}

TEST(InputSanityTest, CorrectVirtualLogsRaiseNothing) {
  // Every seed case, with a heading-only (ROMEO), a gyro (ROMEO yaw with one added) and the
  // VSOR and URIS sensors: no finding on correct logs.
  const std::vector<model::Campaign> campaigns = {
      Virtual("romeo", testing::RomeoSurgeDesigns()),
      Virtual("romeo", testing::RomeoHeaveDesigns()),
      Virtual("romeo", testing::RomeoYawDesigns(), Dof::kYaw, true),
      Virtual("vsor", testing::VsorDesigns()), Virtual("uris", testing::UrisDesigns())};
  for (const model::Campaign& c : campaigns) {
    const auto problems = CheckInputSanity(c);
    EXPECT_TRUE(problems.empty()) << Texts(problems);
  }
}

TEST(InputSanityTest, RealLogsRaiseNothing) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("bluerov-yaw-2016", "tartan-pool-2022");
  // BlueROV: gyro only, 99th-percentile rates 0.27–1.74 rad/s; Tartan: heading and rate
  // (ratio 0.98–0.99, correlation ≥ 0.998), depth and heave rate (ratio 0.98–1.03), and a
  // force balance with m, c > 0 on every chunk although it is closed loop.
  for (const char* c : {"bluerov-yaw-2016/campaign_all.yaml", "tartan-pool-2022/campaign.yaml"}) {
    const auto problems = CheckInputSanity(io::ReadCampaign(uuvplan::testing::RealDataPath(c)));
    EXPECT_TRUE(problems.empty()) << c << "\n" << Texts(problems);
  }
}

TEST(InputSanityTest, APositionColumnThatFollowsTheRateIsAVelocity) {
  // Heading and gyro both logged, but the "heading" column holds the gyro's values: it tracks
  // vel_yaw instead of integrating it.
  model::Campaign c = Virtual("romeo", {testing::RomeoYawDesigns()[3]}, Dof::kYaw, true);
  model::TrialLog& log = c.trials[0].log;
  log.position[model::Index(Dof::kYaw)] = log.velocity[model::Index(Dof::kYaw)];
  const auto problems = CheckInputSanity(c);
  ASSERT_EQ(problems.size(), 1u) << Texts(problems);
  EXPECT_EQ(problems[0].column, "pos_yaw");
  EXPECT_THAT(problems[0].fix, ::testing::HasSubstr("holds a velocity"));
}

TEST(InputSanityTest, AnOppositeRateSignIsNamed) {
  model::Campaign c = Virtual("romeo", {testing::RomeoYawDesigns()[0]}, Dof::kYaw, true);
  for (double& v : c.trials[0].log.velocity[model::Index(Dof::kYaw)]) v = -v;
  const auto problems = CheckInputSanity(c);
  ASSERT_FALSE(problems.empty());
  EXPECT_EQ(problems[0].column, "vel_yaw");
  EXPECT_THAT(problems[0].fix, ::testing::HasSubstr("opposite sign conventions"));
}

TEST(InputSanityTest, ANoisyHeadingInDegreesIsNamedFromItsChangesOverWindows) {
  // VSOR's heading (ref 002: 13 Hz, noisy) beside its gyro, on two 15 s steady turns (the
  // planner's steady runs): the heading's derivative is too noisy to compare with the rate
  // (correlation −0.2 and 0.4 here, under 0.8), but its changes over 2 s windows follow the
  // rate's integral (cosine ≥ 0.99). Logged in rad, nothing is raised; logged in degrees (and
  // read as the CSV reader would), both trials are named at 1/57.3 from those windows.
  model::Truth truth = testing::CaseTruth("vsor");
  model::VirtualCampaignOptions vo;
  vo.seed = 5;
  vo.unwrap_headings = false;
  const std::vector<model::TrialDesign> steady = {
      testing::Segments("yaw_ccw", Dof::kYaw, "yaw-ht1-ht7", {{30, 15}}),
      testing::Segments("yaw_cw", Dof::kYaw, "yaw-ht1-ht7", {{-30, 15}})};
  model::Campaign c = model::BuildVirtualCampaign(truth, steady, vo);
  model::Campaign degrees = c;
  for (model::TrialEntry& e : c.trials) model::UnwrapAngles(&e.log);
  EXPECT_TRUE(CheckInputSanity(c).empty()) << Texts(CheckInputSanity(c));
  for (model::TrialEntry& e : degrees.trials) {
    for (double& p : e.log.position[model::Index(Dof::kYaw)]) p *= 180.0 / M_PI;
    model::UnwrapAngles(&e.log);
  }
  const auto problems = CheckInputSanity(degrees);
  ASSERT_EQ(problems.size(), 2u) << Texts(problems);
  for (const InputProblem& p : problems) {
    EXPECT_EQ(p.column, "pos_yaw") << Texts(problems);
    EXPECT_THAT(p.finding, ::testing::HasSubstr("× the change of pos_yaw over")) << Texts(problems);
    EXPECT_THAT(p.fix, ::testing::HasSubstr("likely in degrees")) << Texts(problems);
  }
}

// A sensor stuck at one value while the force pushes: named on its column, position or rate.
TEST(InputSanityTest, AStuckSensorIsNamed) {
  for (const bool rate : {false, true}) {
    model::Campaign c = Virtual("romeo", {testing::RomeoYawDesigns()[0]}, Dof::kYaw, true);
    model::TrialLog& log = c.trials[0].log;
    auto& column =
        rate ? log.velocity[model::Index(Dof::kYaw)] : log.position[model::Index(Dof::kYaw)];
    for (double& v : column) v = 0.25;
    const auto problems = CheckInputSanity(c);
    ASSERT_FALSE(problems.empty()) << rate;
    EXPECT_EQ(problems[0].column, rate ? "vel_yaw" : "pos_yaw");
    EXPECT_THAT(problems[0].finding, ::testing::HasSubstr("every one of its"));
    EXPECT_THAT(problems[0].fix, ::testing::HasSubstr("stuck or disconnected sensor"));
  }
}

}  // namespace
}  // namespace uuvplan::ident
