// Unit and sign mistakes stop `identify` before any fit (ident/prepare/input_sanity.h): a
// virtual ROMEO campaign with a heading and a gyro (as the BlueROV logs) written to a temporary
// directory, one column then spoiled as a user would — a gyro in deg/s, a heading in degrees,
// a velocity logged as the position, the force with the wrong sign — must exit 2 naming the
// file, the column and the likely unit; --accept-units identifies anyway.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "ident/ident_cases.h"
#include "support/real_data.h"
#include "uuvplan/io/virtual_campaign.h"

namespace uuvplan::cli_test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
constexpr double kDegrees = 180.0 / M_PI;

// Applies `change` to column `column` of every data row of a trial CSV (comments kept), and
// renames it to `rename` when given.
void EditColumn(const std::string& path, const std::string& column,
                const std::function<double(double)>& change, const std::string& rename = "") {
  std::ifstream in(path);
  std::ostringstream out;
  std::string line;
  int index = -1;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#') {
      out << line << "\n";
      continue;
    }
    std::vector<std::string> cells;
    std::stringstream ss(line);
    for (std::string cell; std::getline(ss, cell, ',');) cells.push_back(cell);
    if (line.back() == ',') cells.push_back("");
    for (std::size_t i = 0; i < cells.size(); ++i) {
      if (index < 0 && cells[i] == column) {
        index = static_cast<int>(i);
        if (!rename.empty()) cells[i] = rename;
      } else if (static_cast<int>(i) == index && !cells[i].empty() && cells[0] != "t") {
        std::ostringstream v;
        v.precision(17);
        v << change(std::stod(cells[i]));
        cells[i] = v.str();
      }
    }
    for (std::size_t i = 0; i < cells.size(); ++i) out << (i ? "," : "") << cells[i];
    out << "\n";
  }
  ASSERT_GE(index, 0) << column << " not in " << path;
  std::ofstream(path) << out.str();
}

// ROMEO (ref 000 §IV-D) with `dof` measured by a position sensor and/or a velocity sensor
// (a gyro at 20 Hz, 0.005 rad/s as the BlueROV's), two of its trial designs, written to `dir`.
std::string Campaign(const TempDir& dir, model::Dof dof, bool position, bool velocity) {
  model::Truth truth = ident::testing::CaseTruth("romeo");
  model::DofSensors& s = truth.vehicle.sensors[dof];
  if (!position) s.position.reset();
  if (velocity) s.velocity = model::SensorSpec{20.0, dof == model::Dof::kYaw ? 0.005 : 0.01};
  const auto designs = dof == model::Dof::kYaw ? ident::testing::RomeoYawDesigns()
                                               : ident::testing::RomeoSurgeDesigns();
  model::VirtualCampaignOptions vo;
  vo.seed = 11;
  io::SimulateCampaign(truth, {designs[0], designs[1]}, dir / "c", vo);
  return dir / "c";
}

std::string Trial(const std::string& campaign, model::Dof dof) {
  return campaign + "/trials/" + (dof == model::Dof::kYaw ? "yaw_flrr" : "surge_front") + ".csv";
}

// Exit 2 naming the trial file and the column, with `unit` in the message; --accept-units
// then identifies (exit 0 or 1) and prints the finding as a warning.
void ExpectStopped(const TempDir& dir, const std::string& campaign, const std::string& column,
                   const std::string& unit) {
  const ToolRun r = RunTool("identify '" + campaign + "'", dir);
  EXPECT_EQ(r.status, 2) << r.out << r.err;
  EXPECT_THAT(r.err, ::testing::ContainsRegex("trials/[a-z_0-9]+\\.csv: column " + column));
  EXPECT_THAT(r.err, HasSubstr("column " + column + ":")) << r.err;
  EXPECT_THAT(r.err, HasSubstr(unit)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("--accept-units"));
  const ToolRun accepted = RunTool("identify '" + campaign + "' --accept-units", dir);
  EXPECT_NE(accepted.status, 2) << accepted.err;
  EXPECT_THAT(accepted.err, HasSubstr("warning: units, signs or sensors look wrong"));
  EXPECT_THAT(accepted.out, HasSubstr("Identification of"));
}

TEST(InputSanityCliTest, CleanCampaignIsIdentified) {
  // The unspoiled twin of every case below: no finding, identified (exit 0).
  TempDir dir;
  const std::string c = Campaign(dir, model::Dof::kYaw, true, true);
  const ToolRun r = RunTool("identify '" + c + "'", dir);
  EXPECT_EQ(r.status, 0) << r.out << r.err;
  EXPECT_THAT(r.err, Not(HasSubstr("units or signs")));
}

