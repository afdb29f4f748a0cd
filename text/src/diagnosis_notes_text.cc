#include "uuvplan/text/diagnosis_notes_text.h"

#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::text {
namespace {

using ident::DiagnosisNote;
using ident::DiagnosisNoteKind;
using model::Significant;

// "deadzone (held-out gain 1.23%, D = 45.67)": names[i] with numbers[2i], numbers[2i + 1].
std::string Candidate(const DiagnosisNote& n, std::size_t i) {
  return n.names[i] + " (held-out gain " + Significant(100 * n.numbers[2 * i], 3) +
         "%, D = " + Significant(n.numbers[2 * i + 1], 4) + ")";
}

std::string CannotTell(const DiagnosisNote& n) {
  std::vector<std::string> rivals;
  for (std::size_t i = 1; i < n.names.size(); ++i) rivals.push_back(Candidate(n, i));
  return "these trials cannot tell " + Candidate(n, 0) + " from " + model::Join(rivals) + ": " +
         n.names[0] +
         " is kept for its larger likelihood on the fit trials, but either may be the cause; "
         "trials where their predictions differ (other command levels or directions) are needed "
         "to separate them";
}

// "kq_neg = 421 ± 156 N·s²/m², 0.7σ from kq = 177", or "…σ from 'no effect'".
std::string DistanceText(const ident::NullDistance& d, model::Dof dof) {
  return d.parameter + " = " + Significant(d.value, 4) + " ± " + Significant(d.sigma, 4) + " " +
         model::Unit(d.parameter, dof) + ", " + Significant(d.z, 2) + "σ from " +
         (d.against.empty() ? "'no effect'" : d.against + " = " + Significant(d.against_value, 4));
}

std::string Sentence(const DiagnosisNote& n) {
  switch (n.kind) {
    case DiagnosisNoteKind::kNeedsCampaignClock:
      return n.names[0] +
             " not tested: the campaign gives no `start` time for every trial, so the campaign "
             "clock is unknown";
    case DiagnosisNoteKind::kClosedLoopSuspected:
      return "closed-loop data suspected (see the identification's warning): the logged force "
             "reacts to the motion through a controller, so an effect found here may describe the "
             "loop rather than the vehicle (a controller's delay looks like a sensor delay or "
             "a thruster lag, its gains like drag or a thrust-map shape); confirm with open-loop "
             "trials";
    case DiagnosisNoteKind::kCannotTell:
      return CannotTell(n);
    case DiagnosisNoteKind::kKeptRefitFailed:
      return n.names[0] + " kept although " + DistanceText(n.removal.weakest, n.dof) + " (< " +
             Significant(n.removal.min_z, 2) +
             "σ) in the final model: the refit without it failed (" + n.names[1] + ")";
    case DiagnosisNoteKind::kRemoved:
      return n.names[0] + " accepted in round " + std::to_string(static_cast<int>(n.numbers[0])) +
             ", then removed: " + DistanceText(n.removal.weakest, n.dof) +
             " in the final model (< " + Significant(n.removal.min_z, 2) + "σ)" +
             "; the model refitted without it (the gains of the other findings were measured "
             "with it in)";
    case DiagnosisNoteKind::kHeldAtBound:
      return "the extended model holds " + n.names[0] + " at its admissible bound " +
             Significant(n.numbers[0], 4) + " " + model::Unit(n.names[0], n.dof) +
             " (the free fit puts it outside: model/parameter.h)";
    case DiagnosisNoteKind::kNoCouplingSensor:
      return "the vehicle file declares no " + n.names[0] +
             " velocity sensor; the coupling's σ ignore the noise of its log";
    case DiagnosisNoteKind::kInputNoiseRefitsFailed:
      return "refits with perturbed other-DOF velocities failed; the coupling's σ ignore the "
             "noise of their logs";
    case DiagnosisNoteKind::kInputNoiseIncluded:
      return "σ include the noise of the logged velocities the coupling uses (" +
             std::to_string(static_cast<int>(n.numbers[0])) + " refits with that noise redrawn)";
  }
  return std::string(ident::kDiagnosisNoteKindNames.Name(n.kind));
}

}  // namespace

std::string NoteText(const DiagnosisNote& note) {
  return std::string(model::DofName(note.dof)) + ": " + Sentence(note);
}

std::vector<std::string> NoteTexts(const std::vector<DiagnosisNote>& notes) {
  std::vector<std::string> texts;
  for (const DiagnosisNote& n : notes) texts.push_back(NoteText(n));
  return texts;
}

std::string NotChosenText(const ident::CandidateTest& test) {
  if (!test.not_chosen) return "";
  const ident::NotChosen& n = *test.not_chosen;
  const std::string paired = "held-out MAE " + Significant(n.mae_difference, 2) + " ± " +
                             Significant(n.mae_difference_sigma, 2) + " " +
                             std::string(model::VelocityUnit(test.dof)) + " against " + n.chosen +
                             "'s";
  if (n.cannot_tell) {
    return "cannot be told from " + n.chosen + " (D " + Significant(n.statistic, 4) + " against " +
           Significant(n.chosen_statistic, 4) + "; " + paired + ")";
  }
  return n.chosen + " fits the fit trials better (D " + Significant(n.chosen_statistic, 4) +
         " against " + Significant(n.statistic, 4) + "; " + paired + ")";
}

std::string RemovedText(const ident::CandidateTest& test) {
  if (!test.removed) return "";
  return DistanceText(test.removed->weakest, test.dof) + " in the final model (< " +
         Significant(test.removed->min_z, 2) + "σ)";
}

}  // namespace uuvplan::text
