// `uuvplan check-pool --json` (docs/cli.md): each trial's hard-constraint check in the pool,
// the pool verdict and its required pool, and the best schedule that fits with the
// information it loses.
#pragma once

#include <nlohmann/json.hpp>

#include "uuvplan/model/pool.h"
#include "uuvplan/planner/pool/pool_check.h"
#include "uuvplan/planner/pool/pool_verdict.h"

namespace uuvplan::io {

/// {"feasible" (the verdict's hosted), "trials": [{"id", "dof", "feasible", "reasons",
/// "travel", "travel_unit", "thrust_min"}], "required", "verdict", "fits"?: {"schedule",
/// "information_loss"}}.
nlohmann::json CheckPoolJson(const planner::PoolCheckResult& result,
                             const planner::PoolVerdict& verdict, const model::Pool& pool);

}  // namespace uuvplan::io
