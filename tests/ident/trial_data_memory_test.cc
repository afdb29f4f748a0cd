// A long position-only log is not held twice while it is prepared, and what the
// prepared trial keeps is shared where it can be: the positions are moved out of a log the
// caller gives up (PrepareTrial's `given_up`), the velocity estimate shares their times
// (SharedTimes) and stores its samples in float, and its runs as their first samples; times
// logged on a uniform decimal clock are held as the clock.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "ident_cases.h"
#include "support/live_heap.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/ident/stats/monte_carlo.h"

namespace uuvplan::ident {
namespace {

// The long-log benchmark case in small (bench/cases/position_surge_truth.yaml: position alone at
// 100 Hz, σ 1 cm), 300 s of force legs: 30,001 position samples.
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

std::uint64_t Bits(double x) {
  std::uint64_t b = 0;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

// A time column as the CSV reader reads it: the decimal text of each time (`decimals` digits)
// parsed to the nearest double, as std::strtod does.
std::vector<double> ParsedClock(long long first, long long step, int decimals, std::size_t n) {
  std::vector<double> t(n);
  long long scale = 1;
  for (int d = 0; d < decimals; ++d) scale *= 10;
  char text[64];
  for (std::size_t i = 0; i < n; ++i) {
    const long long v = first + static_cast<long long>(i) * step;
    std::snprintf(text, sizeof text, "%lld.%0*lld", v / scale, decimals, v % scale);
    t[i] = std::strtod(text, nullptr);
  }
  return t;
}

TEST(SharedTimesTest, ALogOnADecimalClockIsHeldAsTheClockEveryTimeBitForBit) {
  // 200,000 rows at 100 Hz from t = 1234.56 s, shifted to the fourth row as the log's reader
  // shifts them (KeptSamples: t − offset): the clock must give back every one of those doubles.
  const std::vector<double> logged = ParsedClock(123456, 1, 2, 200000);
  const double offset = logged[3];
  std::vector<double> t;
  for (std::size_t i = 3; i < logged.size(); ++i) t.push_back(logged[i] - offset);
  SharedTimes s = t;
  s.CompactUniform(offset);
  ASSERT_TRUE(s.uniform());
  ASSERT_EQ(s.size(), t.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < t.size(); ++i) differing += Bits(s[i]) != Bits(t[i]);
  EXPECT_EQ(differing, 0u);
  // Read as a sequence too (binary search, iteration), and given back as the same vector.
  EXPECT_EQ(std::upper_bound(s.begin(), s.end(), 777.777) - s.begin(),
            std::upper_bound(t.begin(), t.end(), 777.777) - t.begin());
  EXPECT_TRUE(std::equal(s.begin(), s.end(), t.begin(), t.end()));
  const SharedTimes copy = s;
  EXPECT_TRUE(copy.SharesWith(s));
  EXPECT_EQ(SharedTimes(s).Release(), t);
  // A change turns the clock into a vector holding the same times and the new one.
  s.push_back(t.back() + 1.0);
  EXPECT_FALSE(s.uniform());
  EXPECT_FALSE(s.SharesWith(copy));
  EXPECT_TRUE(std::equal(t.begin(), t.end(), s.begin()));
  EXPECT_EQ(s.back(), t.back() + 1.0);
}

TEST(SharedTimesTest, TimesGivenOneByOneAreTheClockCompactUniformFinds) {
  // SharedTimes::Of reads the times without storing them: the same clock as a vector of them
  // compacted, every time bit for bit; off a clock, the vector of them.
  const std::vector<double> logged = ParsedClock(123456, 1, 2, 200000);
  const double offset = logged[3];
  const auto at = [&](std::size_t i) { return logged[i + 3] - offset; };
  const SharedTimes s = SharedTimes::Of(logged.size() - 3, at, offset);
  ASSERT_TRUE(s.uniform());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < s.size(); ++i) differing += Bits(s[i]) != Bits(at(i));
  EXPECT_EQ(differing, 0u);
  // A slice of the clock (its n0 moved) gives the same doubles.
  const model::TimesView tail = s.view().Slice(1000, s.size());
  for (std::size_t i = 0; i < tail.size(); i += 997)
    differing += Bits(tail[i]) != Bits(s[1000 + i]);
  EXPECT_EQ(differing, 0u);
  std::vector<double> jittered = ParsedClock(0, 1, 2, 1000);
  jittered[500] += 1e-6;
  const SharedTimes j = SharedTimes::Of(
      jittered.size(), [&](std::size_t i) { return jittered[i]; }, 0.0);
  EXPECT_FALSE(j.uniform());
  EXPECT_TRUE(std::equal(j.begin(), j.end(), jittered.begin(), jittered.end()));
}

TEST(SharedTimesTest, TimesOffAClockStayAVector) {
  // Jittered (a logger's own timestamps), or a missing row: not a clock; nothing changes.
  std::vector<double> jittered = ParsedClock(0, 1, 2, 1000);
  jittered[500] += 1e-6;
  std::vector<double> gap = ParsedClock(0, 1, 2, 1000);
  gap.erase(gap.begin() + 400);
  for (const std::vector<double>& t : {jittered, gap}) {
    SharedTimes s = t;
    s.CompactUniform(0.0);
    EXPECT_FALSE(s.uniform());
    EXPECT_EQ(SharedTimes(s).Release(), t);
  }
  // Times that are k·0.01 computed in binary (not parsed decimals) are off the clock too
  // wherever k·0.01 is not the double nearest k/100: held as they are, never changed.
  std::vector<double> computed(1000);
  for (std::size_t k = 0; k < computed.size(); ++k) computed[k] = static_cast<double>(k) * 0.01;
  SharedTimes c = computed;
  c.CompactUniform(0.0);
  EXPECT_EQ(SharedTimes(c).Release(), computed);
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
  EXPECT_EQ(SharedTimes(a).Release(), (std::vector<double>{0.0, 0.1, 0.2}));
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
  EXPECT_TRUE(std::equal(d.position.t.begin(), d.position.t.end(), copied.position.t.begin(),
                         copied.position.t.end()));
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

TEST(PreparedTrialMemoryTest, TimesReadFromADecimalClockAreHeldAsTheClock) {
  // The same log with its times as a CSV gives them (decimal text, parsed): the trial keeps
  // no vector of times (8 B a sample), and every time it reads is the one logged, shifted.
  model::Campaign logged = PositionLegs();
  std::vector<double>& t = logged.trials[0].log.t;
  t = ParsedClock(0, 1, 2, t.size());
  const TrialData d = PrepareTrial(logged.trials[0], 0, logged.vehicle, TrialDataOptions{});
  ASSERT_GT(d.position.size(), 30000u);
  EXPECT_TRUE(d.position.t.uniform());
  EXPECT_TRUE(d.velocity_estimate.t.SharesWith(d.position.t));
  const std::vector<double>& y = logged.trials[0].log.position[model::Index(model::Dof::kSurge)];
  std::vector<double> kept;  // KeptSamples' rows: a position, at or after t = 0
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (!std::isnan(y[i]) && t[i] >= d.time_offset) kept.push_back(t[i] - d.time_offset);
  }
  ASSERT_EQ(kept.size(), d.position.size());
  std::size_t differing = 0;
  for (std::size_t i = 0; i < kept.size(); ++i) differing += Bits(d.position.t[i]) != Bits(kept[i]);
  EXPECT_EQ(differing, 0u);
}

TEST(PreparedTrialMemoryTest, AForceLoggedAtEveryRowIsHeldOnceAndReadInPlace) {
  // A sine logged at 100 Hz (a new force value every row, on a decimal clock): the trial's hold
  // reads the trial's own force rows (no second copy of 20 bytes a row), its times are the
  // clock's, and its breakpoints are the rows' times strictly inside (0, duration): all but
  // the first and the last.
  model::Campaign c = PositionLegs();
  model::TrialLog& log = c.trials[0].log;
  log.t = ParsedClock(0, 1, 2, log.t.size());
  std::vector<double>& f = log.force[model::Index(model::Dof::kSurge)];
  for (std::size_t i = 0; i < f.size(); ++i) f[i] = 60.0 * std::sin(2 * M_PI * log.t[i] / 40.0);
  const TrialData d = PrepareTrial(c.trials[0], 0, c.vehicle, TrialDataOptions{});
  ASSERT_EQ(d.force.size(), f.size());
  EXPECT_TRUE(d.force_t.uniform());
  const model::TimesView breaks = d.breakpoints();
  ASSERT_EQ(breaks.size(), d.force.size() - 2);
  EXPECT_NE(breaks.clock(), nullptr);  // a slice of the clock, not a list
  std::size_t differing = 0;
  for (std::size_t i = 0; i < breaks.size(); i += 101) {
    differing += Bits(breaks[i]) != Bits(d.force_t[i + 1]);
    differing += d.input->Force(breaks[i]) != d.force[i + 1];
    differing += d.input->Force(breaks[i] - 1e-6) != d.force[i];
  }
  EXPECT_EQ(differing, 0u);
}

}  // namespace
}  // namespace uuvplan::ident
