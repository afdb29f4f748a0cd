// Which of a DOF's parameters of interest a set of trials determines, a priori, and the trials
// of the loop's own families that complete a schedule whose steady runs and sine leave some
// undetermined. One definition shared by the schedule, the pool verdict and (through the
// schedule) the loop: what the planner calls undeterminable in a pool, no family the loop uses
// can determine there either.
//
// Parameters of interest (as the loop's, design_loop.h): m; kq when determined, else k; every
// installation coefficient of a direction the thrusters can hold. Determined: the worst
// predicted σ over the box's design points is at most kInsignificantPercent (51.02%, ref 000
// §IV-D) of the parameter's smallest a priori value.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/design/sine_design.h"
#include "uuvplan/planner/design/steady_design.h"
#include "uuvplan/planner/schedule.h"

namespace uuvplan::planner {

/// The loop's target (DesignLoopOptions::target_percent, `--target`): the largest percentile
/// error 100·σ/|θ| of every parameter of interest. 5%.
inline constexpr double kDefaultTargetPercent = 5.0;
/// The loop's stuck rule (DesignLoopOptions::max_trials_to_target): a trial is negligible when
/// reaching the target at its rate takes more than this many such trials.
inline constexpr double kDefaultMaxTrialsToTarget = 5.0;

/// The precision the pool verdict judges at: the loop's target and its stuck rule.
struct PrecisionGoal {
  double target_percent = kDefaultTargetPercent;
  double max_trials_to_target = kDefaultMaxTrialsToTarget;
};

/// Number of trials like one that takes σ_now to σ_after needed to reach σ_target (the
/// information of independent trials adds: 1/σ² = 1/σ_now² + n·(1/σ_after² − 1/σ_now²));
/// +inf when the trial adds nothing (checked first) or the target is not a number > 0, 0 when
/// σ_now is already there. σ_now = +inf (nothing known yet): the limit, n = (σ_after/σ_target)².
double TrialsToTarget(double sigma_now, double sigma_after, double sigma_target);

struct Determinacy {
  bool determined = false;                ///< every parameter of interest determined
  std::string worst;                      ///< the parameter of interest with the largest error
  double worst_percent = 0.0;             ///< its 100·σ/|θ| (+inf: no trial reaches it)
  std::vector<std::string> undetermined;  ///< "name (σ x% of its value)" or "name (no trial)"
};

/// The determinacy of ctx's parameters of interest given the information `info` (absolute,
/// one matrix per design point of ctx's box).
Determinacy InterestDeterminacy(const DofPlanningProblem& ctx,
                                const std::vector<Eigen::MatrixXd>& info);

/// Whether the loop can bring every parameter of interest to the target from `info` (the
/// schedule's information at each design point of ctx's box) before its stuck rule stops it.
/// The loop's rule (CandidateGain, next_trial_policy.cc): a candidate with σ_now → σ_after is
/// negligible when n = ((σ_now/σ_t)² − 1)/((σ_now/σ_after)² − 1) > N (max_trials_to_target);
/// in information I = 1/σ² that is n = (I_t − I_now)/ΔI, ΔI = I_after − I_now the candidate's
/// gain: the trial's own relative σ, 100/(sqrt(ΔI)·|θ|), must be at most
/// 100·sqrt(N/(I_t − I_now))/|θ| (with I_now one such trial's: ≤ target·sqrt(N + 1)). The
/// candidate is the loop's (DesignNextTrial: the better by robust D of the D-optimal sine and
/// every steady leg from rest), designed again after each one is added, as the loop does: the
/// next D-optimal trial is not a repeat (measured: random vehicle 34's heave, docs/planning.md).
/// Per design point: reached when every parameter of interest gets to the target before some
/// candidate's n exceeds N (at most 2N candidates; n ≤ N throughout counts as reached).
struct TargetReach {
  bool reached = true;
  std::string parameter;     ///< the bottleneck at the point reported
  std::string trial;         ///< the loop's candidate there
  int step = 0;              ///< its number after the schedule (1 = the first sequential trial)
  double now_percent = 0.0;  ///< the bottleneck's 100·σ/|θ| before that candidate
  double per_trial_percent = 0.0;  ///< 100/(sqrt(ΔI)·|θ|) of the candidate
  double needed_percent = 0.0;     ///< the largest per-trial value that reaches the target
  /// n there: the first stuck point's (reached false), else the largest met.
  double trials = 0.0;
  std::string text;  ///< "kq reaches 18% per trial here …; the target 5% needs ≤ 12% …"
};
TargetReach ReachTarget(const DofPlanningProblem& ctx, const SineDesignOptions& sine,
                        const SteadyDesignOptions& steady, std::vector<Eigen::MatrixXd> info,
                        const PrecisionGoal& goal, const std::string& id);

/// The trials the loop's next-trial design would add (DesignNextTrial's families: a sine
/// designed for D on every parameter — with an offset, from rest, in any mapping and
/// direction — and every steady leg from rest), one at a time on the information so far,
/// until every parameter of interest is determined or `max_trials` were added.
struct CompletionResult {
  std::vector<PlannedTrial> trials;
  std::vector<TrialCheck> checks;
  std::vector<std::string> notes;
};
CompletionResult CompleteWithLoopFamilies(const DofPlanningProblem& ctx,
                                          const SineDesignOptions& sine,
                                          const SteadyDesignOptions& steady,
                                          std::vector<Eigen::MatrixXd>* info,
                                          const std::string& id_prefix, int max_trials);

}  // namespace uuvplan::planner
