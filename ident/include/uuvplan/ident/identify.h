// Identification of a campaign (contract §identify): every DOF that has `fit` trials gets
// parameter estimates with standard deviations, and the identified model is scored by
// free-run simulation on its `fit` and `validate` trials.
//
// Per DOF, four stages (ident/src/identify_stages.h, docs/identification.md):
//  1. prepare: trials prepared (outliers excluded and reported, gaps found, velocity estimated
//     by Savitzky–Golay, ref 000 §IV-D, the logged force held between rows), the DOF's fit and
//     validate trials, its model structure and start values (PriorTheta);
//  2. estimate: steady-state segments detected (or taken from the user's windows) and the drag,
//     bias, ballast step and installation coefficients fitted (ref 000 eqs. 7–12, 20), with
//     model selection by significance (51.02%); the inertia by the integral method with the
//     drag known (ref 000 eqs. 16–19), and the one-step integral least squares of all
//     regressor-linear parameters (refs 002/004);
//  3. refine: the output-error (maximum-likelihood) refinement of all parameters, started from
//     the least-squares answer — the reported estimate when it converges;
//  4. validate: plausibility of the estimates, free-run validation (velocity MAE, ref 002
//     eq. 37; position RMS; residual whiteness).
// Ill-posed cases (no excitation, too few steady segments, singular regressions, closed-loop
// data) are reported with what would fix them; nothing is silently dropped.
#pragma once

#include <Eigen/Dense>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "uuvplan/ident/estimate.h"
#include "uuvplan/ident/estimators/closed_loop_iv.h"
#include "uuvplan/ident/estimators/integral_inertia.h"
#include "uuvplan/ident/estimators/one_step_ls.h"
#include "uuvplan/ident/estimators/output_error.h"
#include "uuvplan/ident/estimators/rls.h"
#include "uuvplan/ident/estimators/steady_state.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/ident/stats/model_selection_options.h"
#include "uuvplan/ident/summary.h"
#include "uuvplan/ident/validation.h"
#include "uuvplan/model/campaign.h"
#include "uuvplan/model/model_structure.h"

