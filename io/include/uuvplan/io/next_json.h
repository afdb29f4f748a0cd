// `uuvplan next --json` (docs/cli.md): the estimates so far, the next trial (read back by
// `simulate --plan` as a plan's single "trial", schedule_json.h) and its predicted σ, the
// progress against the target, the candidates and the pool verdict.
#pragma once

#include <nlohmann/json.hpp>

#include "uuvplan/model/pool.h"
#include "uuvplan/planner/loop/design_loop.h"
#include "uuvplan/planner/pool/pool_verdict.h"

namespace uuvplan::io {

/// {"estimates", "trial" (null unless planned), "predicted", "status", "message", "source",
///  "target", "progress", "candidates", "exit_status", "notes", "verdict"}. When the pool
/// refuses what `next` found (`pool_refuses`: a trial in a pool the verdict hosts for no
/// vehicle of the box, or a stuck DOF in one not hosted over the whole box), the status is
/// "infeasible" and the message the verdict's sentence (then the stop's own message); the best
/// next trial, if any, is still given.
nlohmann::json NextStepJson(const planner::NextStepResult& result, double target_percent,
                            const planner::PoolVerdict& verdict, const model::Pool& pool,
                            int exit_status, bool pool_refuses);

}  // namespace uuvplan::io
