// A payload on a known vehicle (docs/planning.md "A payload on a known vehicle"):
// payload60 as its skid on the frame `loop` identified (cases/payload60/on-frame-truth.yaml)
// against the same vehicle described from scratch (truth.yaml), in the same pool, loop seed 1
// (the CLI's). Known, the loop designs about the frame's estimates from its first trial instead of
// running the a priori schedule's steady runs: fewer trials and less pool time, and every
// final parameter of interest still within 3σ of the truth. Full-size figures over seeds in
// docs/validation.md ("A payload on a known vehicle").
#include <gtest/gtest.h>

#include <string>

#include "support/loop_validation.h"
#include "uuvplan/io/pool_yaml.h"
#include "uuvplan/io/truth_yaml.h"

namespace uuvplan::testing {
namespace {

std::string Payload60(const std::string& file) {
  return std::string(UUVPLAN_SOURCE_DIR) + "/cases/payload60/" + file;
}

TEST(PayloadLoop, OnItsKnownFrameTheLoopNeedsLessPoolTime) {
  const model::Pool pool = io::ReadPool(Payload60("pool.yaml"));
  const LoopCaseOutcome scratch =
      RunLoopCase("from scratch", io::ReadTruth(Payload60("truth.yaml")), pool, 1);
  const LoopCaseOutcome known =
      RunLoopCase("on its frame", io::ReadTruth(Payload60("on-frame-truth.yaml")), pool, 1);
  SCOPED_TRACE(CaseLine(scratch) + "\n" + CaseLine(known));
  ASSERT_EQ(scratch.status, planner::LoopStatus::kConverged);
  ASSERT_EQ(known.status, planner::LoopStatus::kConverged);
  EXPECT_LT(known.trials, scratch.trials);
  EXPECT_LT(known.pool_time_s, scratch.pool_time_s);
  EXPECT_EQ(known.interest.size(), scratch.interest.size());
  for (const auto& e : known.interest) EXPECT_TRUE(e.within3) << e.name << " z = " << e.z;
}

}  // namespace
}  // namespace uuvplan::testing
