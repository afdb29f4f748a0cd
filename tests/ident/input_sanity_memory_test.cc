// Issue #16: the unit and sign check of a long log holds memory in proportion to the columns it
// reads, not a dense regression of them: its force balance is summed sample by sample
// (ident/src/centred_moments.h) over the Savitzky–Golay samples streamed by ForEachSmoothed.
#include <gtest/gtest.h>

#include <iostream>

#include "ident_cases.h"
#include "support/live_heap.h"
#include "uuvplan/ident/input_sanity.h"
#include "uuvplan/model/campaign_builder.h"

namespace uuvplan::ident {
namespace {

TEST(InputSanityMemoryTest, LiveHeapOfTheCheckIsTheFiniteColumnsItReads) {
  if (!uuvplan::testing::HeapCountingAvailable())
    GTEST_SKIP() << "a sanitizer build counts no heap";
  // ROMEO surge with a sonar-like position sensor alone at 100 Hz (the issue #16 case at 1/10
  // of its length: 100,000 rows), force legs of ±25/50 N. The check copies the finite samples
  // of the two columns it reads (force and position: t and value, 32 B a row) and holds O(1)
  // more; under 40 B a row leaves room for those copies' small vectors. The dense check it
  // replaces held the n × 3 regression matrix and its QR (48 B a row), four sample columns
  // grown by doubling (up to 64) and the stored smoothed signal (36): about 180 B a row.
  model::Truth truth = testing::CaseTruth("romeo");
  truth.vehicle.sensors[model::Dof::kSurge] = model::DofSensors{};
  truth.vehicle.sensors[model::Dof::kSurge].position = model::SensorSpec{100.0, 0.01};
  std::vector<std::pair<double, double>> legs;
  for (int i = 0; legs.size() < 50; ++i) legs.push_back({(i % 2 ? -25.0 : 50.0), 20.0});
  model::VirtualCampaignOptions vo;
  vo.seed = 16;
  const model::Campaign c = model::BuildVirtualCampaign(
      truth, {testing::Segments("long", model::Dof::kSurge, "surge-front", legs)}, vo);
  const long long rows = static_cast<long long>(c.trials.front().log.size());
  ASSERT_GT(rows, 99000);
  uuvplan::testing::StartCountingHeap();
  const std::vector<InputProblem> problems = CheckInputSanity(c);
  const long long peak = uuvplan::testing::StopCountingHeap();
  EXPECT_TRUE(problems.empty());  // correct logs: nothing found (the check still ran its fits)
  EXPECT_LT(peak, 40LL * rows) << rows << " rows, peak live heap " << peak << " B";
  std::cout << rows << " rows, peak live heap " << peak / 1e6 << " MB (" << peak / rows << " B a row)\n";
}

}  // namespace
}  // namespace uuvplan::ident
