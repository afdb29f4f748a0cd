// The whole schedule, the next trial, and predicted precision (see schedule_planner.h).
#include "uuvplan/planner/schedule_planner.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "options_check.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/util/numbers.h"
#include "uuvplan/model/util/parallel.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/switched_design.h"
#include "uuvplan/planner/design/trial_envelope.h"
#include "uuvplan/planner/determinacy.h"

namespace uuvplan::planner {

constexpr model::EnumNames<PlanStatus, 3> kPlanStatusNames{
    {{{PlanStatus::kOk, "ok"},
      {PlanStatus::kPartial, "partial"},
      {PlanStatus::kInfeasible, "infeasible"}}}};

std::string_view PlanStatusName(PlanStatus s) { return kPlanStatusNames.Name(s); }

bool ScheduleOptions::IsValid(std::string* error) const {
  for (const auto& [dof, p] : prior) {
    if (p.M.rows() != static_cast<Eigen::Index>(p.names.size()) || p.M.cols() != p.M.rows()) {
      if (error) {
        *error = "ScheduleOptions::prior[" + std::string(model::DofName(dof)) + "].M is " +
                 std::to_string(p.M.rows()) + " x " + std::to_string(p.M.cols()) + " for " +
                 std::to_string(p.names.size()) +
                 " names. Violated constraint: square, one row per name";
      }
      return false;
    }
  }
  const bool goal =
      internal::OptionsCheck("ScheduleOptions", error)
          .Require(precision.target_percent > 0 && std::isfinite(precision.target_percent),
                   "precision.target_percent", precision.target_percent, "> 0")
          .Require(precision.max_trials_to_target > 0, "precision.max_trials_to_target",
                   precision.max_trials_to_target, "> 0")
          .ok();
  return goal && planner.IsValid(error) && steady.IsValid(error) && sine.IsValid(error);
}

std::vector<Eigen::MatrixXd> TrialsInformation(const DofPlanningProblem& ctx,
                                               const std::vector<PlannedTrial>& trials,
                                               const PriorInformation* prior) {
  const Eigen::MatrixXd M0 = ctx.PriorMatrix(prior);
  std::vector<Eigen::MatrixXd> total(ctx.design_thetas().size(), M0);
  for (const auto& t : trials) {
    if (t.design.dof != ctx.dof()) continue;
    const auto info = ctx.Information(t.design);
    for (std::size_t j = 0; j < total.size(); ++j) total[j] += info[j];
  }
  return total;
}

PredictedPrecision PredictPrecision(const DofPlanningProblem& ctx,
                                    const std::vector<Eigen::MatrixXd>& info,
                                    std::vector<std::string>* notes) {
  PredictedPrecision p;
  p.criterion = std::string(CriterionName(Criterion::kD));
  const auto& names = ctx.model().parameter_names();
  std::vector<double> worst(names.size(), -1.0);
  std::vector<double> crit;
  for (std::size_t j = 0; j < info.size(); ++j) {
    const Eigen::VectorXd s = PredictedSigma(info[j], ctx.design_thetas()[j]);
    for (int i = 0; i < s.size(); ++i) {
      if (std::isnan(s[i])) continue;
      worst[i] = std::max(worst[i], s[i]);
    }
    crit.push_back(
        EvaluateCriterion(RelativeInformation(info[j], ctx.design_thetas()[j]), Criterion::kD, {})
            .value);
  }
  p.criterion_value = Aggregate(ctx.options().robustness, crit);
  const std::string dof(model::DofName(ctx.dof()));
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (worst[i] < 0) {
      if (notes) notes->push_back(dof + ": no trial reaches " + names[i] + " (not identified)");
    } else if (!std::isfinite(worst[i])) {
      if (notes) {
        notes->push_back(dof + ": " + names[i] +
                         " cannot be told apart from the other parameters by these trials");
      }
    } else {
      p.sigma[names[i]] = worst[i];
      // Ref 000 §IV-D: a percentile error above 51.02% means the parameter is statistically
      // insignificant at 95% (indistinguishable from zero).
      double nominal = std::numeric_limits<double>::infinity();
      for (const auto& th : ctx.design_thetas()) nominal = std::min(nominal, std::abs(th[i]));
      if (notes && nominal > 0 && worst[i] / nominal > 0.5102) {
        std::ostringstream s;
        s << dof << ": predicted σ(" << names[i] << ") = " << worst[i] << " is "
          << 100.0 * worst[i] / nominal
          << "% of its smallest a priori value: these trials would not determine it (seed 000: "
             "above 51% a parameter is insignificant)";
        notes->push_back(s.str());
      }
    }
  }
  return p;
}

