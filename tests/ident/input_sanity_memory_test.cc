// The unit and sign check of a long log holds memory in proportion to the columns it
// reads, not a dense regression of them: its force balance is summed sample by sample
// (ident/src/stats/centred_moments.h) over the Savitzky–Golay samples streamed by ForEachSmoothed.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>

#include "ident_cases.h"
#include "support/live_heap.h"
#include "uuvplan/ident/prepare/input_sanity.h"
#include "uuvplan/model/campaign_builder.h"

namespace uuvplan::ident {
namespace {

// ROMEO surge with a sonar-like position sensor alone at 100 Hz (the long-log benchmark case at
// 1/10 of its length: 100,000 rows; the force logged at 20 Hz, ~2% of the positions dropped out),
// force legs of ±25/50 N.
model::Campaign LongSurgeCampaign() {
  model::Truth truth = testing::CaseTruth("romeo");
  truth.vehicle.sensors[model::Dof::kSurge] = model::DofSensors{};
  truth.vehicle.sensors[model::Dof::kSurge].position = model::SensorSpec{100.0, 0.01};
  std::vector<std::pair<double, double>> legs;
  for (int i = 0; legs.size() < 50; ++i) legs.push_back({(i % 2 ? -25.0 : 50.0), 20.0});
  model::VirtualCampaignOptions vo;
  vo.seed = 16;
  return model::BuildVirtualCampaign(
      truth, {testing::Segments("long", model::Dof::kSurge, "surge-front", legs)}, vo);
}

TEST(InputSanityMemoryTest, LiveHeapOfTheCheckIsTheFiniteColumnsItReads) {
  if (!uuvplan::testing::HeapCountingAvailable())
    GTEST_SKIP() << "a sanitizer build counts no heap";
  // The check copies the finite samples
  // of the two columns it reads (force and position: t and value, 32 B a row) and holds O(1)
  // more; under 40 B a row leaves room for those copies' small vectors. The dense check it
  // replaces held the n × 3 regression matrix and its QR (48 B a row), four sample columns
  // grown by doubling (up to 64) and the stored smoothed signal (36): about 180 B a row.
  const model::Campaign c = LongSurgeCampaign();
  const long long rows = static_cast<long long>(c.trials.front().log.size());
  ASSERT_GT(rows, 99000);
  uuvplan::testing::StartCountingHeap();
  const std::vector<InputProblem> problems = CheckInputSanity(c);
  const long long peak = uuvplan::testing::StopCountingHeap();
  EXPECT_TRUE(problems.empty());  // correct logs: nothing found (the check still ran its fits)
  EXPECT_LT(peak, 40LL * rows) << rows << " rows, peak live heap " << peak << " B";
  std::cout << rows << " rows, peak live heap " << peak / 1e6 << " MB (" << peak / rows
            << " B a row)\n";
}

TEST(InputSanityMemoryTest, ALentLogIsCheckedWithoutACopyAndGivenBackUnchanged) {
  if (!uuvplan::testing::HeapCountingAvailable())
    GTEST_SKIP() << "a sanitizer build counts no heap";
  // The command line lends the campaign's logs to the check (CheckInputSanity(Campaign*)): a
  // column with no gap goes into its signal and the times are shared; else the one column with
  // few gaps is compacted in place, its dropped rows set aside. The same findings as from a
  // copy, and the log given back bit for bit. In this case the force is logged at 20 Hz (NaN
  // between) and the position has ~2% dropouts, so the position is compacted and the force's
  // finite samples copied. The check's heap is then at most: that copy (t and value, 16 B a
  // sample), the dropped rows (24 B each, twice that for the vector's doubling), MedianStep's
  // sample of at most 40,000 steps (8 B each) and 64 kB for the O(1) sums, runs and texts. A
  // copy of the position (16 B a finite sample, 1.6 MB here) does not fit under it.
  model::Campaign c = LongSurgeCampaign();
  for (const bool gaps : {false, true}) {
    model::TrialLog& log = c.trials.front().log;
    if (gaps) {  // a gap every 997 rows (0.1%) and a sign flip that the check must still name
      std::vector<double>& pos = log.position[model::Index(model::Dof::kSurge)];
      for (std::size_t i = 5; i < pos.size(); i += 997) pos[i] = std::nan("");
      for (double& f : log.force[model::Index(model::Dof::kSurge)]) f = -f;
    }
    const model::TrialLog before = log;
    const long long rows = static_cast<long long>(log.size());
    const std::vector<InputProblem> copied =
        CheckInputSanity(static_cast<const model::Campaign&>(c));
    uuvplan::testing::StartCountingHeap();
    const std::vector<InputProblem> lent = CheckInputSanity(&c);
    const long long peak = uuvplan::testing::StopCountingHeap();
    ASSERT_EQ(lent.size(), copied.size()) << (gaps ? "with gaps" : "without gaps");
    for (std::size_t k = 0; k < lent.size(); ++k) EXPECT_EQ(lent[k].Text(), copied[k].Text());
    EXPECT_EQ(lent.size(), gaps ? 1u : 0u);  // the flipped force is named, else nothing
    auto same_bits = [](const std::vector<double>& a, const std::vector<double>& b) {
      return a.size() == b.size() &&
             std::equal(a.begin(), a.end(), b.begin(),
                        [](double x, double y) { return std::memcmp(&x, &y, sizeof x) == 0; });
    };
    EXPECT_TRUE(same_bits(log.t, before.t));
    for (int d = 0; d < model::kNumDofs; ++d) {
      EXPECT_TRUE(same_bits(log.force[d], before.force[d])) << d;
      EXPECT_TRUE(same_bits(log.position[d], before.position[d])) << d;
      EXPECT_TRUE(same_bits(log.velocity[d], before.velocity[d])) << d;
    }
    auto finite = [](const std::vector<double>& y) {
      return static_cast<long long>(
          std::count_if(y.begin(), y.end(), [](double v) { return std::isfinite(v); }));
    };
    const long long force_samples = finite(log.force[model::Index(model::Dof::kSurge)]);
    const long long dropped = rows - finite(log.position[model::Index(model::Dof::kSurge)]);
    const long long bound = 16 * force_samples + 48 * dropped + 8 * 40000 + 64000;
    EXPECT_LT(peak, bound) << rows << " rows, peak live heap " << peak << " B";
    EXPECT_LT(bound, 16 * (rows - dropped)) << "the bound must exclude a copy of the position";
    std::cout << (gaps ? "with gaps: " : "no gaps: ") << rows << " rows, peak live heap " << peak
              << " B (" << double(peak) / rows << " B a row)\n";
  }
}

}  // namespace
}  // namespace uuvplan::ident
