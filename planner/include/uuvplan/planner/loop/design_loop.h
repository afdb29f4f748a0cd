// The iterative design–identify loop: identify from every trial logged so far, turn
// the estimates and their covariance into the a priori knowledge of the next design (box =
// estimates ± 2σ, prior information = covariance⁻¹), and plan the single most informative next
// trial; on the virtual vehicle, run it and repeat until every parameter of interest has a
// percentile error 100·σ/|θ| (ref 000 §III-A) below the target.
//
// Thin orchestration: identification is ident::Identify, the a priori schedule PlanSchedule,
// the sequential design DesignNextTrial (schedule_planner.h), the trials
// model::VirtualCampaignBuilder. Files: design_loop.cc (next, loop), next_trial_policy.cc (which
// DOF, which trial), loop_progress.cc (parameters of interest and their errors).
// What this file decides:
//   - parameters of interest per DOF ("m, k (or kq where significant) and
//     every η"): m; kq when the identification finds it significant (percentile error below
//     51.02%, ref 000 §IV-D), else k; every installation coefficient of the DOF's mappings
//     (one per non-open-water direction, as the planner's model has them; one not estimated
//     yet counts as an infinite error). bias and bias_step are nuisance.
//   - which DOF next: the one whose worst parameter of interest is furthest above the target;
//   - which trial: while the DOF's estimates are not usable yet (no trial, or m or the drag of
//     interest insignificant) the next trial of its a priori schedule, in ref 000 order (steady
//     runs, then the sine, §III); afterwards DesignNextTrial.
//   - pool time: trial durations plus a pause between consecutive trials (PlannerOptions::
//     pause_s), the accounting of PlanSchedule.
#pragma once

#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/model/campaign.h"
#include "uuvplan/model/dof.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/truth.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::planner {

/// Ref 000 §IV-D: a parameter whose percentile error exceeds 51.02% is, at 95% confidence,
/// statistically insignificant.
inline constexpr double kInsignificantPercent = 51.02;

/// The loop's identification: every parameter of the structure kept
/// (IdentifyOptions::selection.prune_insignificant = false). Ref 000 §IV-D's model selection
/// refits without the parameters it finds insignificant, and the σ of that refit are
/// conditional on the dropped ones being exactly 0: on random vehicles a dropped bias or linear
/// drag that is small but not zero moved m, the drag and η by 4–281 of their σ while the loop
/// converged (docs/validation.md, "The loop on every vehicle"). The loop judges precision by
/// σ, so it needs the σ of the full model (as the coverage figures of identification do).
inline ident::IdentifyOptions LoopIdentifyOptions() {
  ident::IdentifyOptions o;
  o.selection.prune_insignificant = false;
  return o;
}

struct DesignLoopOptions {
  /// DOFs to drive to the target, in this order (ties in the choice of the next DOF go to the
  /// first). Empty: NextStep takes the DOFs the campaign has fit trials of (every DOF the
  /// vehicle can plan when it has none); RunLoop the DOFs the truth has parameters for.
  std::vector<model::Dof> dofs;
  /// Largest percentile error 100·σ/|θ| (%) of every parameter of interest. 5%
  /// (the default the pool verdict judges at, ScheduleOptions::precision).
  double target_percent = kDefaultTargetPercent;
  /// Estimates are usable for the sequential design once m and the drag of interest have a
  /// percentile error below this (%). CHOSEN: ref 000's significance limit; before, the box
  /// estimates ± 2σ would be wider than the a priori one and the a priori schedule is better.
  double usable_percent = kInsignificantPercent;
  /// Level of the χ² consistency test of each new trial against the previous estimate
  /// (ConsistencyTest). CHOSEN 1%: the test is conservative (C_prev + C_new bounds the
  /// covariance of the change), so a failure at 1% is an inconsistency, not chance.
  double consistency_level = 0.01;
  /// A trial's information gain is negligible when reaching the target at its rate would take
  /// more than this many such trials (CandidateGain::trials_to_target). CHOSEN 5: a pool
  /// session's worth of repeats; the ROMEO loop's useful trials need at most 3.
  double max_trials_to_target = kDefaultMaxTrialsToTarget;
  /// A trial brought new information when some parameter of interest gained at least this
  /// fraction of the information it had ((σ_before/σ_after)² − 1). CHOSEN 0.05 (σ down 2.4%).
  double min_information_ratio = 0.05;
  /// The identified model fails validation when its output-error residuals have a lag-1
  /// autocorrelation above this (the level at which identification warns of model error).
  double max_residual_lag1 = 0.8;
  ScheduleOptions schedule;  ///< the a priori schedule of each DOF (its `dofs` is ignored)
  NextTrialOptions next;     ///< the sequential design (its `schedule` is replaced by the above)
  ident::IdentifyOptions identify = LoopIdentifyOptions();

