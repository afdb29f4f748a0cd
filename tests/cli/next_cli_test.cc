// `next` after three ROMEO surge trials of the virtual pool, in a pool 6 m long that hosts
// surge for part of the a priori box only: the pool verdict it prints is judged over the current
// estimates — the sentence `schedule` prints for the vehicle file `identify --write-vehicle`
// writes from the same campaign, not the a priori one — and `--commands DIR` writes the planned
// trial's command file and its run-sheet line.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "cli_test_util.h"

namespace uuvplan::cli_test {
namespace {

using ::testing::HasSubstr;

const std::string kRomeo = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/";

// The line of `text` that starts with "Verdict: ".
std::string VerdictLine(const std::string& text) {
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("Verdict: ", 0) == 0) return line;
  }
  return "";
}

TEST(NextCli, VerdictIsJudgedOnTheEstimatesAndCommandsAreWritten) {
  const TempDir scratch;
  const std::string plan = scratch.Write("plan.json", kRomeoFirstSurgeTrials);
  const std::string pool = scratch.Write("six.yaml",
                                         "name: six\nlength: 6\nwidth: 12\ndepth: 5\n"
                                         "margin: 1\n");
  const std::string campaign = scratch / "campaign";
  const ToolRun sim = RunTool("simulate --truth " + kRomeo + "truth.yaml --plan " + plan +
                                  " --out " + campaign + " --seed 7",
                              scratch);
  ASSERT_EQ(sim.status, 0) << sim.err;
  const std::string commands = scratch / "commands", json = scratch / "next.json";
  const ToolRun next = RunTool("next " + campaign + " --pool " + pool + " --dof surge --commands " +
                                   commands + " --json " + json,
                               scratch);
  ASSERT_EQ(next.status, 0) << next.err;  // a trial planned; the pool hosts part of the box
  const std::string identified = scratch / "identified.yaml";
  const ToolRun id =
      RunTool("identify " + campaign + " --dof surge --write-vehicle " + identified, scratch);
  ASSERT_EQ(id.status, 0) << id.err;
  const ToolRun schedule =
      RunTool("schedule " + identified + " --pool " + pool + " --dof surge", scratch);
  // One question, one answer: the same sentence, about the estimates' box.
  const std::string verdict = VerdictLine(next.out);
  EXPECT_EQ(verdict, VerdictLine(schedule.out)) << next.out << "\n" << schedule.out;
  EXPECT_THAT(verdict, HasSubstr("the box about the identified model")) << next.out;

  const nlohmann::json j = nlohmann::json::parse(ReadText(json));
  ASSERT_EQ(j["status"], "trial") << j.dump();
  const std::string trial = j["trial"]["id"].get<std::string>();
  EXPECT_TRUE(std::filesystem::exists(commands + "/" + trial + ".csv")) << trial;
  const std::string sheet = ReadText(commands + "/run_sheet.md");
  EXPECT_THAT(sheet, HasSubstr("| 1 | " + trial + " | surge |")) << sheet;
  EXPECT_THAT(next.out, HasSubstr("Commands of " + trial));
}

}  // namespace
}  // namespace uuvplan::cli_test
