// A Monte Carlo coverage report (ident/stats/monte_carlo.h) as a readable table: one line per
// estimator, DOF and parameter with the truth, the spread of the estimates against their
// reported σ and the Cramér–Rao σ, and the coverage of θ̂ ± z·σ.
#pragma once

#include <string>

#include "uuvplan/ident/stats/monte_carlo.h"

namespace uuvplan::text {

std::string MonteCarloTable(const ident::MonteCarloReport& report);

}  // namespace uuvplan::text
