// The `loop` and `next` commands on ROMEO (cases/romeo): exit statuses (4 budget spent, 2 bad
// input, 1 a pool the verdict refuses) and the JSON of the contract.
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "cli_test_util.h"
#include "planner/planner_test_util.h"

namespace uuvplan::cli {
namespace {

using planner::testing::RomeoPath;

// The command line: exit 4 when the budget runs out, 2 on bad input; JSON keys of the
// contract. Skipped when the uuvplan binary has not been built with this test program.
class LoopCliTest : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!std::filesystem::exists(UUVPLAN_BINARY)) GTEST_SKIP() << "uuvplan not built";
  }
  cli_test::TempDir dir_;
};

TEST_F(LoopCliTest, BudgetAndBadInputExitCodes) {
  const std::string base = "loop --truth '" + RomeoPath("truth.yaml") + "' --pool '" +
                           RomeoPath("pool.yaml") + "' --dof surge";
  const auto spent =
      cli_test::RunTool(base + " --budget 1 --json '" + (dir_ / "l.json") + "'", dir_);
  EXPECT_EQ(spent.status, 4) << spent.err;  // docs/cli.md: 4 = budget spent
  const auto j = nlohmann::json::parse(cli_test::ReadText(dir_ / "l.json"));
  EXPECT_FALSE(j.at("converged").get<bool>());
  ASSERT_EQ(j.at("iterations").size(), 1u);
  EXPECT_TRUE(j["iterations"][0].at("trial").contains("kind"));
  EXPECT_TRUE(j["iterations"][0].at("params").at("surge").at("m").contains("sigma"));
  EXPECT_GT(j.at("pool_time").get<double>(), 0.0);
  EXPECT_EQ(cli_test::RunTool(base + " --target -1", dir_).status, 2);
  EXPECT_EQ(cli_test::RunTool(base + " --budget 0", dir_).status, 2);
  const auto roll = cli_test::RunTool(base + " --dof roll", dir_);
  EXPECT_EQ(roll.status, 2);
  EXPECT_NE(roll.err.find("dofs.roll"), std::string::npos) << roll.err;
}

TEST_F(LoopCliTest, NextWritesEstimatesTrialAndPredicted) {
  // An empty campaign of the ROMEO vehicle: the next trial is the first of ref 000's order.
  const std::string campaign =
      dir_.Write("campaign.yaml", "vehicle: '" + RomeoPath("vehicle.yaml") + "'\ntrials: []\n");
  const auto r = cli_test::RunTool("next '" + campaign + "' --pool '" + RomeoPath("pool.yaml") +
                                       "' --dof yaw --json '" + (dir_ / "n.json") + "'",
                                   dir_);
  ASSERT_EQ(r.status, 0) << r.err << r.out;
  const auto j = nlohmann::json::parse(cli_test::ReadText(dir_ / "n.json"));
  EXPECT_TRUE(j.contains("estimates"));
  EXPECT_EQ(j.at("trial").at("dof"), "yaw");
  EXPECT_TRUE(j.at("predicted").contains("yaw"));
  // The trial can be run by `simulate --plan` (ReadScheduleJson reads a next result).
  const auto sim = cli_test::RunTool("simulate --truth '" + RomeoPath("truth.yaml") + "' --plan '" +
                                         (dir_ / "n.json") + "' --out '" + (dir_ / "c") + "'",
                                     dir_);
  EXPECT_EQ(sim.status, 0) << sim.err;
}

// A pool the verdict refuses (ROMEO heave in 0.5 m of free depth): `next` exits 1 and its
// JSON says so as `loop`'s does — status "infeasible", the verdict's sentence as the message —
// so that a script reading `status` stops; the best next trial stays in `trial` for reference.
// Before, the status read "trial" beside "exit_status": 1.
TEST_F(LoopCliTest, NextInAPoolTheVerdictRefusesIsInfeasible) {
  const std::string campaign =
      dir_.Write("campaign.yaml", "vehicle: '" + RomeoPath("vehicle.yaml") + "'\ntrials: []\n");
  const std::string pool =
      dir_.Write("shallow.yaml", "name: shallow\nlength: 30\nwidth: 20\ndepth: 2.5\nmargin: 1\n");
  const auto r = cli_test::RunTool("next '" + campaign + "' --pool '" + pool +
                                       "' --dof heave --json '" + (dir_ / "n.json") + "'",
                                   dir_);
  EXPECT_EQ(r.status, 1) << r.err << r.out;
  const auto j = nlohmann::json::parse(cli_test::ReadText(dir_ / "n.json"));
  EXPECT_EQ(j.at("status"), "infeasible");
  EXPECT_EQ(j.at("exit_status"), 1);
  EXPECT_EQ(j.at("message").get<std::string>().rfind("Pool shallow CANNOT host", 0), 0u)
      << j.at("message");
  EXPECT_FALSE(j.at("trial").is_null());
}

}  // namespace
}  // namespace uuvplan::cli
