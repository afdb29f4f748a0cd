// The information a schedule carries (information_table.h).
#include "uuvplan/planner/design/information_table.h"

#include <cmath>
#include <limits>
#include <memory>

#include "uuvplan/ident/stats/sub_matrix.h"
#include "uuvplan/planner/design/criteria.h"
#include "uuvplan/planner/design/dof_planning_problem.h"

namespace uuvplan::planner {
InformationSummary SummariseInformation(model::Dof dof, const std::vector<std::string>& names,
                                        const Eigen::VectorXd& theta, const Eigen::MatrixXd& M) {
  InformationSummary s;
  s.dof = dof;
  s.names = names;
  s.theta = theta;
  s.fisher = M;
  const Eigen::MatrixXd R = RelativeInformation(M, theta);
  const CriterionValue d = EvaluateCriterion(R, Criterion::kD, {});
  s.d = d.value;
  s.a = EvaluateCriterion(R, Criterion::kA, {}).value;
  s.e = EvaluateCriterion(R, Criterion::kE, {}).value;
  s.singular = d.singular;
  s.sigma = PredictedSigma(M, theta);
  const std::vector<int> P = InformedParameters(R);
  s.condition_number = std::numeric_limits<double>::infinity();
  if (!P.empty()) {
    const Eigen::VectorXd lambda =
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(ident::SubMatrix(R, P)).eigenvalues();
    if (lambda.minCoeff() > kSingularThreshold) {
      s.condition_number = lambda.maxCoeff() / lambda.minCoeff();
    }
  }
  return s;
}

ScheduleInformation InformationOf(const model::Vehicle& vehicle, const model::Pool& pool,
                                  const Schedule& schedule, const ScheduleOptions& options) {
  ScheduleInformation result;
  std::map<model::Dof, std::unique_ptr<DofPlanningProblem>> contexts;
  std::map<model::Dof, Eigen::MatrixXd> totals;
  std::vector<std::string> notes;  // the planner's own notes were printed with the schedule
  for (const PlannedTrial& t : schedule.trials) {
    const model::Dof dof = t.design.dof;
    auto& ctx = contexts[dof];
    if (!ctx) ctx = DofPlanningProblem::APriori(vehicle, pool, dof, options.planner, &notes);
    const Eigen::VectorXd& centre = ctx->design_thetas()[0];  // DesignPoints(): centre first
    const Eigen::MatrixXd M = ctx->Information(t.design)[0];
    result.trials.push_back(SummariseInformation(dof, ctx->model().parameter_names(), centre, M));
    auto total = totals.find(dof);
    if (total == totals.end()) {
      totals.emplace(dof, M);
    } else {
      total->second += M;
    }
  }
  for (const auto& [dof, M] : totals) {
    const DofPlanningProblem& ctx = *contexts.at(dof);
    result.dofs[dof] =
        SummariseInformation(dof, ctx.model().parameter_names(), ctx.design_thetas()[0], M);
  }
  return result;
}

}  // namespace uuvplan::planner
