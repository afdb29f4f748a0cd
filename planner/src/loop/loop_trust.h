// Whether a DOF's estimates can be trusted by the design–identify loop (design_loop.h):
// physical, not a priori fallbacks, validated, and consistent across the trials that produced
// them. Internal to the planner library.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/ident/identify.h"
#include "uuvplan/planner/loop/design_loop.h"

namespace uuvplan::planner::internal {

/// The parameter is an a priori fallback: held (fixed, not dropped as insignificant) or listed
/// as not reliable by the identification (e.g. conditional on a held parameter).
bool Held(const ident::DofIdentification& id, const std::string& name);

/// The χ² test of `current` against `previous` (ConsistencyTest) at `level`.
ConsistencyTest TestConsistency(const ident::DofIdentification& previous,
                                const ident::DofIdentification& current, double level);

/// Why the identified model fails validation (empty: it passes): failed identification, a
/// free run that diverges, output-error residuals correlated beyond `max_residual_lag1`.
std::vector<std::string> ValidationDoubts(const ident::DofIdentification& id,
                                          double max_residual_lag1);

}  // namespace uuvplan::planner::internal
