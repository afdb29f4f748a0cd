// Diagnosis: what the standard model's simulation gets wrong, which physical effect
// causes it, the extended model, and what the extension gains.
//
//  1. The standard model (contract: all η = 1, symmetric drag, no extra terms) is identified.
//  2. Every trial is simulated free-run with it; the errors are broken down by thrust
//     direction and mapping, by direction of motion, by speed, by small commands, by lag
//     (cross-correlation of simulated and measured velocity) and by campaign time.
//  3. Each candidate effect (model::Effects()) extends the model; the extension is fitted by output
//     error from the current estimate and kept only when the evidence is significant:
//       likelihood ratio  D = 2·(C₀ − C₁)/s₁²  ~ χ²(Δp) under "no effect",
//     C the output-error cost ½‖r‖², s₁² = 2·C₁/(N − P₁), at level `significance` per test
//     (Bonferroni over the candidates), AND a new parameter at least `min_z` standard deviations
//     from its null value (η = 1, others 0). Effects are added greedily, largest D first, and the
//     rest re-tested against the extended model, so several effects can be combined.
//  4. The gain of each finding is the velocity MAE (ref 002 eq. 37) of the free-run simulation
//     before and after adding it, on the `validate` trials, or by 2-fold cross-validation across
//     trials when none is marked.
// The driver times its stages — screen (the standard model identified, fitted and broken down),
// test (candidates fitted and tested), extend (the greedy choice), measure (held-out gains,
// input noise) — and DiagnosisResult::Summary() gives them in the pipelines' shape (summary.h).
#pragma once

#include <cstdint>
#include <functional>
#include <limits>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "uuvplan/ident/diagnosis/diagnosis_note.h"
#include "uuvplan/ident/estimate.h"
#include "uuvplan/ident/estimators/output_error.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/ident/summary.h"
#include "uuvplan/model/campaign.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/error_breakdown.h"
#include "uuvplan/model/model_structure.h"

