// Issue #16: a long position-only log is not held twice while it is prepared, and what the
// prepared trial keeps is shared where it can be: the positions are moved out of a log the
// caller gives up (PrepareTrial's `given_up`), the velocity estimate shares their times
// (SharedTimes) and stores its samples in float, and its runs as their first samples.
#include <gtest/gtest.h>

#include <string>

#include "ident_cases.h"
#include "support/live_heap.h"
#include "uuvplan/ident/monte_carlo.h"
#include "uuvplan/ident/trial_data.h"

namespace uuvplan::ident {
namespace {

// Issue #16's case in small (bench/cases/position_surge_truth.yaml: position alone at 100 Hz,
// σ 1 cm), 300 s of force legs: 30,001 position samples.
model::Campaign PositionLegs() {
  const model::Truth truth =
      io::ReadTruth(std::string(UUVPLAN_SOURCE_DIR) + "/bench/cases/position_surge_truth.yaml");
  return VirtualCampaign(
      truth,
      {testing::Segments(
          "legs", model::Dof::kSurge, "surge-front",
          {{50, 40}, {-25, 30}, {75, 40}, {-50, 40}, {25, 50}, {-75, 40}, {50, 60}})},
      16);
}

TEST(SharedTimesTest, CopiesShareTheTimesAndAChangeDetachesOnlyTheChangedCopy) {
  SharedTimes a = std::vector<double>{0.0, 0.1, 0.2};
  SharedTimes b = a;
  EXPECT_TRUE(b.SharesWith(a));
  b.push_back(0.3);
  EXPECT_FALSE(b.SharesWith(a));
  EXPECT_EQ(a.size(), 3u);
  EXPECT_EQ(b.size(), 4u);
  EXPECT_EQ(b.back(), 0.3);
  const SharedTimes moved = std::move(b);
  EXPECT_EQ(moved.size(), 4u);
  EXPECT_TRUE(b.empty());  // NOLINT(bugprone-use-after-move): a moved-from SharedTimes is empty
  EXPECT_EQ(static_cast<const std::vector<double>&>(a), (std::vector<double>{0.0, 0.1, 0.2}));
}

TEST(PreparedTrialMemoryTest, AGivenUpLogIsMovedNotCopiedAndTheEstimateSharesItsTimes) {
  if (!uuvplan::testing::HeapCountingAvailable())
    GTEST_SKIP() << "a sanitizer build counts no heap";
  const model::Campaign logged = PositionLegs();
  const TrialData copied = PrepareTrial(logged.trials[0], 0, logged.vehicle, TrialDataOptions{});
  ASSERT_FALSE(copied.has_velocity());
  const long long n = static_cast<long long>(copied.position.size());
  ASSERT_GT(n, 30000);

  model::Campaign given = logged;
  uuvplan::testing::StartCountingHeap();
  TrialData d =
      PrepareTrial(given.trials[0], 0, given.vehicle, TrialDataOptions{}, &given.trials[0].log);
  const long long moved_peak = uuvplan::testing::StopCountingHeap();
  model::Campaign again = logged;
  uuvplan::testing::StartCountingHeap();
  { const TrialData c = PrepareTrial(again.trials[0], 0, again.vehicle, TrialDataOptions{}); }
  const long long copied_peak = uuvplan::testing::StopCountingHeap();

  // The same trial either way, and the log given up is left empty.
  EXPECT_TRUE(given.trials[0].log.t.empty());
  EXPECT_EQ(d.position.t.vector(), copied.position.t.vector());
  EXPECT_EQ(d.position.y, copied.position.y);
  EXPECT_EQ(d.velocity_estimate.value, copied.velocity_estimate.value);
  EXPECT_EQ(d.initial_velocity, copied.initial_velocity);
  // The estimate's times are the positions' own, not a copy (8 B a sample).
  EXPECT_TRUE(d.velocity_estimate.t.SharesWith(d.position.t));
  // Moving the positions' times and values saves their copy, 16 B a sample (the log's own
  // blocks count against the peak once freed): at least 12 B a sample below the copying
  // path whatever the allocator's rounding.
  EXPECT_LT(moved_peak, copied_peak - 12 * n)
      << "given up: " << moved_peak << " B, copied: " << copied_peak << " B, " << n << " samples";
  std::cout << n << " samples: prepare's peak heap " << moved_peak / static_cast<double>(n)
            << " B a sample from a given-up log, " << copied_peak / static_cast<double>(n)
            << " B copied\n";
}

}  // namespace
}  // namespace uuvplan::ident
