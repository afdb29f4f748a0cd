// What preparing a trial did, in words (ident/prepare/trial_note.h): one sentence per kind,
// the same in the identification's JSON and tables.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/ident/prepare/trial_note.h"

namespace uuvplan::text {

/// One sentence, e.g. "heading unwrapped (2 jumps of 2π)".
std::string NoteText(const ident::TrialNote& note);

/// One sentence for all the other-DOF motion notes of a trial: "not a single-DOF trial: the
/// vehicle also moved in roll (0.222 rad/s rms) and pitch (0.46 rad/s rms), …"; "" when none.
std::string OtherMotionText(const std::vector<ident::TrialNote>& notes);

/// NoteText of each note, in order.
std::vector<std::string> NoteTexts(const std::vector<ident::TrialNote>& notes);

}  // namespace uuvplan::text