namespace uuvplan::ident {

struct DiagnoseOptions {
  /// Level of each likelihood-ratio test. With ~12 candidates per DOF, 1e-3 keeps the chance
  /// of any false finding on clean data near 1%.
  double significance = 1e-3;
  /// A new parameter must lie this many σ from its null value (η = 1, others 0).
  double min_z = 3.0;
  /// A significant effect must also reduce the free-run velocity error on held-out data
  /// (validate trials, else 2-fold cross-validation) by at least this fraction. Measured inputs
  /// (a coupling's logged velocities of other DOFs) carry sensor noise that acts as a random
  /// force; the free-run fit then finds any extra parameter "significant" by the likelihood
  /// ratio, but such a parameter fits that trial's noise and predicts other trials no better
  /// (hidden-effect draws 1–40: spurious gains ≤ 0.15%, real effects ≥ 0.98%; docs/diagnosis.md).
  double min_gain = 0.005;
  int max_effects = 3;  ///< per DOF
  /// Refits with the other DOFs' logged velocities redrawn with their sensor noise, to add
  /// that noise to the σ of a model with coupling (errors in variables); 0 = off.
  int input_noise_replicates = 20;
  std::uint64_t seed = 1;  ///< of those redraws
  /// Effects to try, by name (model::Effects()); default: every one diagnosis may propose.
  std::vector<std::string> candidates = model::Effects().Diagnosable();
  /// Threads for the candidate fits (0: one per core). The result does not depend on it.
  int threads = 0;
  /// Called at each stage of each DOF with a line saying what runs (the CLI prints it on
  /// stderr once a run has taken 2 s); empty: silent.
  std::function<void(const std::string&)> progress;
  /// DOFs to diagnose; empty: every DOF with a fit trial.
  std::vector<model::Dof> dofs;
  IdentifyOptions identify;         ///< for the nominal (standard-model) identification
  OutputErrorOptions output_error;  ///< for the candidate fits
  bool IsValid(std::string* error) const;
};

/// Where the standard model's free-run simulation goes wrong (model/error_breakdown.h).
using model::ErrorBreakdown;
using model::ErrorGroup;

struct DiagnosisGain {
  std::string metric = "velocity_mae";
  double before = 0.0;
  double after = 0.0;
  double relative = 0.0;  ///< (before − after) / before; NaN when not scored
  std::string on;         ///< "validate" or "cross-validation"
  /// False when the held-out data cannot score the two models (no held-out trial, a fold
  /// without trials, a free run that cannot be simulated): `unscored` says why.
  bool scored = false;
  std::string unscored;
  /// `after` per held-out unit (validate trial, or cross-validation fold) with its velocity
  /// samples: two extensions scored on the same units are compared by their paired difference.
  std::vector<std::pair<double, int>> after_by_unit;
};

/// The static thrust map a thrust_map (and dead zone) finding implies, in the units of the
/// vehicle file: for the reference thruster of a mapping (largest |share|), each command V →
/// the force the vehicle file's thrust model gives (nominal) and the force the extended model
/// delivers, f_d = share·φ_d, φ_d = φ·(|φ|/φ_ref)^p with φ = Thrust(V)/share (after the dead
/// zone, when found), with σ from σ_p: σ_fd = |f_d·ln(|φ|/φ_ref)|·σ_p.
struct CorrectedThrustMap {
  std::string mapping, thruster;
  struct Row {
    double command = 0.0, nominal = 0.0, delivered = 0.0, sigma = 0.0;  // command unit, N
  };
  std::vector<Row> rows;  ///< commands from command_min to command_max, 0 left out
  /// The delivered force grows as |V|^n over the commands of the data (log–log slope), n ± σ.
  double command_exponent = 0.0, command_exponent_sigma = 0.0;
  /// The commands of the fit trials span [smallest, largest] |V| (n's meaning is there).
  double smallest_command = 0.0, largest_command = 0.0;
  /// Least-squares fit of the delivered force by the vehicle file's poly2 thrust model
  /// f = sign(V)·(a·V² + b·|V|), a, b ≥ 0: the map to put in the vehicle file.
  double poly2_a = 0.0, poly2_b = 0.0;
  /// The chosen static map (Finding::chosen_map) at each row's command, N (NaN: none chosen).
  std::vector<double> chosen_force;
  /// "linear in the command", "square in the command" (each when that power law stays within
  /// 20% of the fitted one over the commands of the data) or "a power of the command, |command|^n".
  std::string shape;
};

/// A static thrust map fitted in place of a thrust_map finding's power law (diagnosis.md §5):
/// each sample's force re-mapped through the reference thruster's command V,
/// linear f = g·V (g = Thrust(V_ref)/V_ref, V_ref the largest |V| of the data: the map agrees
/// with the vehicle file's at the largest command), "dead-band" the same after a dead zone
/// (parameter `deadzone`, in N of DOF force), "asymmetric" with the reverse gain a free η
/// (eta.<mapping>.neg); the rest of the extended model refitted on the fit trials.
struct StaticMapCandidate {
  std::string shape;                      ///< "linear", "dead-band" or "asymmetric"
  std::vector<ParameterEstimate> params;  ///< its own parameters (none for linear)
  double aic = 0.0;                       ///< N·ln(2C/N) + 2P on the fit trials (C: ½‖r‖²)
  /// Validate-trial velocity MAE, and its difference from the power law's, paired by trial
  /// (positive: worse), with σ = √(T/(T−1)·Σ w_t²(d_t − δ)²), w_t the trial's share of samples.
  double validate_mae = 0.0, vs_power_law = 0.0, vs_power_law_sigma = 0.0;
  bool scored = false;
  /// Within the admissible ranges and converged (a map that contains linear fits at least as
  /// well); only these are chosen.
  bool physical = true;
  std::string why;  ///< why not scored or not physical
};

struct Finding {
  std::string effect;  ///< name in the effect table (model/effects.h)
  model::Dof dof = model::Dof::kSurge;
  std::string detail;                     ///< the proposal's detail (a coupling's pair)
  std::vector<ParameterEstimate> params;  ///< the extension's parameters
  double statistic = 0.0;                 ///< likelihood ratio D
  int added_parameters = 0;
  double p_value = 1.0;
  DiagnosisGain gain;
  /// thrust_map findings: the corrected static map of each mapping of the fit trials.
  std::vector<CorrectedThrustMap> thrust_maps;
  /// thrust_map findings: the static maps compared and the one chosen: linear unless a map
  /// with a parameter predicts the validate trials better by more than 2σ (paired by trial),
  /// then the lowest AIC of those; without validate trials the lowest AIC; physical fits only
  /// (empty when none).
  std::vector<StaticMapCandidate> static_maps;
  std::string chosen_map;
};

/// One candidate's test (also those not retained), for the report.
struct CandidateTest {
  std::string effect;  ///< name in the effect table
  model::Dof dof = model::Dof::kSurge;
  std::string detail;  ///< e.g. the coupling pair, or why it was not testable
  double statistic = 0.0;
  int added_parameters = 0;
  double p_value = 1.0;
  /// The new parameter farthest from its null value, in σ; NaN when the extension's fit ended
  /// worse than the model it extends (C₁ > C₀: not at its optimum, `detail` says so).
  double max_z = 0.0;
  bool significant = false;  ///< p < significance and a new parameter ≥ min_z σ from null
  /// Held-out gain (relative velocity-MAE reduction) of a significant candidate, when
  /// evaluated and scored; NaN otherwise.
  double gain = std::numeric_limits<double>::quiet_NaN();
  /// Why a significant candidate's held-out gain could not be scored (empty when it was).
  std::string unscored;
  /// Why the extension is not physical (a parameter outside its family's admissible range,
  /// model/parameter.h), e.g. "kq_neg = -453.4 N·s²/m² (expected a number >= 0)"; such a
  /// candidate is never significant.
  std::string non_physical;
  bool accepted = false;  ///< significant, held-out gain ≥ min_gain, and chosen in its round
  /// A significant candidate with enough held-out gain that was not chosen: which one was, and
  /// whether the held-out data can tell the two apart (paired difference of their MAE > 2σ).
  std::optional<NotChosen> not_chosen;
  /// Accepted, then removed by the final model's backward test: its new parameters no longer
  /// min_z σ from their null values once the effects found after it are in (which, and why).
  std::optional<Removal> removed;
  int round = 0;  ///< greedy round (0 = against the standard model)

