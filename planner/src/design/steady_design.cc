// The steady design's steps (steady_design.h): candidates, approximate design, exact design,
// packing, and the criterion of the packed trials.
#include "uuvplan/planner/design/steady_design.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <sstream>

#include "design/steady_legs.h"
#include "options_check.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/criteria.h"

namespace uuvplan::planner {

using internal::DirName;

bool SteadyDesignOptions::IsValid(std::string* error) const {
  internal::OptionsCheck check("SteadyDesignOptions", error);
  check.Require(legs >= 0, "legs", legs, ">= 0")
      .Require(levels >= 1, "levels", levels, ">= 1")
      .Require(settle_tolerance > 0 && settle_tolerance < 1, "settle_tolerance", settle_tolerance,
               "0 < tol < 1")
      .Require(min_hold_s > 0, "min_hold_s", min_hold_s, "> 0")
      .Require(speed_rel_sigma > 0, "speed_rel_sigma", speed_rel_sigma, "> 0")
      .Require(max_legs_per_trial >= 1, "max_legs_per_trial", max_legs_per_trial, ">= 1");
  return check.ok();
}

namespace {

// Step 2: the information of each candidate from rest (M[c][j] at design point j).
std::vector<std::vector<Eigen::MatrixXd>> CandidateInformation(const DofPlanningProblem& ctx,
                                                               const std::vector<SteadyLeg>& legs) {
  std::vector<std::vector<Eigen::MatrixXd>> M;
  for (const SteadyLeg& leg : legs) M.push_back(ctx.Information(LegDesign(leg, ctx.dof(), "")));
  return M;
}

// Number of legs: the options', or every informed parameter but m plus 2.
int LegCount(const DofPlanningProblem& ctx, const SteadyDesignOptions& o,
             const std::vector<std::vector<Eigen::MatrixXd>>& M) {
  if (o.legs != 0) return o.legs;
  const int np = ctx.model().num_parameters();
  Eigen::MatrixXd total = Eigen::MatrixXd::Zero(np, np);
  for (const auto& m : M) total += RelativeInformation(m[0], ctx.design_thetas()[0]);
  return static_cast<int>(InformedParameters(total).size()) - 1 + 2;
}

// Step 2: the approximate design's weights; false (status and message set) if it failed.
bool SolveWeights(const DofPlanningProblem& ctx, const SteadyDesignOptions& o,
                  const std::vector<std::vector<Eigen::MatrixXd>>& M, int N,
                  const std::vector<Eigen::MatrixXd>& prior, SteadyDesignResult* result) {
  const DesignProblem problem = SteadyWeightsProblem(ctx, M, N, prior, o.criterion);
  SolverOptions so = ctx.options().solver;
  so.robustness = ctx.options().robustness;
  so.global = GlobalMethod::kNone;  // concave: a local method finds the global optimum
  so.max_local_evaluations = std::max(so.max_local_evaluations, 200);
  result->summary = Solve(ctx.options().steady_backend, problem, so);
  if (!result->summary.is_success()) {
    result->status = DesignStatus::kFailed;
    result->message = "approximate design: " + result->summary.BriefReport();
    return false;
  }
  result->weights = result->summary.x;
  return true;
}

// A leg the exact design runs more than once is a replicate, not a slip: the D-optimal
// weights put that share of the N legs on it (efficient rounding of N·w, Pukelsheim & Rieder
// 1992), so a schedule may list the same run twice.
void NoteReplicates(const DofPlanningProblem& ctx, const std::vector<SteadyLeg>& legs, int N,
                    SteadyDesignResult* result) {
  std::map<std::pair<std::string, double>, int> count;
  for (const SteadyLeg& l : legs) ++count[{l.mapping, l.force}];
  for (const auto& [leg, n] : count) {
    if (n < 2) continue;
    result->notes.push_back(
        std::string(model::DofName(ctx.dof())) + ": the steady run " +
        DirName(leg.first, leg.second > 0 ? 1 : -1) + " at " + model::Significant(leg.second, 3) +
        " " + std::string(model::ForceUnit(ctx.dof())) + " runs " + std::to_string(n) +
        " times: the D-optimal design puts " + std::to_string(n) + " of its " + std::to_string(N) +
        " legs there (replicates, not a repeated entry)");
  }
}

// The criterion of the packed trials with the prior, and the status and notes.
void Summarise(const DofPlanningProblem& ctx, const SteadyDesignOptions& o,
               const std::vector<Eigen::MatrixXd>& prior, const std::string& infeasible,
               SteadyDesignResult* result) {
  const std::string dof(model::DofName(ctx.dof()));
  const std::vector<Eigen::MatrixXd> total = WithPrior(result->information, prior);
  std::vector<int> interest;
  for (int i : InformedParameters(RelativeInformation(total[0], ctx.design_thetas()[0]))) {
    if (i != 0) interest.push_back(i);
  }
  bool singular = false;
  result->criterion_per_point = ctx.CriterionValues(total, o.criterion, interest, &singular);
  result->criterion = Aggregate(ctx.options().robustness, result->criterion_per_point);
  bool all_ok = true;
  for (const auto& c : result->checks) all_ok = all_ok && c.feasible;
  if (!all_ok) {
    result->status = DesignStatus::kInfeasible;
    result->message = "a packed steady trial violates a hard constraint";
    return;
  }
  result->status = DesignStatus::kOk;
  if (singular) {
    result->notes.push_back(dof +
                            ": the steady runs alone leave a combination of drag, bias "
                            "and eta undetermined; the other trials must resolve it");
  }
  if (!infeasible.empty()) {
    result->notes.push_back(dof + ": some directions cannot be run in this pool:" + infeasible);
  }
}

}  // namespace

SteadyDesignResult DesignSteady(const DofPlanningProblem& ctx, const SteadyDesignOptions& o,
                                const std::vector<Eigen::MatrixXd>& prior,
                                const std::string& id_prefix) {
  SteadyDesignResult result;
  std::string error;
  if (!o.IsValid(&error) || !ctx.options().IsValid(&error)) {
    result.message = error;
    return result;
  }
  // 1. Candidates per mapping and direction.
  SteadyCandidates cands = MakeSteadyCandidates(ctx, o);
  result.candidates = cands.legs;
  result.required_travel = cands.required_travel;
  for (const auto& n : cands.notes) result.notes.push_back(n);
  if (result.candidates.empty()) {
    result.status = DesignStatus::kInfeasible;
    result.message =
        "no steady run of " + std::string(model::DofName(ctx.dof())) + " fits:" + cands.infeasible;
    return result;
  }
  // 2. Information of each candidate from rest, and the approximate design.
  const auto M = CandidateInformation(ctx, result.candidates);
  const int N = LegCount(ctx, o, M);
  if (!SolveWeights(ctx, o, M, N, prior, &result)) return result;
  // 3. Exact design.
  result.legs = internal::ExactDesign(result.candidates, result.weights, N);
  if (result.legs.empty()) {
    result.status = DesignStatus::kFailed;
    result.message =
        "approximate design without support (no positive weight): " + result.summary.BriefReport();
    return result;
  }
  // 4. Pack legs into trials: alternate directions, compatible thrusters, within the pool.
  internal::PackTrials(ctx, o, id_prefix, &result);
  Summarise(ctx, o, prior, cands.infeasible, &result);
  NoteReplicates(ctx, result.legs, N, &result);
  return result;
}

}  // namespace uuvplan::planner
