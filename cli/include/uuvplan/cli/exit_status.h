// The exit statuses of the commands that answer with a pool verdict or a loop's end
// (docs/cli.md): beyond the common 0 success, 1 a result the user must act on, 2 bad input
// (command.h), `next` and `loop` end with 4 budget spent, 5 stuck (no trial adds
// information), 6 convergence refused (estimates inconsistent, non-physical or failing
// validation).
#pragma once

#include "uuvplan/planner/loop/design_loop.h"
#include "uuvplan/planner/pool/pool_verdict.h"

namespace uuvplan::cli {

inline constexpr int kExitBudgetSpent = 4;
inline constexpr int kExitStuck = 5;
inline constexpr int kExitRefused = 6;
int ExitStatus(planner::LoopStatus s);
int ExitStatus(planner::NextStatus s);

/// The exit status of a verdict: 0 hosted, 1 not (kExitActionNeeded).
int VerdictExit(const planner::PoolVerdict& verdict);

}  // namespace uuvplan::cli