  bool IsValid(std::string* error) const;
  /// `schedule` judged at this loop's target and stuck rule (ScheduleOptions::precision): the
  /// options of the loop's a priori schedules and of the pool verdict `loop` and `next` print.
  ScheduleOptions ScheduleAtTarget() const {
    ScheduleOptions so = schedule;
    so.precision = {target_percent, max_trials_to_target};
    return so;
  }
};

/// One parameter of interest of a DOF as the identification left it.
struct InterestParameter {
  std::string name;
  bool estimated = false;  ///< identified with a finite σ (and not held: see `held`)
  double value = std::numeric_limits<double>::quiet_NaN();
  double sigma = std::numeric_limits<double>::quiet_NaN();
  /// 100·σ/|value| (ref 000 §III-A); +inf when not estimated or held.
  double percent = std::numeric_limits<double>::infinity();
  /// An a priori fallback: the identification held it (or a parameter it depends on) at its a
  /// priori value or calls it not reliable (ill-conditioned least squares). Its value and σ are
  /// kept for printing but never counted as information (percent = +inf).
  bool held = false;
  bool physical = true;  ///< within its family's physical range (NonPhysical)
  std::string flag;      ///< why it is held or non-physical ("" when neither)
};

/// The χ² test of a DOF's newest trial against the estimate before it: over the
/// parameters estimated (and reliable) in both, Δθ = θ_new − θ_prev and
/// χ² = Δθᵀ (C_prev + C_new)⁻¹ Δθ on n = |Δθ| degrees of freedom, consistent when its survival
/// probability is at least the level. C_prev + C_new bounds the covariance of Δθ from above
/// (for nested efficient estimates it is C_prev − C_new, Hausman 1978), so the test is
/// conservative: it fails on estimates that moved by many of their σ (an overconfident σ or a
/// model that does not explain every trial), not by chance.
struct ConsistencyTest {
  bool tested = false;  ///< false: no earlier estimate with a parameter in common
  double chi2 = std::numeric_limits<double>::quiet_NaN();
  int dof = 0;
  double p_value = std::numeric_limits<double>::quiet_NaN();
  double level = 0.0;
  bool consistent = false;  ///< tested and p_value >= level
  std::string worst;        ///< the parameter that moved by most of its combined σ
  double worst_sigmas = std::numeric_limits<double>::quiet_NaN();
  std::string text;  ///< one sentence for people
};

/// How far a DOF is from the target.
struct DofProgress {
  model::Dof dof = model::Dof::kSurge;
  int trials = 0;  ///< fit trials of the DOF in the campaign
  std::vector<InterestParameter> interest;
  std::string worst;  ///< name of the parameter with the largest percentile error
  double worst_percent = std::numeric_limits<double>::infinity();
  bool usable = false;   ///< estimates good enough for the sequential design
  bool precise = false;  ///< every parameter of interest below the target by its own σ
  /// Convergence needs more than precision: every parameter of interest physical,
  /// none held, the model validated and the newest trial consistent with the estimate before it.
  bool trusted = false;
  bool converged = false;           ///< precise and trusted
  ConsistencyTest consistency;      ///< the newest trial against the estimate before it
  std::vector<std::string> doubts;  ///< why the estimates are not trusted (empty when trusted)
  /// Precise and consistent, yet non-physical or failing validation: more trials of this model
  /// cannot make it right, the loop refuses to converge on it (its reason; "" otherwise).
  std::string refusal;
  std::string status;  ///< the identification's status and message for the DOF
};

/// The parameters of interest of `dof` for a vehicle (m; kq when it is estimated and
/// significant, else k; every η of its mappings in a direction the thrusters can hold), how far
/// `identification` (may be null: no trial yet) has brought them, and whether they can be
/// trusted; `previous` (may be null) is the DOF's identification before its newest trial.
DofProgress EvaluateProgress(const model::Vehicle& vehicle, model::Dof dof,
                             const ident::DofIdentification* identification, int trials,
                             const DesignLoopOptions& options,
                             const ident::DofIdentification* previous = nullptr);

/// "" when `value` of parameter `name` is physically admissible on `dof` of `vehicle` (its
/// family's physical range, ParameterFamily::Physical; a translational m above the vehicle's
/// dry mass), else why not.
std::string NonPhysical(const model::Vehicle& vehicle, model::Dof dof, const std::string& name,
                        double value);

