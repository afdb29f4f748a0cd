// Diagnosis' warnings and notes in words (ident/diagnosis/diagnosis_note.h): one sentence per
// kind, the same in the text report, the JSON and the report document.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/ident/diagnosis/diagnosis_note.h"

namespace uuvplan::text {

/// One line, starting with the DOF: "surge: thruster_lag not tested: …".
std::string NoteText(const ident::DiagnosisNote& note);

/// NoteText of each note, in order.
std::vector<std::string> NoteTexts(const std::vector<ident::DiagnosisNote>& notes);

/// Why `test` was not chosen ("cannot be told from deadzone (D …; held-out MAE …)"), or "".
std::string NotChosenText(const ident::CandidateTest& test);

/// Why `test` was removed after being accepted ("kq_neg = … in the final model (< 3σ)"), or "".
std::string RemovedText(const ident::CandidateTest& test);

}  // namespace uuvplan::text
