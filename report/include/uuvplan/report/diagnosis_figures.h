// The figures of a diagnosis, per DOF diagnosed: the residual of each trial's
// free run before (standard model) and after the extension (the extended model), and the
// held-out gain of every candidate effect tested (docs/diagnosis.md).
#pragma once

#include <vector>

#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/ident/score.h"
#include "uuvplan/report/chart.h"

namespace uuvplan::report {

/// The free runs of the standard and the extended model of `dof`, scored on the campaign with
/// curves kept (ident::ScoreCampaign with ScoreOptions::curve_points).
struct BeforeAfter {
  model::Dof dof = model::Dof::kSurge;
  ident::ScoreResult before, after;
};

Figure ResidualsBeforeAfterFigure(const BeforeAfter& runs);
/// Held-out gain (relative velocity-MAE reduction, %) of each candidate tested on `dof`.
Figure CandidateGainFigure(const ident::DiagnosisResult& diagnosis, model::Dof dof);

}  // namespace uuvplan::report
