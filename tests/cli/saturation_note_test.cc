// `simulate`'s note on thrusters asked beyond their range answers as the planner's thrust check
// does (one question, one answer): a plan the planner made raises none — ROMEO's switched
// multisines peak below the sum of their amplitudes — and a steady push beyond the thrusters'
// range raises one with its figure.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "cli_test_util.h"

namespace uuvplan::cli_test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

TEST(SaturationNote, APlanThePlannerMadeAsksNoThrusterBeyondItsRange) {
  TempDir dir;
  ToolRun r = RunTool("schedule " + kRomeoCase + "vehicle.yaml --pool " + kRomeoCase +
                          "pool.yaml --dof sway --json '" + (dir / "plan.json") + "'",
                      dir);
  ASSERT_NE(r.status, 2) << r.err;
  r = RunTool("simulate --truth " + kRomeoCase + "truth.yaml --plan '" + (dir / "plan.json") +
                  "' --out '" + (dir / "run") + "' --seed 1",
              dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, Not(HasSubstr("does not saturate"))) << r.err;
}

TEST(SaturationNote, ASteadyPushBeyondTheRangeIsNamedWithItsFigure) {
  TempDir dir;
  // surge-front shares 300 N as 0.70711·300 = 212 N per front thruster (Table I); each gives
  // at most 1.02·10² = 102 N: 108% beyond.
  dir.Write("plan.json", R"({"trials": [{"id": "too_hard", "dof": "surge", "kind": "steady",
    "duration": 10, "mapping": "surge-front", "force": 300}]})");
  const ToolRun r = RunTool("simulate --truth " + kRomeoCase + "truth.yaml --plan '" +
                                (dir / "plan.json") + "' --out '" + (dir / "run") + "' --seed 1",
                            dir);
  ASSERT_EQ(r.status, 0) << r.err;
  EXPECT_THAT(r.err, HasSubstr("trial 'too_hard' asks a thruster up to 108% more than its "
                               "command range gives"));
}

}  // namespace
}  // namespace uuvplan::cli_test
