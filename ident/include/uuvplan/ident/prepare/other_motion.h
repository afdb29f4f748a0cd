// How far a single-DOF trial moved the vehicle in its other DOFs. The seeds identify one DOF per
// trial with the others still (ref 000 §II: each trial excites one DOF, the model of eq. 3 has no
// coupling); motion logged in another DOF is measured and reported, so that a trial that was not
// single-DOF says so (diagnose tests the coupling it implies).
#pragma once

#include <vector>

#include "uuvplan/ident/prepare/trial_note.h"
#include "uuvplan/model/dof.h"
#include "uuvplan/model/trial_log.h"

namespace uuvplan::ident {

/// One TrialNoteKind::kOtherDofMotion per DOF other than `dof` that the log has a position or
/// velocity column of: the travel of its position (max − min, m or rad) and the rms of its
/// velocity (m/s or rad/s), then the same of `dof` for scale, NaN for a column absent or
/// without two finite samples, over the rows from `from_t` (s, log time) on.
std::vector<TrialNote> OtherDofMotion(const model::TrialLog& log, model::Dof dof, double from_t);

}  // namespace uuvplan::ident
