// `simulate --pool`: every trial of the truth checked against the pool's free volume — its
// span when the plan places no start, and from its planned start otherwise — exit 1 naming the
// trial when one leaves it. The truth's travel is checked here against the logged positions
// (ROMEO's surge echo-sounder, σ 0.03 m).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "cli_test_util.h"
#include "uuvplan/io/trial_log_csv.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::cli {
namespace {

using cli_test::RunTool;
using cli_test::TempDir;
using cli_test::ToolRun;
using ::testing::HasSubstr;
using ::testing::Not;

const std::string kTruth = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/truth.yaml";

// ROMEO surge at 20 N for 30 s from rest, with or without a start 1 m past the rear margin line.
std::string Plan(bool with_start) {
  return std::string(R"({"trials": [
  {"id": "push", "dof": "surge", "kind": "segments", "duration": 30, "mapping": "surge-front",
   "segments": [{"force": 20, "duration": 30, "mapping": "surge-front"}])") +
         (with_start ? R"json(,
   "start": {"value": 2.5, "unit": "m", "from": "the rear wall (negative surge)"})json"
                     : "") +
         "}]}";
}

// A pool `free` m long between its margin lines (1.5 m each).
std::string Pool(const TempDir& dir, const std::string& name, double free) {
  return dir.Write(name + ".yaml", "name: " + name +
                                       "\nlength: " + model::ShortestNumber(free + 3) +
                                       "\nwidth: 12\ndepth: 5\nmargin: 1.5\n");
}

ToolRun Simulate(const TempDir& dir, const std::string& plan, const std::string& pool,
                 const std::string& out) {
  return RunTool("simulate --truth '" + kTruth + "' --plan '" + plan + "' --out '" + (dir / out) +
                     "' --seed 3 --pool '" + pool + "'",
                 dir);
}

TEST(SimulatePool, ATrialThatLeavesTheFreeVolumeIsNamed) {
  const TempDir dir;
  const std::string bare = dir.Write("bare.json", Plan(false));
  const ToolRun wide = Simulate(dir, bare, Pool(dir, "wide", 100), "wide");
  ASSERT_EQ(wide.status, 0) << wide.out << wide.err;
  EXPECT_THAT(wide.out, Not(HasSubstr("NOT IN THE POOL")));
  // The logged travel: the truth's within the sensor's noise (a few σ of 0.03 m each end).
  const model::TrialLog log = io::ReadTrialLog(dir / "wide/trials/push.csv");
  std::vector<double> x;
  for (double p : log.position[model::Index(model::Dof::kSurge)]) {
    if (!std::isnan(p)) x.push_back(p);
  }
  ASSERT_FALSE(x.empty());
  const double span = *std::max_element(x.begin(), x.end()) - *std::min_element(x.begin(), x.end());
  // A long push: 20% of it, and 0.5 m, are far beyond the noise's reach on the span (±0.2 m).
  ASSERT_GT(span, 3.0);
  // No start: the span against the free length.
  EXPECT_EQ(Simulate(dir, bare, Pool(dir, "roomy", span + 0.5), "roomy").status, 0);
  const ToolRun short_pool = Simulate(dir, bare, Pool(dir, "short", 0.8 * span), "short");
  EXPECT_EQ(short_pool.status, 1) << short_pool.out << short_pool.err;
  EXPECT_THAT(short_pool.out, HasSubstr("NOT IN THE POOL: trial 'push': the truth's surge spans "));
  EXPECT_THAT(short_pool.out, HasSubstr("(the plan places no start); pool short leaves"));
  // From its start 1 m past the margin line, the same roomy pool is 0.5 m short at the far end.
  const std::string placed = dir.Write("placed.json", Plan(true));
  const ToolRun late = Simulate(dir, placed, Pool(dir, "roomy", span + 0.5), "late");
  EXPECT_EQ(late.status, 1) << late.out << late.err;
  EXPECT_THAT(late.out, HasSubstr("trial 'push': the truth's surge goes from 1 to "));
  EXPECT_THAT(late.out, HasSubstr("from the margin line of the rear wall (negative surge) "
                                  "(planned start 2.5 m); pool roomy leaves"));
  EXPECT_EQ(Simulate(dir, placed, Pool(dir, "long", span + 1.5), "long").status, 0);
  // The JSON carries the same sentences.
  const ToolRun json =
      RunTool("simulate --truth '" + kTruth + "' --plan '" + placed + "' --out '" + (dir / "json") +
                  "' --pool '" + (dir / "roomy.yaml") + "' --json '" + (dir / "s.json") + "'",
              dir);
  EXPECT_EQ(json.status, 1);
  EXPECT_THAT(
      cli_test::ReadText(dir / "s.json"),
      HasSubstr("\"outside_pool\": [\n    \"trial 'push': the truth's surge goes from 1 to"));
}

}  // namespace
}  // namespace uuvplan::cli
