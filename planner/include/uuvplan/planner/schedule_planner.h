// The planner's public entry points (the API `next` and `loop` build on):
//
//   PlanSchedule     the whole test schedule of a vehicle (a new payload): for each requested
//                    DOF the steady runs for drag and installation coefficients (ref 000
//                    §III-A), then one sine trial for the inertia designed given what the steady
//                    runs leave unknown (§III-B), ordered, with durations, predicted σ per
//                    parameter and total pool time (contract §schedule).
//   DesignNextTrial  ONE next trial for a DOF given current estimates and their covariance
//                    (sequential design: the covariance's inverse is the prior information and
//                    the box is centred on the estimates).
//   PredictPrecision the predicted σ and criterion of any set of trials (e.g. a user's plan).
//
// Predicted σ are the worst over the design points of the box (max_j sqrt((M_j⁻¹)_ii), the
// Cramér–Rao bound at the least favourable a priori parameters) and criterion values are the
// robust aggregate (maximin by default) of the D criterion in relative units (criteria.h).
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <map>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/design/sine_design.h"
#include "uuvplan/planner/design/steady_design.h"
#include "uuvplan/planner/determinacy.h"
#include "uuvplan/planner/schedule.h"

namespace uuvplan::planner {

struct ScheduleOptions {
  PlannerOptions planner;
  SteadyDesignOptions steady;
  SineDesignOptions sine;
  /// DOFs to plan, in this order; empty: every DOF with a mapping and a sensor (surge, sway,
  /// heave, roll, pitch, yaw).
  std::vector<model::Dof> dofs;
  bool steady_runs = true;  ///< plan the steady runs
  bool sine_trial = true;   ///< plan the sine trial
  /// Trials of the loop's families (determinacy.h) added to a DOF whose steady runs and sine
  /// leave a parameter of interest undetermined. CHOSEN 3: each adds one sine or leg; a DOF
  /// that three more do not determine is limited by the pool, not by the schedule's shape.
  int max_completion_trials = 3;
  /// The precision a DOF's schedule must let the loop reach (the verdict judges at
  /// the loop's target): `complete` also needs ReachTarget (determinacy.h). `uuvplan
  /// schedule`, `check-pool`, `next` and `loop --target` set it; DesignLoopOptions shares the
  /// defaults.
  PrecisionGoal precision;
  /// Information from earlier trials per DOF (absolute units); added to every design.
  std::map<model::Dof, PriorInformation> prior;

  bool IsValid(std::string* error) const;
};

/// kOk: every DOF's parameters of interest determined (determinacy.h) and the target
/// reachable from its trials (ReachTarget); kPartial: some are not
/// (see the DOFs' messages: what is missing and the pool it would need); kInfeasible: nothing
/// planned.
enum class PlanStatus { kOk, kPartial, kInfeasible };
std::string_view PlanStatusName(PlanStatus s);

struct DofPlan {
  model::Dof dof = model::Dof::kSurge;
  /// kOk: at least one trial planned; `complete` also says its trials determine every
  /// parameter of interest (`determinacy`).
  DesignStatus status = DesignStatus::kFailed;
  bool complete = false;
  Determinacy determinacy;
  /// Whether the loop can bring the parameters of interest to `ScheduleOptions::precision`
  /// from these trials (ReachTarget; judged once they are determined, else left reached).
  TargetReach reach;
  std::string message;
  std::vector<PlannedTrial> trials;
  std::vector<TrialCheck> checks;
  PredictedPrecision predicted;
  /// Free travel (m or rad) the DOF's smallest useful trial needs (at least the largest span of
  /// its planned trials); NaN when it was completely planned.
  double required_travel = 0.0;
  std::vector<std::string> notes;
};

struct ScheduleResult {
  PlanStatus status = PlanStatus::kInfeasible;
  std::string message;
  Schedule schedule;  ///< the feasible trials of every DOF, in order
  std::vector<DofPlan> dofs;
  std::vector<std::string> notes;
};

/// The schedule of every DOF of options.dofs. `dof_planned` (optional) is called as each DOF's
/// plan is done, from the thread that planned it (PlannerOptions::threads: the callee
/// serialises); the CLI prints progress with it.
ScheduleResult PlanSchedule(const model::Vehicle& vehicle, const model::Pool& pool,
                            const ScheduleOptions& options,
                            const std::function<void(model::Dof)>& dof_planned = {});

/// Predicted precision of `info` (absolute, at each design point of ctx's box): worst σ per
/// informed parameter, and the robust D criterion (relative units). Parameters no trial
/// reaches are left out, with a note.
PredictedPrecision PredictPrecision(const DofPlanningProblem& ctx,
                                    const std::vector<Eigen::MatrixXd>& info,
                                    std::vector<std::string>* notes = nullptr);

/// The information of a list of trials of ctx's DOF at each design point (plus `prior`).
std::vector<Eigen::MatrixXd> TrialsInformation(const DofPlanningProblem& ctx,
                                               const std::vector<PlannedTrial>& trials,
                                               const PriorInformation* prior = nullptr);

struct NextTrialOptions {
  ScheduleOptions schedule;  ///< planner, steady and sine settings (dofs, prior unused)
  /// Half-width of the box about the estimates, in σ of each estimate. CHOSEN 2 (95%).
  double box_sigmas = 2.0;
  Criterion criterion = Criterion::kD;  ///< on all parameters the trials reach
  /// Rank the candidates by the criterion's gain per second of pool time (trial duration +
  /// PlannerOptions::pause_s) rather than by the criterion reached. Off by default: on the
  /// ROMEO loop (seeds 1-8) it gave the same pool time on 7 seeds and 16 s more on one (it
  /// picks a short leg, and the long sine is still needed next); docs/planning.md.
  bool per_pool_time = false;
  std::string id = "next";
};

struct NextTrialResult {
  DesignStatus status = DesignStatus::kFailed;
  std::string message;
  PlannedTrial trial;
  TrialCheck check;
  PredictedPrecision predicted;                          ///< after the trial (prior + trial)
  double criterion_before = 0.0, criterion_after = 0.0;  ///< robust criterion
  std::vector<std::string> notes;
};

/// Designs the single next trial of `dof` (a sine, or one steady leg from rest in some mapping
/// and direction) that adds the most information (or the most per second of pool time, see
/// NextTrialOptions::per_pool_time) given current `estimates` (by parameter name) and their
/// `covariance` (rows/cols in `names` order; empty: no estimates yet). The box is the
/// estimates ± box_sigmas·σ.
NextTrialResult DesignNextTrial(const model::Vehicle& vehicle, const model::Pool& pool,
                                model::Dof dof, const ParameterValues& estimates,
                                const std::vector<std::string>& names,
                                const Eigen::MatrixXd& covariance, const NextTrialOptions& options);

}  // namespace uuvplan::planner
