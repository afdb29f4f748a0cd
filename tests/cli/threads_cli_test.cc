// The planner's independent designs — the DOFs of a schedule and of the pool verdict,
// the loop's a priori schedules and the candidate trials of several DOFs — run on `--threads`
// threads with output identical to one thread (as identification's trials and DOFs,
// tests/ident/threads_test.cc): each design is planned on its own and taken in serial order.
#include <gtest/gtest.h>

#include <string>

#include "cli_test_util.h"

namespace uuvplan::cli_test {
namespace {

std::string Case(const std::string& file) {
  return std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/" + file;
}

TEST(ThreadsCliTest, LoopJsonOfTwoThreadsIsThatOfOne) {
  // ROMEO surge, heave and yaw: three a priori schedules and the verdict's three DOFs planned
  // at once; budget 4 reaches the sequential designs of the first DOF (not every DOF
  // converges: the candidates of several DOFs are planned in each decision).
  TempDir scratch;
  std::string json[2];
  for (int threads : {1, 2}) {
    const std::string out = scratch / ("loop" + std::to_string(threads) + ".json");
    const ToolRun r =
        RunTool("loop --truth " + Case("truth.yaml") + " --pool " + Case("pool.yaml") +
                    " --budget 4 --threads " + std::to_string(threads) + " --json " + out,
                scratch);
    ASSERT_EQ(r.status, 4) << r.out << r.err;  // 4: budget spent (docs/cli.md)
    json[threads - 1] = ReadText(out);
  }
  ASSERT_FALSE(json[0].empty());
  EXPECT_EQ(json[0], json[1]);  // byte for byte
}

}  // namespace
}  // namespace uuvplan::cli_test