namespace uuvplan::ident {

enum class ClosedLoop { kAuto, kYes, kNo };

/// The estimator run on each DOF (`identify --method`, docs/identification.md "Methods"), so
/// that the papers' methods can be compared on one campaign, each with its σ and its free-run
/// validation.
enum class Method {
  kChain,         ///< "chain": the best chain — steady state + integral method or one-step LS,
                  ///< then the output error (closed-loop IV under feedback)
  kLeastSquares,  ///< "ls": steady-state least squares (ref 000 eqs. 7–12, 20); m held a priori
  kIntegral,      ///< "integral": steady state, then m by the integral method (000 eqs. 16–19)
  kOneStep,       ///< "one-step": one-step integral LS (ref 002 eqs. 20–36, 004 eqs. 8–14)
  kRls,           ///< "rls": recursive LS with forgetting on the one-step rows (004 eq. 15)
  kOutputError,   ///< "output-error": output error (maximum likelihood) from the a priori values
};
std::string_view MethodName(Method m);
/// The method of a name ("ls", "one-step", …), or nothing.
std::optional<Method> ParseMethod(std::string_view name);
/// "chain, ls, integral, one-step, rls, output-error".
std::string MethodNames();
/// Whether the method uses steady-state segments (and so `steady_windows`).
bool UsesSteadyState(Method m);

struct IdentifyOptions {
  /// DOFs to identify; empty: every DOF with at least one `fit` trial.
  std::vector<model::Dof> dofs;
  /// Model structure per DOF; absent: ModelStructure::Standard with the mappings seen in the
  /// fit trials and a ballast step when the fit trials have different ballast_steps.
  std::map<model::Dof, model::ModelStructure> structures;
  /// Starting values by parameter name (all DOFs), e.g. {"lag": 0.1}; the a priori values of
  /// the vehicle are used otherwise.
  std::map<std::string, double> initial_guess;
  /// User-marked steady-state windows per campaign trial index, in the log's time (s).
  std::map<int, std::vector<std::pair<double, double>>> steady_windows;
  TrialDataOptions data;
  SteadyStateOptions steady;
  IntegralInertiaOptions inertia;
  OneStepOptions one_step;
  ClosedLoopIvOptions closed_loop_iv;
  OutputErrorOptions output_error;
  ValidationOptions validation;
  RlsOptions rls;  ///< Method::kRls (λ: `--forgetting`)
  Method method = Method::kChain;
  bool refine = true;  ///< run the output-error stage (Method::kChain only)
  /// Refit the effects a model in the vehicle file gives (identify_stages.h FitWrittenModel;
  /// Method::kChain with refine only). Diagnosis turns it off: its baseline is the standard
  /// model.
  bool written_model = true;
  /// The model selection of every stage (least squares, RLS, closed-loop IV, output error):
  /// it replaces the stages' own `selection`. `identify --no-prune` turns it off,
  /// `--seed-selection` drops whatever the correlation (kSeedDropCorrelation), whose σ then
  /// assume the dropped parameters exactly 0 (significance.h).
  ModelSelectionOptions selection;
  ClosedLoop closed_loop = ClosedLoop::kAuto;
  /// Threads for preparing the trials and fitting the DOFs (0: one per core); each job fills
  /// its own slot, so the result does not depend on it.
  int threads = 0;
  bool IsValid(std::string* error) const;
};

/// In increasing severity (WorseStatus): a campaign's status is its worst DOF's.
enum class IdentifyStatus {
  kOk,          ///< estimates with σ, nothing to report
  kWarnings,    ///< estimates with caveats (see warnings)
  kModelError,  ///< estimates of a model that does not explain the data (output-error
                ///< residuals strongly correlated): the next step is `uuvplan diagnose`
  kFailed,      ///< no usable estimate: none, nothing significant, non-physical, diverged or no
                ///< better than ν ≡ 0 (docs/identification.md "Failure statuses")
};
std::string_view IdentifyStatusName(IdentifyStatus s);
/// The more severe of two statuses (the enum's order).
inline IdentifyStatus WorseStatus(IdentifyStatus a, IdentifyStatus b) { return a < b ? b : a; }

/// Which estimator produced a DOF's reported parameters.
enum class FinalEstimator {
  kOutputError,
  kSteadyStateIntegral,
  kOneStep,
  kClosedLoopIv,
  kSteadyState,  ///< Method::kLeastSquares: drag, bias, η; m a priori
  kRls,          ///< Method::kRls: the recursive estimate after the last row
  kNone,
};
std::string_view FinalEstimatorName(FinalEstimator e);

/// An estimate outside the range the vehicle file states for it before any trial: m against
/// the inertia bounds, mass (or inertia) × (1 + added_mass) (model::Vehicle::InertiaBounds). A
/// finding, not a failure: the prior or the data is wrong (the text layer words the likely
/// causes; docs/identification.md "Outside the a priori range").
struct OutsidePrior {
  std::string parameter;
  double value = 0.0;
  double sigma = 0.0;
  double lo = 0.0, hi = 0.0;  ///< the a priori range
  bool above() const { return value > hi; }
  /// How many σ the estimate lies beyond the bound it crosses (∞ for σ = 0).
  double SigmasBeyond() const { return (above() ? value - hi : lo - value) / sigma; }
};

struct DofIdentification {
  model::Dof dof = model::Dof::kSurge;
  IdentifyStatus status = IdentifyStatus::kOk;
  std::string message;
  /// Failed, and every reason is an estimate outside its admissible range: the standard model
  /// fits the data only with non-physical values, i.e. it misses an effect — what `diagnose`
  /// looks for (it refits within the ranges), so diagnosis still runs on such a DOF.
  bool failed_only_non_physical = false;
  model::ModelStructure structure;
  std::vector<std::string> parameter_names;  ///< theta layout (model::DofModel)
  Eigen::VectorXd theta;                     ///< values used by the model (0 when dropped)
  Eigen::MatrixXd covariance;                ///< theta layout; 0 rows for fixed/dropped
  std::vector<ParameterEstimate> params;     ///< one per parameter, theta layout
  std::vector<std::string> unreliable;       ///< parameters not to be trusted (and why: warnings)
  std::vector<OutsidePrior> outside_prior;   ///< estimates outside the vehicle file's range
  FinalEstimator estimator = FinalEstimator::kNone;
  std::vector<int> fit_trials, validate_trials;  ///< campaign trial indices
  std::vector<SteadyPoint> steady_points;
  std::optional<SteadyStateResult> steady;
  std::optional<IntegralInertiaResult> inertia;
  std::optional<OneStepDofResult> one_step;
  /// Method::kRls: the parameter trajectory (ref 004 Fig. 11) and the final estimate.
  std::optional<RlsDofResult> rls;
  std::optional<OutputErrorResult> output_error;
  /// Under feedback (closed_loop_suspected): the instrumental-variable estimate, reported
  /// instead of the output error (closed_loop_iv.h).
  std::optional<ClosedLoopIvResult> closed_loop_iv;
  FitSummary fit;
  bool closed_loop_suspected = false;
  std::vector<std::string> notes;
  std::vector<std::string> warnings;
  /// Wall time of each stage, in order: "prepare" (this DOF's trials' share of the data
  /// preparation and the model set-up), "estimate" (steady state, integral method, one-step
  /// least squares), "refine" (output error), "validate" (plausibility and free runs).
  std::vector<StageTime> timing;

