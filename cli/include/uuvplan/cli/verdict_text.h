// The pool verdict as every command prints it (planner/pool/pool_verdict.h): the same lines, so the
// same inputs read the same in schedule, check-pool, next, loop and demo.
#pragma once

#include <ostream>

#include "uuvplan/model/pool.h"
#include "uuvplan/planner/pool/pool_verdict.h"

namespace uuvplan::cli {

/// "Verdict: <sentence>" then the pool, one line per DOF and the smallest pool.
void PrintVerdict(const planner::PoolVerdict& verdict, const model::Pool& pool, std::ostream& out);

/// The exit status of a verdict: 0 hosted, 1 not (kExitActionNeeded).
int VerdictExit(const planner::PoolVerdict& verdict);

}  // namespace uuvplan::cli
