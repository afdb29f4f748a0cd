// The `schedule`, `check-pool` and `loop` commands on ROMEO (cases/romeo): exit statuses, the
// JSON of the contract, and one verdict sentence for one question.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "planner/planner_test_util.h"

namespace uuvplan::cli {
namespace {

// The command line (UUVPLAN_BINARY): exit statuses and JSON of schedule and check-pool.
int RunTool(const std::string& args) {
  const std::string cmd = std::string(UUVPLAN_BINARY) + " " + args + " > /dev/null 2>&1";
  const int status = std::system(cmd.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(PlannerCli, ScheduleAndCheckPool) {
  namespace fs = std::filesystem;
  const fs::path dir =
      fs::temp_directory_path() / ("uuvplan_planner_cli_" + std::to_string(::getpid()));
  fs::create_directories(dir);
  const std::string vehicle = planner::testing::RomeoPath("vehicle.yaml");
  const std::string pool = planner::testing::RomeoPath("pool.yaml");
  const std::string plan = (dir / "plan.json").string();
  ASSERT_EQ(RunTool("schedule " + vehicle + " --pool " + pool + " --dof surge --json " + plan), 0);
  std::ifstream in(plan);
  const nlohmann::json j = nlohmann::json::parse(in);
  ASSERT_TRUE(j.contains("trials"));
  ASSERT_TRUE(j["predicted"].contains("surge"));
  EXPECT_TRUE(j["predicted"]["surge"]["sigma"].contains("m"));
  for (const auto& t : j["trials"]) {
    EXPECT_TRUE(t.contains("travel"));
    EXPECT_TRUE(t.contains("thrust_min"));
  }
  // The plan fits its own pool (exit 0: surge, the DOF it plans, is hosted) and not a 6 m one
  // (exit 1, with the required length).
  const std::string out = (dir / "check.json").string();
  EXPECT_EQ(RunTool("check-pool " + vehicle + " --pool " + pool + " --dof surge --plan " + plan +
                    " --json " + out),
            0);
  const fs::path small = dir / "small.yaml";
  std::ofstream(small) << "name: small\nlength: 6\nwidth: 12\ndepth: 5\nmargin: 1.5\n";
  EXPECT_EQ(RunTool("check-pool " + vehicle + " --pool " + small.string() + " --plan " + plan +
                    " --json " + out),
            1);
  std::ifstream cin(out);
  const nlohmann::json c = nlohmann::json::parse(cin);
  EXPECT_FALSE(c["feasible"].get<bool>());
  EXPECT_GT(c["required"]["length"].get<double>(), 20.0);
  EXPECT_EQ(c["required"]["unit"], "m");
  EXPECT_EQ(c["required"]["measure"], "wall to wall");
  EXPECT_EQ(c["verdict"]["dofs"]["surge"]["limit"], "length");
  EXPECT_FALSE(c["trials"][0]["reasons"].empty());
  EXPECT_TRUE(c.contains("fits"));
  // Bad input: exit 2.
  EXPECT_EQ(RunTool("schedule " + vehicle + " --pool " + pool + " --dof twist"), 2);
  EXPECT_EQ(RunTool("schedule " + (dir / "missing.yaml").string() + " --pool " + pool), 2);
  fs::remove_all(dir);
}

// The output and exit status of `uuvplan ARGS`, its output kept in dir/name.
int RunToText(const std::filesystem::path& dir, const std::string& args, const std::string& name,
              std::string* text) {
  const std::filesystem::path out = dir / name;
  const std::string cmd = std::string(UUVPLAN_BINARY) + " " + args + " > " + out.string() + " 2>&1";
  const int status = std::system(cmd.c_str());
  std::ifstream in(out);
  text->assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A fresh directory for one test's files, removed at its end.
struct VerdictDir {
  explicit VerdictDir(const std::string& name)
      : path(std::filesystem::temp_directory_path() /
             ("uuvplan_verdict_cli_" + name + "_" + std::to_string(::getpid()))) {
    std::filesystem::create_directories(path);
  }
  ~VerdictDir() { std::filesystem::remove_all(path); }
  std::filesystem::path path;
};

// The texts of ROMEO surge's schedule, check-pool (own and --plan) in the pool `pool` (each
// expected to exit 1: no pool is promised before the first trials), in this order.
std::vector<std::string> PlanAndCheck(const VerdictDir& dir, const std::filesystem::path& pool) {
  const std::string v = planner::testing::RomeoPath("vehicle.yaml"),
                    p = " --pool " + pool.string() + " --dof surge",
                    plan = (dir.path / "plan.json").string();
  std::vector<std::string> texts(3);
  EXPECT_EQ(RunToText(dir.path, "schedule " + v + p + " --json " + plan, "a.txt", &texts[0]), 1);
  EXPECT_EQ(RunToText(dir.path, "check-pool " + v + p, "b.txt", &texts[1]), 1);
  EXPECT_EQ(RunToText(dir.path, "check-pool " + v + p + " --plan " + plan, "c.txt", &texts[2]), 1);
  return texts;
}

// The same inputs, one answer: schedule, check-pool (own and --plan) and the start of loop on
// ROMEO surge in a pool 3 m long (hosted for no vehicle of the a priori box) all exit 1 with the
// same verdict sentence (docs/planning.md, "The pool verdict").
TEST(PlannerCli, ScheduleCheckPoolAndLoopRefuseAPoolAlike) {
  const VerdictDir dir("none");
  const std::filesystem::path small = dir.path / "small.yaml";
  std::ofstream(small) << "name: small\nlength: 3\nwidth: 12\ndepth: 5\nmargin: 1\n";
  // The precision judged at is in the sentence: the loop's default target.
  const std::string sentence = "Pool small CANNOT host the identification of surge to 5% ";
  std::vector<std::string> texts = PlanAndCheck(dir, small);
  std::string d;
  const std::string loop_json = (dir.path / "loop.json").string();
  EXPECT_EQ(RunToText(dir.path,
                      "loop --truth " + planner::testing::RomeoPath("truth.yaml") + " --pool " +
                          small.string() + " --dof surge --json " + loop_json,
                      "d.txt", &d),
            1);
  texts.push_back(d);
  for (const std::string& t : texts) EXPECT_NE(t.find(sentence), std::string::npos) << t;
  // The refused loop still writes its JSON: the verdict, status and exit status.
  std::ifstream in(loop_json);
  std::string e((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  EXPECT_NE(e.find("\"status\": \"infeasible\""), std::string::npos) << e;
  EXPECT_NE(e.find("\"exit_status\": 1"), std::string::npos) << e;
  EXPECT_NE(e.find(sentence), std::string::npos) << e;
}

// Part of the box: in a 6 m pool (hosted for part of the box) the same commands print the same
// "PART" verdict, schedule and check-pool exit 1 (nothing can be promised before the first
// trials) and loop runs — and converges.
TEST(PlannerCli, ScheduleCheckPoolAndLoopHostPartOfTheBoxAlike) {
  const VerdictDir dir("part");
  const std::filesystem::path six = dir.path / "six.yaml";
  std::ofstream(six) << "name: six\nlength: 6\nwidth: 12\ndepth: 5\nmargin: 1\n";
  const std::string part =
      "Pool six can host the identification of surge to 5% (every "
      "parameter of interest's 100·σ/|θ|) for PART of the a priori box only";
  std::vector<std::string> texts = PlanAndCheck(dir, six);
  std::string d;
  EXPECT_EQ(RunToText(dir.path,
                      "loop --truth " + planner::testing::RomeoPath("truth.yaml") + " --pool " +
                          six.string() + " --dof surge",
                      "h.txt", &d),
            0);
  texts.push_back(d);
  for (const std::string& t : texts) EXPECT_NE(t.find(part), std::string::npos) << t;
  EXPECT_NE(d.find("Converged after"), std::string::npos) << d;
}

}  // namespace
}  // namespace uuvplan::cli