namespace {

std::vector<model::Dof> DofsToPlan(const model::Vehicle& v, const ScheduleOptions& o) {
  if (!o.dofs.empty()) return o.dofs;
  std::vector<model::Dof> out;
  for (model::Dof d : model::kAllDofs) {
    auto s = v.sensors.find(d);
    const bool sensed = s != v.sensors.end() && (s->second.position || s->second.velocity);
    if (sensed && !v.MappingsOf(d).empty()) out.push_back(d);
  }
  return out;
}

std::vector<Eigen::MatrixXd> PriorPerPoint(const DofPlanningProblem& ctx,
                                           const PriorInformation* prior) {
  return std::vector<Eigen::MatrixXd>(ctx.design_thetas().size(), ctx.PriorMatrix(prior));
}

// The box about the estimates (± box_sigmas σ); an axis whose parameters have no estimate with
// a σ keeps the range of the box the vehicle gives (PlanningBox).
ParameterBox NextTrialBox(const model::Vehicle& vehicle, const model::Pool& pool, model::Dof dof,
                          const ParameterValues& estimates, const ParameterValues& sigmas,
                          const NextTrialOptions& o, std::vector<std::string>* notes) {
  std::unique_ptr<DofPlanningProblem> probe =
      DofPlanningProblem::APriori(vehicle, pool, dof, o.schedule.planner, notes);
  ParameterBox box = BoxAboutEstimates(probe->box(), probe->model().parameter_names(), estimates,
                                       sigmas, o.box_sigmas, o.schedule.planner.box);
  ClampToLeastInertia(vehicle, dof, probe->box(), &box, notes);
  return box;
}

// The DOF's trial families, each designed on the information of the prior and of the trials
// before it (in `info`, which gains theirs): steady runs, the sine, then the loop's families
// completing the schedule. Their trials, checks and notes go to `plan`; why a family could not
// be designed to `failures`.
void DesignFamilies(const DofPlanningProblem& ctx, const ScheduleOptions& o,
                    const std::string& name, std::vector<Eigen::MatrixXd>* info, DofPlan* plan,
                    std::vector<std::string>* failures) {
  if (o.steady_runs) {
    SteadyDesignResult st = DesignSteady(ctx, o.steady, *info, name + "-steady");
    for (auto& n : st.notes) plan->notes.push_back(std::move(n));
    if (st.status == DesignStatus::kOk) {
      for (std::size_t j = 0; j < info->size(); ++j) (*info)[j] += st.information[j];
      for (std::size_t i = 0; i < st.trials.size(); ++i) {
        plan->trials.push_back(st.trials[i]);
        plan->checks.push_back(st.checks[i]);
      }
    } else {
      failures->push_back("steady runs: " + st.message);
      plan->required_travel = std::max(plan->required_travel, st.required_travel);
    }
  }
  if (o.sine_trial) {
    SineDesignResult sn = DesignInertiaTrial(ctx, o.sine, *info, name + "-sine");
    for (auto& n : sn.notes) plan->notes.push_back(std::move(n));
    if (sn.status == DesignStatus::kOk) {
      for (std::size_t j = 0; j < info->size(); ++j) (*info)[j] += sn.information[j];
      plan->trials.push_back(sn.trial);
      plan->checks.push_back(sn.check);
    } else {
      failures->push_back("sine trial: " + sn.message);
      if (sn.check.span > 0) plan->required_travel = std::max(plan->required_travel, sn.check.span);
    }
  }
  if (o.max_completion_trials > 0) {
    CompletionResult extra = CompleteWithLoopFamilies(ctx, o.sine, o.steady, info, name + "-more",
                                                      o.max_completion_trials);
    for (std::size_t i = 0; i < extra.trials.size(); ++i) {
      plan->trials.push_back(extra.trials[i]);
      plan->checks.push_back(extra.checks[i]);
    }
    for (auto& n : extra.notes) plan->notes.push_back(std::move(n));
  }
}

// The steady runs and the sine of one DOF, each designed on the information of the prior and
// of the trials before it, with the DOF's status, message and predicted precision.
DofPlan PlanDof(const model::Vehicle& vehicle, const model::Pool& pool, model::Dof dof,
                const ScheduleOptions& o) {
  DofPlan plan;
  plan.dof = dof;
  const std::string name(model::DofName(dof));
  std::unique_ptr<DofPlanningProblem> ctx =
      DofPlanningProblem::APriori(vehicle, pool, dof, o.planner, &plan.notes);
  auto pit = o.prior.find(dof);
  const PriorInformation* user_prior = pit == o.prior.end() ? nullptr : &pit->second;
  std::vector<Eigen::MatrixXd> info = PriorPerPoint(*ctx, user_prior);
  std::vector<std::string> failures;
  DesignFamilies(*ctx, o, name, &info, &plan, &failures);
  plan.determinacy = InterestDeterminacy(*ctx, info);
  std::ostringstream m;
  for (const auto& f : failures) m << " " << f;
  if (plan.trials.empty()) {
    plan.status = DesignStatus::kInfeasible;
    plan.message = name + " cannot be planned in pool '" + pool.name + "':" + m.str();
    return plan;
  }
  plan.status = DesignStatus::kOk;
  // Complete: every parameter of interest determined, whichever families did it (a steady run
  // that does not fit is no loss when sines determine the drag).
  // ... and the loop's target reachable from them before its stuck rule stops it.
  // With the trials the loop would design next, one after the other.
  if (plan.determinacy.determined) {
    plan.reach = ReachTarget(*ctx, o.sine, o.steady, info, o.precision, name + "-next");
  }
  plan.complete = plan.determinacy.determined && plan.reach.reached;
  if (plan.complete) plan.required_travel = std::numeric_limits<double>::quiet_NaN();
  for (const auto& f : failures) plan.notes.push_back(name + ": " + f);
  if (plan.determinacy.determined && !plan.reach.reached) {
    plan.message = name + " is determined in pool '" + pool.name + "' but not to the target " +
                   model::Significant(o.precision.target_percent, 3) + "%: " + plan.reach.text +
                   "." + m.str();
  } else if (!plan.complete) {
    plan.message = name + " only partly determined in pool '" + pool.name +
                   "': " + model::Join(plan.determinacy.undetermined) +
                   " stay undetermined after " + std::to_string(plan.trials.size()) + " trials." +
                   m.str();
  }
  for (const auto& t : plan.trials) {
    if (!plan.complete) {
      plan.required_travel = std::max(plan.required_travel, t.travel[1] - t.travel[0]);
    }
  }
  plan.predicted = PredictPrecision(*ctx, info, &plan.notes);
  for (auto& t : plan.trials) AddReplayFields(vehicle, pool, &t);
  return plan;
}

using model::kInf;

// The ranking of DesignNextTrial's candidates; the best so far is in the result's trial.
struct NextCandidates {
  const DofPlanningProblem& ctx;
  const NextTrialOptions& o;
  const std::vector<Eigen::MatrixXd>& M0;  // prior information at each design point
  double criterion_before;
  double best;        // criterion of the best candidate so far
  double best_score;  // its score
  std::vector<Eigen::MatrixXd> best_info;

