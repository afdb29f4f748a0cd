// The `identify` result as a readable table (its JSON is io::IdentifyJson).
#pragma once

#include <ostream>
#include <string>

#include "uuvplan/ident/identify.h"

namespace uuvplan::text {

/// Readable tables: per DOF the parameters (value, σ, percentile error, significance) and the
/// fit figures, then warnings and what was excluded from the data.
void PrintIdentifyTable(const ident::IdentifyResult& result, std::ostream& out);

/// "m = 1052 ± 15.3 kg lies above the vehicle file's a priori range [495, 675] kg (mass ×
/// (1 + added_mass)), 24.8σ beyond it; likely causes: …": the finding, with the causes that
/// move the estimate that way (identify's terminal output and its JSON `outside_prior`).
std::string OutsidePriorText(model::Dof dof, const ident::OutsidePrior& finding);

}  // namespace uuvplan::text
