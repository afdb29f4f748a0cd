// The sine family's objective (sine_family_objective.h).
#include "design/sine_family_objective.h"

#include <algorithm>
#include <cmath>

#include "design/travel_margin.h"

namespace uuvplan::planner {

SineFamilyObjective::SineFamilyObjective(const DofPlanningProblem& ctx, const SineDesignOptions& o,
                                         const std::vector<Eigen::MatrixXd>& prior,
                                         double force_abs, double duration, int harmonics)
    : ctx_(ctx),
      criterion_(o.criterion),
      prior_(prior),
      interest_(ctx.Indices(o.interest)),
      omega_(SineFrequencyRange(ctx, force_abs, o.min_periods, duration, harmonics)) {}

double SineFamilyObjective::Criteria(const DofPlanningProblem::TrialModel& tm,
                                     const model::Excitation& input, double duration,
                                     double* phi) const {
  std::array<double, 2> travel;
  const std::vector<double> criteria =
      ctx_.CriterionValues(WithPrior(ctx_.DesignInformation(tm, input, duration, &travel), prior_),
                           criterion_, interest_);
  std::copy(criteria.begin(), criteria.end(), phi);
  return travel[1] - travel[0];
}

double SineFamilyObjective::TravelExcess(double span) const {
  const double avail = ctx_.available();
  return std::isfinite(avail) ? (span - (avail - kSineTravelMargin)) / avail : -1.0;
}

double SineFamilyObjective::Omega(double v) const {
  return omega_[0] * std::pow(omega_[1] / omega_[0], std::clamp(v, 0.0, 1.0));
}

}  // namespace uuvplan::planner