  double Score(double criterion, double duration) const {
    if (!o.per_pool_time) return criterion;
    return (criterion - criterion_before) / (duration + ctx.options().pause_s);
  }

  void TakeSine(const SineDesignResult& sn, NextTrialResult* result) {
    best = sn.criterion;
    best_score = Score(sn.criterion, sn.trial.design.duration);
    result->trial = sn.trial;
    result->check = sn.check;
    best_info = sn.information;
  }

  // A steady run from rest of `leg`, taken if it scores more than 1e-9 above the best (the
  // criteria are O(1..100) logs; a tie keeps the earlier candidate, the sine) and is feasible.
  void ConsiderSteady(const SteadyLeg& leg, NextTrialResult* result) {
    const model::TrialDesign d = LegDesign(leg, ctx.dof(), o.id);
    std::vector<Eigen::MatrixXd> info = ctx.Information(d);
    std::vector<Eigen::MatrixXd> total = info;
    for (std::size_t j = 0; j < total.size(); ++j) total[j] += M0[j];
    const double c =
        Aggregate(ctx.options().robustness, ctx.CriterionValues(total, o.criterion, {}));
    const double sc = Score(c, d.duration);
    if (!(sc > best_score + 1e-9)) return;
    const TrialCheck check = ctx.Check(d);
    if (!check.feasible) return;
    best = c;
    best_score = sc;
    result->trial.design = d;
    result->trial.travel = check.travel;
    result->trial.thrust_min = check.thrust_min;
    result->check = check;
    best_info = std::move(info);
  }
};

// A trial restricted to one direction of one mapping (SineDesignOptions::mappings and sign: the
// loop's trial for a direction not pushed yet) informs no installation coefficient of another
// direction: without prior information on them the information is singular and no sine is
// designed. Each gets the information of σ = 10 (an η lies in [0, 1]: no knowledge, yet above
// kSingularThreshold): the D criterion is then that of the parameters the trial reaches, up to
// a constant (log det of a block-diagonal matrix).
void HoldUnreachedEtas(const DofPlanningProblem& ctx, const SineDesignOptions& sine,
                       std::vector<Eigen::MatrixXd>* information) {
  if (sine.sign == 0 || sine.mappings.size() != 1) return;
  const std::string reached = model::EtaName(
      sine.mappings.front(), sine.sign > 0 ? model::Direction::kPos : model::Direction::kNeg);
  const std::vector<std::string>& names = ctx.model().parameter_names();
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (!model::StartsWith(names[i], model::param::kEtaPrefix) || names[i] == reached) continue;
    for (Eigen::MatrixXd& m : *information) m(i, i) += 1e-2;
  }
}

}  // namespace