  /// Its AIC gain over the model of its round on the fit trials: D − 2·Δp.
  double AicGain() const { return statistic - 2.0 * added_parameters; }
};

/// "deadzone" or "coupling vr": a candidate or finding as reports name it (a coupling by its
/// pair; other effects' detail is not part of the name).
std::string CandidateName(const std::string& effect, const std::string& detail);

struct DiagnosisResult {
  IdentifyResult nominal;
  std::vector<Finding> findings;  ///< ordered by gain, largest first
  std::vector<ErrorBreakdown> breakdowns;
  std::vector<CandidateTest> tests;
  /// The extended structure and its estimate per DOF diagnosed (the standard one when nothing
  /// found), every parameter with σ (0 for one held at its admissible bound); `fit` holds the
  /// free run of every trial of the DOF with it, as `uuvplan score` computes it.
  std::vector<DofIdentification> extended;
  /// The standard model per DOF diagnosed, as diagnosis fits it (output error, every parameter
  /// free: the "before" of the first finding), with its free runs in `fit` likewise.
  std::vector<DofIdentification> standard;
  /// What limits the findings' meaning (e.g. closed-loop data), to show beside them, and the
  /// remarks on how they were reached (text/diagnosis_notes_text.h words both).
  std::vector<DiagnosisNote> warnings;
  std::vector<DiagnosisNote> notes;
  /// The DOFs asked for (or with a fit trial), in the order diagnosed.
  std::vector<model::Dof> dofs;
  /// The DOFs refused, and why: the standard model's identification failed (a diagnosis of a
  /// failed fit would name effects of the failure), or its output-error fit did.
  std::map<model::Dof, std::string> not_diagnosed;
  /// Wall time of each stage, summed over the DOFs, in order: "screen" (trials prepared, the
  /// standard model identified, fitted by output error and its errors broken down), "test"
  /// (every candidate fitted and tested), "extend" (the greedy choice, the extended model),
  /// "measure" (held-out gains, input-noise covariance). They add up to Diagnose's wall time.
  std::vector<StageTime> timing;
  /// Status "findings" (some effect found), "none" (every DOF diagnosed, nothing found) or
  /// "failed" (some DOF could not be diagnosed: not_diagnosed says why); the stage timings; per
  /// DOF the effects found with their held-out gain.
  PipelineSummary Summary() const;
};

/// Diagnoses the campaign. Throws model::InputError for unusable input.
DiagnosisResult Diagnose(const model::Campaign& campaign, const DiagnoseOptions& options);

/// The standard structure of the contract for a DOF: all η = 1 (no free η), symmetric drag,
/// no effects; bias_step when the trials' ballast differs.
model::ModelStructure NominalStructure(const model::Vehicle& vehicle, model::Dof dof,
                                       const std::vector<std::string>& mappings_used, bool ballast);

}  // namespace uuvplan::ident