TEST(InputSanityCliTest, ThePlannersOwnScheduleRaisesNothing) {
  // ROMEO's surge and yaw schedule in its pool, run on the truth by `simulate` and identified:
  // no unit or sign finding. Its steady trials hold one force from rest (surge-steady-6 pushes
  // 5.77 N for 81 s): a force without variance, whose 0/0 R² once called pos_surge a velocity
  // and yaw-steady-4's force the wrong sign (exit 2 on the planner's own trials).
  TempDir dir;
  const std::string romeo = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/";
  ASSERT_EQ(RunTool("schedule " + romeo + "vehicle.yaml --pool " + romeo +
                        "pool.yaml --dof surge --dof yaw --json " + (dir / "plan.json"),
                    dir)
                .status,
            0);
  ASSERT_EQ(RunTool("simulate --truth " + romeo + "truth.yaml --plan " + (dir / "plan.json") +
                        " --out " + (dir / "campaign") + " --seed 3",
                    dir)
                .status,
            0);
  const ToolRun r = RunTool("identify " + (dir / "campaign/campaign.yaml"), dir);
  EXPECT_EQ(r.status, 0) << r.err << r.out;
  EXPECT_THAT(r.err, Not(HasSubstr("units, signs or sensors look wrong")));
}

TEST(InputSanityCliTest, GyroInDegreesPerSecondStops) {
  TempDir dir;
  const std::string c = Campaign(dir, model::Dof::kYaw, true, true);
  EditColumn(Trial(c, model::Dof::kYaw), "vel_yaw", [](double v) { return v * kDegrees; });
  ExpectStopped(dir, c, "vel_yaw", "deg/s");
}

TEST(InputSanityCliTest, GyroAloneInDegreesPerSecondStops) {
  // No heading to compare with: the rate itself (over a turn per second) names deg/s.
  TempDir dir;
  const std::string c = Campaign(dir, model::Dof::kYaw, false, true);
  EditColumn(Trial(c, model::Dof::kYaw), "vel_yaw", [](double v) { return v * kDegrees; });
  ExpectStopped(dir, c, "vel_yaw", "deg/s");
}

TEST(InputSanityCliTest, HeadingInDegreesStops) {
  TempDir dir;
  const std::string c = Campaign(dir, model::Dof::kYaw, true, true);
  EditColumn(Trial(c, model::Dof::kYaw), "pos_yaw", [](double v) { return v * kDegrees; });
  ExpectStopped(dir, c, "pos_yaw", "degrees");
}

TEST(InputSanityCliTest, VelocityLoggedAsPositionStops) {
  // A surge log whose only motion column is the velocity, headed pos_surge.
  TempDir dir;
  const std::string c = Campaign(dir, model::Dof::kSurge, false, true);
  EditColumn(
      Trial(c, model::Dof::kSurge), "vel_surge", [](double v) { return v; }, "pos_surge");
  ExpectStopped(dir, c, "pos_surge", "holds a velocity");
}

TEST(InputSanityCliTest, ForceOfTheWrongSignStops) {
  TempDir dir;
  const std::string c = Campaign(dir, model::Dof::kYaw, true, true);
  EditColumn(Trial(c, model::Dof::kYaw), "force_yaw", [](double f) { return -f; });
  ExpectStopped(dir, c, "force_yaw", "negate force_yaw");
}

TEST(InputSanityCliTest, RealBluerovGyroInDegreesPerSecondStops) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("bluerov-yaw-2016");
  // shared/data/bluerov-yaw-2016 copied with its gyro converted to deg/s (its rates reach
  // 0.3–1.7 rad/s, so 16–100 "rad/s" in degrees): stopped, naming vel_yaw and deg/s.
  TempDir dir;
  const std::string copy = dir / "bluerov";
  std::filesystem::copy(uuvplan::testing::RealDataPath("bluerov-yaw-2016"), copy,
                        std::filesystem::copy_options::recursive);
  for (const auto& f : std::filesystem::directory_iterator(copy + "/trials")) {
    EditColumn(f.path().string(), "vel_yaw", [](double v) { return v * kDegrees; });
  }
  ExpectStopped(dir, copy + "/campaign.yaml", "vel_yaw", "deg/s");
}

}  // namespace
}  // namespace uuvplan::cli_test
