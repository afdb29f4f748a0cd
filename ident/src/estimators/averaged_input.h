// Internal to the output error's coarse stage (output_error.cc, CoarseStart): a logged force held
// row by row, averaged over pieces about one coarse step long.
#pragma once

#include <memory>

#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/model/excitation.h"

namespace uuvplan::ident::internal {

// The trial's zero-order hold of its force rows with consecutive rows of one mapping merged into
// pieces no longer than `span` seconds, each piece holding the rows' time average: ∫φ dt over the
// piece is the log's, so the momentum it imparts (m·Δv = ∫(φ − drag) dt, ref 000 eq. 16) is
// kept, and the simulation steps once a piece instead of once a row. Null when no two rows merge
// (a log whose commands hold for longer than `span`: the trial's own input is exact and as fast).
std::unique_ptr<model::Excitation> AveragedInput(const TrialData& d, double span);

}  // namespace uuvplan::ident::internal