  /// The reported estimate of parameter `name`, or null.
  const ParameterEstimate* Param(const std::string& name) const;
};

/// What preparing a trial found and excluded.
struct TrialReport {
  int index = -1;
  std::string file;
  model::Dof dof = model::Dof::kSurge;
  model::TrialUse use = model::TrialUse::kFit;
  double time_offset = 0.0;
  std::vector<Outlier> position_outliers, velocity_outliers;  ///< times in trial time
  std::vector<Gap> gaps;
  std::vector<TrialNote> notes;
};

/// What an identification did, in the style of Ceres' Solver::Summary: the status, the wall
/// time of each stage summed over the DOFs, and the estimator and status of each DOF. Its
/// texts are those of the shared shape (summary.h), built by Shape().
struct IdentifySummary {
  struct DofLine {
    model::Dof dof = model::Dof::kSurge;
    IdentifyStatus status = IdentifyStatus::kFailed;
    FinalEstimator estimator = FinalEstimator::kNone;
    int num_parameters = 0, num_fit_trials = 0, num_validate_trials = 0;
    int num_warnings = 0;
    std::string message;
  };
  IdentifyStatus status = IdentifyStatus::kFailed;
  std::string message;
  int num_trials = 0;
  std::vector<StageTime> stages;  ///< prepare, estimate, refine, validate (all DOFs)
  std::vector<DofLine> dofs;
  /// The shared shape: pipeline "identify", the status's name, one line per DOF.
  PipelineSummary Shape() const;
  double total_seconds() const { return Shape().total_seconds(); }
  /// One line: "identify: warnings, 2 DOF(s) from 6 trial(s) in 0.41 s (surge output_error, …)".
  std::string Brief() const { return Shape().Brief(); }
  /// A few lines: the brief line, the stage timings, one line per DOF.
  std::string Full() const { return Shape().Full(); }
};

struct IdentifyResult {
  IdentifyStatus status = IdentifyStatus::kFailed;
  Method method = Method::kChain;  ///< the estimator asked for
  std::string message;
  std::vector<DofIdentification> dofs;
  std::vector<TrialReport> trials;
  std::vector<std::string> notes;
  const DofIdentification* Find(model::Dof dof) const;
  /// The summary of this result (status, stage timings, one line per DOF).
  IdentifySummary Summary() const;
};

/// Identifies the campaign. Throws model::InputError for unusable input (a trial without
/// force or measurement columns, unknown mappings, invalid options); numerical trouble is
/// reported in the result.
IdentifyResult Identify(const model::Campaign& campaign, const IdentifyOptions& options);
/// The same, releasing each trial's log as soon as it is prepared (its columns are not needed
/// after: a million-row log is 24 MB). `campaign` keeps everything else.
IdentifyResult IdentifyReleasingLogs(model::Campaign* campaign, const IdentifyOptions& options);

/// A priori parameter values of a DOF model (vehicle inertia bounds' midpoint, drag prior,
/// η = 1, …) overridden by `guess`: the nominal-θ policy of identification (the starting
/// values of every stage), one function so that it can be swapped.
Eigen::VectorXd PriorTheta(const model::Vehicle& vehicle, const model::DofModel& model,
                           const std::map<std::string, double>& guess);

/// Heuristic closed-loop check of a trial's logged force. Over the sequence of distinct
/// consecutive command values: a designed piecewise-constant input (legs, steps, telegraph,
/// PRBS) takes few levels (at most max(10, 10%) of its changes) → 0; otherwise the roughness
/// median |Δ³φ| / median |Δφ| tells a smooth designed input (a sine sampled at ω·Δt:
/// (ω·Δt)², 0.1 for VSOR's 1 s heave sine at 20 Hz) from a controller reacting to measurement
/// noise (≥ 1 for white noise; tartan 0.79–50): closed loop suspected above 0.4. The second
/// difference (ω·Δt against ~1.4) took that sine for a controller (0.33 > 0.3).
double CommandRoughness(const TrialData& trial);

}  // namespace uuvplan::ident
