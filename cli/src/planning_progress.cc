// Progress of a schedule's planning (planning_progress.h).
#include "uuvplan/cli/planning_progress.h"

#include <memory>
#include <mutex>

#include "uuvplan/cli/command.h"

namespace uuvplan::cli {

PlanningProgress ShowPlanningProgress(const std::string& command) {
  PlanningProgress p;
  p.line = TerminalProgress(command);
  auto lock = std::make_shared<std::mutex>();
  p.dof_planned = [line = p.line, lock](model::Dof dof) {
    const std::lock_guard<std::mutex> held(*lock);
    line(std::string(model::DofName(dof)) + " planned");
  };
  return p;
}

}  // namespace uuvplan::cli
