// Outputs that never lose data: concurrent runs on one --out, and a user's
// directory with the name of an old temporary directory.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <string>

#include "cli_test_util.h"

namespace uuvplan::cli_test {
namespace {

namespace fs = std::filesystem;

const std::string kTruth = std::string(UUVPLAN_SOURCE_DIR) + "/tests/data/io/truth.yaml";
const std::string kGoodPlanPath =
    std::string(UUVPLAN_SOURCE_DIR) + "/tests/data/bad/cases/plan_good.json";

// Four `simulate --out X` at once: one writes X; every other one either fails naming the
// other run (it started while the winner held X) or, had it won, wrote the same campaign. A
// directory of the user's called X.tmp-uuvplan is left as it was, and no temporary remains.
TEST(ConcurrentOutput, FourSimulateRunsOnOneOutAllButOneRefused) {
  const TempDir dir;
  const std::string out = dir / "X";
  fs::create_directories(out + ".tmp-uuvplan");
  dir.Write("X.tmp-uuvplan/mine.txt", "user data\n");
  std::string script;
  for (int i = 0; i < 4; ++i) {
    const std::string n = std::to_string(i);
    script += "('" + std::string(UUVPLAN_BINARY) + "' simulate --truth '" + kTruth + "' --plan '" +
              kGoodPlanPath + "' --out '" + out + "' >/dev/null 2>'" + (dir / ("err" + n)) +
              "'; echo $? >'" + (dir / ("rc" + n)) + "') & ";
  }
  ASSERT_EQ(std::system((script + "wait").c_str()), 0);  // std::system runs /bin/sh
  int succeeded = 0;
  for (int i = 0; i < 4; ++i) {
    const std::string n = std::to_string(i);
    const std::string rc = ReadText(dir / ("rc" + n)), err = ReadText(dir / ("err" + n));
    if (rc == "0\n") {
      ++succeeded;
      continue;
    }
    EXPECT_EQ(rc, "2\n") << err;
    const bool named = err.find("another run is writing " + out) != std::string::npos ||
                       err.find("another run wrote a campaign there") != std::string::npos ||
                       err.find("exists and is not empty") != std::string::npos;
    EXPECT_TRUE(named) << err;
  }
  EXPECT_EQ(succeeded, 1);
  EXPECT_TRUE(fs::exists(out + "/campaign.yaml"));
  EXPECT_EQ(ReadText(dir / "X.tmp-uuvplan/mine.txt"), "user data\n");
  for (const auto& e : fs::directory_iterator(dir.path())) {
    EXPECT_EQ(e.path().filename().string().rfind("X.tmp-uuvplan-", 0), std::string::npos)
        << e.path();
  }
}

}  // namespace
}  // namespace uuvplan::cli_test
