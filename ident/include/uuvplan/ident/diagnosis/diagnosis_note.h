// A remark diagnosis makes beside its findings (a caveat, a test not run, an effect removed), as
// data: what kind of remark, the DOF and the values it quotes. The text layer words it
// (text/diagnosis_notes_text.h); the library builds no sentence.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::ident {

/// A new parameter's distance from its null value in a fit: `value` ± `sigma` (the parameter's
/// unit), `z` σ from `against` = `against_value` (the parameter it defaults to), or from 'no
/// effect' when `against` is empty.
struct NullDistance {
  std::string parameter;
  double value = 0.0, sigma = 0.0, z = 0.0;
  std::string against;
  double against_value = 0.0;
};

/// Why a significant candidate with enough held-out gain was not chosen: the held-out data
/// cannot tell it from the chosen one (`cannot_tell`), or the chosen one fits the fit trials
/// better. D of both, and the paired held-out MAE difference δ ± σ against the chosen one
/// (velocity unit of the DOF).
struct NotChosen {
  bool cannot_tell = false;
  std::string chosen;  ///< the chosen candidate's name ("deadzone", "coupling vr")
  double statistic = 0.0, chosen_statistic = 0.0;
  double mae_difference = 0.0, mae_difference_sigma = 0.0;
};

/// An effect accepted, then found weak in the final model: its strongest new parameter
/// (`weakest`) is under `min_z` σ from its null value.
struct Removal {
  NullDistance weakest;
  double min_z = 0.0;
};

/// What a DiagnosisNote says; the comment lists what it quotes, in `names` then `numbers` order.
enum class DiagnosisNoteKind {
  /// names {effect}: the effect needs the campaign clock, which the campaign does not give.
  kNeedsCampaignClock,
  /// The identification suspects closed-loop data: a finding may describe the loop.
  kClosedLoopSuspected,
  /// names {chosen, rival 1, …}, numbers {held-out gain, D} of the chosen one then of each
  /// rival (gain as a fraction): the trials cannot tell the chosen effect from its rivals.
  kCannotTell,
  /// names {effect, the refit's message}, `removal`: the effect is kept although weak, its
  /// removal's refit failed.
  kKeptRefitFailed,
  /// names {effect}, numbers {round, 1-based}, `removal`: accepted then removed by the final
  /// model's backward test.
  kRemoved,
  /// names {parameter}, numbers {value, in the parameter's unit}: the extended model holds it
  /// at its admissible bound.
  kHeldAtBound,
  /// names {other DOF}: no velocity sensor for the other DOF a coupling reads.
  kNoCouplingSensor,
  /// The refits with perturbed other-DOF velocities failed.
  kInputNoiseRefitsFailed,
  /// numbers {refits}: the coupling's σ include the noise of the velocities it reads.
  kInputNoiseIncluded,
};

inline constexpr model::EnumNames<DiagnosisNoteKind, 9> kDiagnosisNoteKindNames{{{
    {DiagnosisNoteKind::kNeedsCampaignClock, "needs_campaign_clock"},
    {DiagnosisNoteKind::kClosedLoopSuspected, "closed_loop_suspected"},
    {DiagnosisNoteKind::kCannotTell, "cannot_tell"},
    {DiagnosisNoteKind::kKeptRefitFailed, "kept_refit_failed"},
    {DiagnosisNoteKind::kRemoved, "removed"},
    {DiagnosisNoteKind::kHeldAtBound, "held_at_bound"},
    {DiagnosisNoteKind::kNoCouplingSensor, "no_coupling_sensor"},
    {DiagnosisNoteKind::kInputNoiseRefitsFailed, "input_noise_refits_failed"},
    {DiagnosisNoteKind::kInputNoiseIncluded, "input_noise_included"},
}}};

struct DiagnosisNote {
  DiagnosisNoteKind kind = DiagnosisNoteKind::kNeedsCampaignClock;
  model::Dof dof = model::Dof::kSurge;
  std::vector<std::string> names;  ///< names (and quoted texts) in the order of the kind's list
  std::vector<double> numbers;     ///< numbers in the order of the kind's list
  Removal removal;                 ///< kKeptRefitFailed and kRemoved: the weak parameter
};

}  // namespace uuvplan::ident
