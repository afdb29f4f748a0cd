#include "uuvplan/cli/verdict_text.h"

#include "uuvplan/cli/command.h"

namespace uuvplan::cli {

void PrintVerdict(const planner::PoolVerdict& verdict, const model::Pool& pool,
                  std::ostream& out) {
  const auto lines = planner::VerdictLines(verdict, pool);
  out << "\nVerdict: ";
  for (const auto& line : lines) out << line << "\n";
}

int VerdictExit(const planner::PoolVerdict& verdict) {
  return verdict.hosted ? kExitOk : kExitActionNeeded;
}

}  // namespace uuvplan::cli
