// `uuvplan schedule VEHICLE --pool POOL --model coupled` (issue #19): the per-DOF planner's
// options are refused, not ignored. The plan itself is tested in
// tests/planner/coupled_design_test.cc (5–16 s a plan; not repeated here).
#include <gtest/gtest.h>

#include "tool_test_util.h"

namespace uuvplan::tool_test {
namespace {

TEST(CoupledScheduleCli, OptionsOfThePerDofPlannerAreRefusedNotIgnored) {
  // Refused before any file is read (exit 2, naming every option given).
  TempDir scratch;
  const ToolRun run = RunTool("schedule '" + (scratch / "none.yaml") + "' --pool '" +
                                  (scratch / "none.yaml") +
                                  "' --model coupled --dof surge --no-steady",
                              scratch);
  EXPECT_EQ(run.status, 2) << run.out << run.err;
  const std::string text = run.out + run.err;
  EXPECT_NE(text.find("--model coupled"), std::string::npos) << text;
  EXPECT_NE(text.find("no --dof, --no-steady"), std::string::npos) << text;
}

}  // namespace
}  // namespace uuvplan::tool_test
