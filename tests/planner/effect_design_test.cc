// Designs for effects: a vehicle file whose identified model has a thruster lag is
// planned with the lag in its Fisher information (the planner's model is the standard one plus
// the file's effects, dof_planning_problem.cc), so the schedule predicts σ(lag); Monte Carlo over
// the schedule run in the virtual pool and identified confirms it.
#include "support/effect_design.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "uuvplan/io/pool_yaml.h"
#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::planner {
namespace {

// Predicted σ(lag) (the Cramér–Rao bound, worst over the ± 3σ box) against the spread of the
// identified lag over 10 seeds. The ratio must lie in (1/2, 2): the sample standard deviation of
// 10 draws is within ±45% of σ with 95% probability (χ² with 9 degrees of freedom), and the
// prediction is a worst case over a narrow box (30 seeds: docs/validation.md, "Designs for
// effects").
TEST(EffectDesign, PredictedSigmaOfALagIsWhatMonteCarloGives) {
  const std::string frame = std::string(UUVPLAN_SOURCE_DIR) + "/cases/payload60/";
  const uuvplan::testing::LagCase c = uuvplan::testing::MakeFrameLagCase(
      io::ReadTruth(frame + "frame/truth.yaml"), io::ReadPool(frame + "pool.yaml"), 0.15);
  ScheduleOptions o;
  o.dofs = {model::Dof::kSurge};
  const ScheduleResult plan = PlanSchedule(c.identified, c.pool, o);
  ASSERT_EQ(plan.status, PlanStatus::kOk) << plan.message;
  const auto& predicted = plan.schedule.predicted.at(model::Dof::kSurge).sigma;
  ASSERT_EQ(predicted.count(model::param::kLag), 1u);
  const double sigma = predicted.at(model::param::kLag);
  std::vector<model::TrialDesign> designs;
  for (const PlannedTrial& t : plan.schedule.trials) designs.push_back(t.design);
  const std::vector<uuvplan::testing::LagEstimate> lags =
      uuvplan::testing::IdentifiedLags(c, designs, 1, 10);
  ASSERT_EQ(lags.size(), 10u);
  double mean = 0.0, ss = 0.0;
  for (const auto& x : lags) mean += x.value / lags.size();
  for (const auto& x : lags) ss += (x.value - mean) * (x.value - mean);
  const double spread = std::sqrt(ss / (lags.size() - 1));
  EXPECT_NEAR(mean, 0.15, 3 * spread / std::sqrt(10.0));  // unbiased within its standard error
  EXPECT_GT(spread / sigma, 0.5) << "spread " << spread << " s, predicted " << sigma << " s";
  EXPECT_LT(spread / sigma, 2.0) << "spread " << spread << " s, predicted " << sigma << " s";
}

}  // namespace
}  // namespace uuvplan::planner