/// The predicted information gain of a candidate trial for its DOF's parameters of interest
/// above the target: for each, the information ratio r = (σ_now/σ_after)² − 1 (σ_now the
/// identification's σ the design knew, +inf when it knew none) and the number of such trials
/// to the target n = ((σ_now/σ_target)² − 1)/r; the one reported is the parameter the trial
/// brings nearest to the target (the smallest n). Negligible when even that n >
/// DesignLoopOptions::max_trials_to_target.
struct CandidateGain {
  model::Dof dof = model::Dof::kSurge;
  std::string trial;      ///< the candidate's id
  std::string parameter;  ///< the parameter it brings nearest to the target
  double sigma_now = std::numeric_limits<double>::quiet_NaN();
  double sigma_after = std::numeric_limits<double>::quiet_NaN();  ///< predicted
  double gain = 0.0;  ///< 1 − σ_after/σ_now of that parameter (1 when σ_now is +inf)
  double trials_to_target = 0.0;
  /// σ_now is +inf (not determined yet) and this trial determines it: one trial, then planned
  /// from its estimate (trials_to_target 1).
  bool first_estimate = false;
  bool negligible = false;
};

enum class NextStatus {
  kTrial,       ///< a next trial is planned
  kConverged,   ///< every parameter of interest is already below the target: nothing to run
  kInfeasible,  ///< no DOF that needs a trial can be given one in this pool (see message)
  kStuck,       ///< every trial the pool allows adds negligible information (see message)
  kRefused,     ///< precise but non-physical or failing validation: no convergence claimed
};
std::string_view NextStatusName(NextStatus s);

struct NextStepResult {
  NextStatus status = NextStatus::kInfeasible;
  std::string message;
  ident::IdentifyResult estimates;      ///< of the campaign (no DOF when it has no fit trial)
  std::vector<DofProgress> progress;    ///< per DOF of interest, before the next trial
  model::Dof dof = model::Dof::kSurge;  ///< of the next trial
  /// "a priori schedule" (ref 000 order) or "sequential design" (DesignNextTrial).
  std::string source;
  PlannedTrial trial;
  PredictedPrecision predicted;           ///< predicted σ of the DOF's parameters after the trial
  std::vector<CandidateGain> candidates;  ///< every DOF's candidate trial, in the order tried
  std::vector<std::string> notes;
};

/// `uuvplan next`: identifies `campaign` and plans its next trial in `pool`. Throws
/// model::InputError on unusable input (invalid options, a DOF without sensor or mapping).
NextStepResult NextStep(const model::Campaign& campaign, const model::Pool& pool,
                        const DesignLoopOptions& options);

struct LoopOptions {
  DesignLoopOptions step;
  int budget = 40;                ///< most trials to run before giving up
  std::uint64_t seed = 1;         ///< trial i draws from model::StreamSeed(seed, i)
  double command_rate_hz = 20.0;  ///< virtual pool's command rate (VirtualPoolOptions)
  /// A design that already ran this many times without new information
  /// (DesignLoopOptions::min_information_ratio) is not run again: its DOF is stuck:
  /// never more than twice.
  int max_repeats = 2;
  /// Consecutive failed consistency tests of a DOF before the loop refuses it. CHOSEN 3: one
  /// failure is an overconfident early σ the next trials correct (VSOR yaw), three in a row a
  /// model that does not explain the trials.
  int max_inconsistent = 3;
  /// `loop --diagnose`: after each identification of a DOF with two fit trials or more (the
  /// held-out data a finding needs), diagnose its trials (ident::Diagnose, these options; its
  /// `dofs` is replaced by the DOF). When the effects it accepts differ from the model's, its
  /// extended model becomes the DOF's model, which the DOF is identified in at once and in every
  /// later identification (the written-model stage of identify): the diagnosis of every trial
  /// so far decides; an effect leaves when it is no longer significant on top of the diagnosed
  /// model. nullopt: the standard model throughout.
  std::optional<ident::DiagnoseOptions> diagnose;
  /// Under `diagnose`, a DOF's model is settled when each effect the diagnosis accepted leads
  /// every other significant candidate of its round by at least this AIC difference; until
  /// then its estimates are not trusted (no convergence). CHOSEN 10: "essentially no support"
  /// for the other model (Burnham & Anderson 2002, §2.6). A thruster lag and a sensor delay
  /// differ little on slow responses: on the loop's first trials the diagnosis had preferred
  /// the delay to a true lag by less, and the loop converged on it (docs/validation.md).
  double settled_aic_gap = 10.0;

  bool IsValid(std::string* error) const;
};

