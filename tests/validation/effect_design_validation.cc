// Full-size validation of designs for effects (docs/validation.md "Designs for effects"): the
// surge schedule of payload60's frame planned about an identified model with a 0.15 s thruster
// lag (tests/support/effect_design.h), run in the virtual pool on N seeds and identified by
// `identify` reading that model. Claims: the schedule predicts σ(lag); the spread of the
// identified lag is within a factor 1.5 of it (N = 30: the sample standard deviation is within
// ±26% of σ with 95% probability) and its mean within 3 standard errors of the truth; the σ
// identify reports are within a factor 1.5 of the spread. Exit status 1 when a claim fails.
//
//   effect_design_validation [N=30] [first_seed=1]
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>
#include <vector>

#include "support/effect_design.h"
#include "uuvplan/io/pool_yaml.h"
#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/planner/schedule_planner.h"

int main(int argc, char** argv) {
  namespace t = uuvplan::testing;
  using namespace uuvplan;  // NOLINT: a validation program
  const int n = argc > 1 ? std::atoi(argv[1]) : 30;
  const std::uint64_t first = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  const std::string dir = std::string(UUVPLAN_SOURCE_DIR) + "/cases/payload60/";
  const double lag = 0.15;
  const t::LagCase c = t::MakeFrameLagCase(io::ReadTruth(dir + "frame/truth.yaml"),
                                           io::ReadPool(dir + "pool.yaml"), lag);
  planner::ScheduleOptions o;
  o.dofs = {model::Dof::kSurge};
  const planner::ScheduleResult plan = planner::PlanSchedule(c.identified, c.pool, o);
  const auto& predicted = plan.schedule.predicted.at(model::Dof::kSurge).sigma;
  if (plan.status != planner::PlanStatus::kOk || !predicted.count(model::param::kLag)) {
    std::cout << "the schedule predicts no σ(lag): " << plan.message << std::endl;
    return 1;
  }
  std::vector<model::TrialDesign> designs;
  for (const auto& tr : plan.schedule.trials) designs.push_back(tr.design);
  const std::vector<t::LagEstimate> lags = t::IdentifiedLags(c, designs, first, n);
  double mean = 0.0, ss = 0.0, reported = 0.0;
  for (const auto& x : lags) mean += x.value / lags.size();
  for (const auto& x : lags) {
    ss += (x.value - mean) * (x.value - mean);
    reported += x.sigma / lags.size();
  }
  const double spread = std::sqrt(ss / (lags.size() - 1)), sigma = predicted.at("lag");
  std::cout << plan.schedule.trials.size() << " trials; lag identified on " << lags.size() << "/"
            << n << " seeds: mean " << mean << " s (truth " << lag << "), spread " << spread
            << " s; predicted σ " << sigma << " s (ratio " << spread / sigma
            << "); mean reported σ " << reported << " s (spread / reported " << spread / reported
            << ")" << std::endl;
  const bool pass = static_cast<int>(lags.size()) == n && spread / sigma < 1.5 &&
                    spread / sigma > 1 / 1.5 && spread / reported < 1.5 &&
                    spread / reported > 1 / 1.5 &&
                    std::abs(mean - lag) < 3 * spread / std::sqrt(lags.size());
  return pass ? 0 : 1;
}
