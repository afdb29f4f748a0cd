// Exit statuses of the verdict and the loop (exit_status.h).
#include "uuvplan/cli/exit_status.h"

#include "uuvplan/cli/command.h"

namespace uuvplan::cli {

int ExitStatus(planner::LoopStatus s) {
  switch (s) {
    case planner::LoopStatus::kConverged:
      return kExitOk;
    case planner::LoopStatus::kInfeasible:
      return kExitActionNeeded;
    case planner::LoopStatus::kBudgetSpent:
      return kExitBudgetSpent;
    case planner::LoopStatus::kStuck:
      return kExitStuck;
    case planner::LoopStatus::kRefused:
      return kExitRefused;
  }
  return kExitActionNeeded;
}

int ExitStatus(planner::NextStatus s) {
  switch (s) {
    case planner::NextStatus::kTrial:
    case planner::NextStatus::kConverged:
      return kExitOk;
    case planner::NextStatus::kInfeasible:
      return kExitActionNeeded;
    case planner::NextStatus::kStuck:
      return kExitStuck;
    case planner::NextStatus::kRefused:
      return kExitRefused;
  }
  return kExitActionNeeded;
}

int VerdictExit(const planner::PoolVerdict& verdict) {
  return verdict.hosted ? kExitOk : kExitActionNeeded;
}

}  // namespace uuvplan::cli
