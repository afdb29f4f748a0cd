// Scoring's notes in words (ident/score.h, ScoreNote): one sentence per kind, the same in
// `uuvplan score`'s text and its JSON.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/ident/score.h"

namespace uuvplan::text {

/// One sentence, e.g. "t3.csv: not scored: the model gives no dofs.sway.params".
std::string NoteText(const ident::ScoreNote& note);

/// NoteText of each note, in order.
std::vector<std::string> NoteTexts(const std::vector<ident::ScoreNote>& notes);

}  // namespace uuvplan::text
