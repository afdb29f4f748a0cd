#include "uuvplan/text/score_notes_text.h"

namespace uuvplan::text {

std::string NoteText(const ident::ScoreNote& n) {
  switch (n.kind) {
    case ident::ScoreNoteKind::kNoModelForDof:
      return n.trial + ": not scored: the model gives no dofs." +
             std::string(model::DofName(n.dof)) + ".params";
  }
  return std::string(ident::kScoreNoteKindNames.Name(n.kind));
}

std::vector<std::string> NoteTexts(const std::vector<ident::ScoreNote>& notes) {
  std::vector<std::string> texts;
  for (const ident::ScoreNote& n : notes) texts.push_back(NoteText(n));
  return texts;
}

}  // namespace uuvplan::text
