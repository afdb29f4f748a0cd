// What preparing a trial did, in words (ident/prepare/trial_note.h): one sentence per kind,
// the same in the identification's JSON and tables.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/ident/prepare/trial_note.h"

namespace uuvplan::text {

/// One sentence, e.g. "heading unwrapped (2 jumps of 2π)".
std::string NoteText(const ident::TrialNote& note);

/// NoteText of each note, in order.
std::vector<std::string> NoteTexts(const std::vector<ident::TrialNote>& notes);

}  // namespace uuvplan::text