ScheduleResult PlanSchedule(const model::Vehicle& vehicle, const model::Pool& pool,
                            const ScheduleOptions& o,
                            const std::function<void(model::Dof)>& dof_planned) {
  ScheduleResult result;
  std::string error;
  if (!o.IsValid(&error)) {
    result.message = error;
    return result;
  }
  const std::vector<model::Dof> dofs = DofsToPlan(vehicle, o);
  if (dofs.empty()) {
    result.message = "vehicle '" + vehicle.name +
                     "' has no DOF with both a thrust mapping and a sensor: nothing to plan";
    return result;
  }
  // Each DOF is planned on its own (DofPlanningProblem per DOF), on PlannerOptions::Threads
  // threads.
  std::vector<DofPlan> plans(dofs.size());
  model::ParallelFor(dofs.size(), o.planner.Threads(), [&](std::size_t i) {
    plans[i] = PlanDof(vehicle, pool, dofs[i], o);
    if (dof_planned) dof_planned(dofs[i]);
  });
  int planned = 0, complete = 0;
  for (DofPlan& plan : plans) {
    if (plan.status == DesignStatus::kOk) {
      result.schedule.predicted[plan.dof] = plan.predicted;
      for (const auto& t : plan.trials) result.schedule.trials.push_back(t);
      ++planned;
      if (plan.complete) ++complete;
    }
    result.dofs.push_back(std::move(plan));
  }
  double time = 0.0;
  for (const auto& t : result.schedule.trials) time += t.design.duration;
  if (!result.schedule.trials.empty()) {
    time += o.planner.pause_s * (result.schedule.trials.size() - 1);
  }
  result.schedule.pool_time = time;
  if (complete == static_cast<int>(dofs.size())) {
    result.status = PlanStatus::kOk;
  } else {
    result.status = planned > 0 ? PlanStatus::kPartial : PlanStatus::kInfeasible;
    std::ostringstream m;
    for (const auto& p : result.dofs) {
      if (!p.complete) m << p.message << " ";
    }
    result.message = m.str();
  }
  return result;
}

