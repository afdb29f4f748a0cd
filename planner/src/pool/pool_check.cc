// Pool check of a schedule (see pool_check.h).
#include "uuvplan/planner/pool/pool_check.h"

#include <algorithm>
#include <cmath>
#include <memory>

#include "uuvplan/ident/stats/sub_matrix.h"

namespace uuvplan::planner {
namespace {

// D criterion on the parameters P only (relative units).
double DOn(const Eigen::MatrixXd& R, const std::vector<int>& P) {
  std::vector<int> all(P.size());
  for (std::size_t a = 0; a < P.size(); ++a) all[a] = static_cast<int>(a);
  return EvaluateCriterion(ident::SubMatrix(R, P), Criterion::kD, all).value;
}

}  // namespace

PoolCheckResult CheckPool(const model::Vehicle& vehicle, const model::Pool& pool,
                          const Schedule& plan, const PoolCheckOptions& o) {
  PoolCheckResult result;
  result.feasible = true;
  std::map<model::Dof, std::unique_ptr<DofPlanningProblem>> contexts;
  std::vector<model::Dof> order;
  auto context = [&](model::Dof dof) -> DofPlanningProblem& {
    auto it = contexts.find(dof);
    if (it == contexts.end()) {
      it = contexts
               .emplace(dof, DofPlanningProblem::APriori(vehicle, pool, dof, o.schedule.planner,
                                                         &result.notes))
               .first;
      order.push_back(dof);
    }
    return *it->second;
  };
  double span[model::kNumDofs] = {0, 0, 0, 0, 0, 0};
  for (const auto& t : plan.trials) {
    TrialPoolCheck c;
    c.id = t.design.id;
    c.dof = t.design.dof;
    c.check = context(t.design.dof).Check(t.design);
    span[model::Index(c.dof)] = std::max(span[model::Index(c.dof)], c.check.span);
    result.feasible = result.feasible && c.check.feasible;
    result.trials.push_back(std::move(c));
  }
  result.required_length = pool.WallToWallFor(span[model::Index(model::Dof::kSurge)]);
  result.required_width = pool.WallToWallFor(span[model::Index(model::Dof::kSway)]);
  result.required_depth = pool.WallToWallFor(span[model::Index(model::Dof::kHeave)]);
  if (plan.trials.empty()) {
    result.notes.push_back("the plan has no trials");
  }
  if (result.feasible || !o.plan_alternative || order.empty()) return result;

  ScheduleOptions so = o.schedule;
  so.dofs = order;
  result.alternative = PlanSchedule(vehicle, pool, so);
  result.has_alternative = true;
  for (model::Dof dof : order) {
    DofPlanningProblem& ctx = *contexts.at(dof);
    const auto plan_info = TrialsInformation(ctx, plan.trials);
    auto it = std::find_if(result.alternative.dofs.begin(), result.alternative.dofs.end(),
                           [&](const DofPlan& dp) { return dp.dof == dof; });
    const std::vector<int> P =
        InformedParameters(RelativeInformation(plan_info[0], ctx.design_thetas()[0]));
    const int p = static_cast<int>(P.size());
    if (it == result.alternative.dofs.end() || it->status != DesignStatus::kOk || p == 0) {
      result.information_loss[dof] = 1.0;
      continue;
    }
    // Both on the plan's parameters, same box, same model.
    const auto alt_info = TrialsInformation(ctx, it->trials);
    std::vector<double> d_plan, d_alt;
    for (std::size_t j = 0; j < plan_info.size(); ++j) {
      d_plan.push_back(DOn(RelativeInformation(plan_info[j], ctx.design_thetas()[j]), P));
      d_alt.push_back(DOn(RelativeInformation(alt_info[j], ctx.design_thetas()[j]), P));
    }
    const double D_plan = Aggregate(ctx.options().robustness, d_plan);
    const double D_alt = Aggregate(ctx.options().robustness, d_alt);
    result.information_loss[dof] = 1.0 - std::exp((D_alt - D_plan) / p);
  }
  return result;
}

}  // namespace uuvplan::planner
