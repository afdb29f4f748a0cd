#include "verdict_text.h"

#include "command.h"

namespace uuvplan::tool {

void PrintVerdict(const planner::PoolVerdict& verdict, const model::Pool& pool,
                  std::ostream& out) {
  const auto lines = planner::VerdictLines(verdict, pool);
  out << "\nVerdict: ";
  for (const auto& line : lines) out << line << "\n";
}

int VerdictExit(const planner::PoolVerdict& verdict) {
  return verdict.hosted ? kExitOk : kExitActionNeeded;
}

}  // namespace uuvplan::tool