NextTrialResult DesignNextTrial(const model::Vehicle& vehicle, const model::Pool& pool,
                                model::Dof dof, const ParameterValues& estimates,
                                const std::vector<std::string>& names,
                                const Eigen::MatrixXd& covariance, const NextTrialOptions& o) {
  NextTrialResult result;
  std::string error;
  if (!o.schedule.IsValid(&error)) {
    result.message = error;
    return result;
  }
  if (covariance.rows() != static_cast<int>(names.size()) ||
      covariance.cols() != static_cast<int>(names.size())) {
    result.message = "covariance must be square with one row per name";
    return result;
  }
  ParameterValues sigmas;
  for (std::size_t i = 0; i < names.size(); ++i) {
    sigmas[names[i]] = std::sqrt(std::max(0.0, covariance(i, i)));
  }
  ParameterBox box = NextTrialBox(vehicle, pool, dof, estimates, sigmas, o, &result.notes);
  DofPlanningProblem ctx(vehicle, pool, dof, std::move(box), o.schedule.planner);
  const PriorInformation prior = PriorInformation::FromCovariance(names, covariance);
  std::vector<Eigen::MatrixXd> M0 = PriorPerPoint(ctx, &prior);
  HoldUnreachedEtas(ctx, o.schedule.sine, &M0);
  result.criterion_before =
      Aggregate(ctx.options().robustness, ctx.CriterionValues(M0, o.criterion, {}));

  // Candidates: the sine designed for this criterion, and each steady leg from rest. They are
  // ranked by the criterion they reach or, with per_pool_time, by its gain per second of pool
  // time (the trial plus the pause before the next one; a cost-normalised criterion).
  NextCandidates ranking{ctx, o, M0, result.criterion_before, -kInf, -kInf, {}};
  SineDesignOptions so = o.schedule.sine;
  so.criterion = o.criterion;
  so.interest.clear();
  const SineDesignResult sn = DesignInertiaTrial(ctx, so, M0, o.id);
  for (const auto& n : sn.notes) result.notes.push_back(n);
  if (sn.status == DesignStatus::kOk) ranking.TakeSine(sn, &result);
  const SteadyCandidates cands = MakeSteadyCandidates(ctx, o.schedule.steady);
  for (const auto& leg : cands.legs) ranking.ConsiderSteady(leg, &result);
  const double best = ranking.best;
  const std::vector<Eigen::MatrixXd>& best_info = ranking.best_info;
  if (!std::isfinite(best)) {
    result.status = DesignStatus::kInfeasible;
    result.message = "no trial of " + std::string(model::DofName(dof)) + " fits pool '" +
                     pool.name + "': " + sn.message + cands.infeasible;
    return result;
  }
  std::vector<Eigen::MatrixXd> total = best_info;
  for (std::size_t j = 0; j < total.size(); ++j) total[j] += M0[j];
  result.criterion_after = best;
  AddReplayFields(vehicle, pool, &result.trial);
  result.predicted = PredictPrecision(ctx, total, &result.notes);
  result.predicted.criterion = std::string(CriterionName(o.criterion));
  result.predicted.criterion_value = best;
  result.status = DesignStatus::kOk;
  return result;
}

}  // namespace uuvplan::planner