/// An effect `loop --diagnose` added to a DOF's model after a trial.
struct EffectEntered {
  std::string effect;  ///< name in the effect table (model/effects.h)
  std::string detail;  ///< the finding's detail (a coupling's pair)
  /// Its parameters as the diagnosis estimated them (then refitted with the rest of the model).
  std::vector<ident::ParameterEstimate> params;
  ident::DiagnosisGain gain;  ///< held-out gain over the model without it
};

/// One trial of the loop and what identification made of it.
struct LoopIteration {
  int index = 0;  ///< 0-based trial number in the campaign
  model::Dof dof = model::Dof::kSurge;
  std::string source;  ///< see NextStepResult::source
  PlannedTrial trial;
  PredictedPrecision predicted;           ///< what the design expected after the trial
  std::vector<CandidateGain> candidates;  ///< the gain of every DOF's candidate trial
  /// Per parameter of the trial's DOF the design predicted σ for: [predicted at the estimates
  /// before the trial, achieved] σ after the trial (achieved NaN when not estimated).
  std::map<std::string, std::array<double, 2>> sigma;
  PredictedPrecision at_estimates;  ///< the trial's predicted σ at the estimates before it
  bool new_information = true;      ///< some parameter of interest gained information (see above)
  double start = 0.0;               ///< campaign clock at the trial's start (s)
  double pool_time = 0.0;           ///< pool time so far, this trial included (s)
  /// Estimates of every identified DOF after this trial (theta layout of each DOF).
  std::map<model::Dof, std::vector<ident::ParameterEstimate>> params;
  std::vector<DofProgress> progress;  ///< after this trial
  double wall_seconds = 0.0;          ///< design + run + identification (+ diagnosis)
  /// Effects the diagnosis after this trial added to its DOF's model (LoopOptions::diagnose),
  /// and those it no longer found (effect name, a coupling's pair after it).
  std::vector<EffectEntered> effects_entered;
  std::vector<std::string> effects_left;
  std::vector<std::string> notes;  ///< identification warnings and design notes
};

enum class LoopStatus {
  kConverged,    ///< every parameter of interest below the target
  kBudgetSpent,  ///< the trial budget ran out first
  kInfeasible,   ///< a DOF that needs a trial cannot get one in this pool
  kStuck,        ///< a DOF's trials add negligible information (a pool, thrust, ... limit)
  kRefused,      ///< a DOF's estimates are inconsistent, non-physical or fail validation
};
std::string_view LoopStatusName(LoopStatus s);

struct LoopResult {
  LoopStatus status = LoopStatus::kInfeasible;
  std::string message;
  /// The DOFs hosted for part of the a priori box that the loop left stuck: it met a vehicle
  /// outside the hostable part (ReadLoopEnd, pool_verdict.h; then status kInfeasible).
  std::vector<model::Dof> outside_part;
  bool converged = false;
  std::vector<LoopIteration> iterations;
  std::vector<DofProgress> progress;           ///< final
  ident::IdentifyResult estimates;             ///< final identification, DOF by DOF
  model::Campaign campaign;                    ///< the virtual campaign that was run (in memory)
  double pool_time = 0.0;                      ///< Σ durations + pauses (s)
  std::map<model::Dof, double> dof_pool_time;  ///< the same restricted to each DOF's trials
  std::vector<std::string> notes;
};

/// `uuvplan loop`: runs the loop on the virtual vehicle of `truth` in `pool`. `on_iteration`
/// (may be empty) sees every iteration as it completes. Throws model::InputError on invalid
/// options or a DOF the truth or the vehicle cannot run.
LoopResult RunLoop(const model::Truth& truth, const model::Pool& pool, const LoopOptions& options,
                   const std::function<void(const LoopIteration&)>& on_iteration = {});

/// Designs alike to the planner's resolution: same DOF, kind and mappings, levels within 5%,
/// duration within 10% (a re-planned leg differs by a solver tolerance, not by intent). The
/// loop's repeat rule (LoopOptions::max_repeats) counts runs of alike designs.
bool SameDesign(const model::TrialDesign& a, const model::TrialDesign& b);

/// The largest number of runs of one design (SameDesign) that brought no new information
/// (LoopIteration::new_information) in `iterations`, over every design. At most
/// LoopOptions::max_repeats (2).
int MostUninformativeRepeats(const std::vector<LoopIteration>& iterations);

/// Pool time of trials run in this order: Σ durations + pause_s between consecutive trials.
double PoolTime(const std::vector<model::TrialDesign>& designs, double pause_s);

}  // namespace uuvplan::planner
