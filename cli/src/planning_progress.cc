// Progress of a schedule's planning (planning_progress.h).
#include "uuvplan/cli/planning_progress.h"

#include <memory>
#include <mutex>

#include "uuvplan/cli/command.h"

namespace uuvplan::cli {

std::function<void(const std::string&)> ShowPlanningProgress(const std::string& command,
                                                             planner::ScheduleOptions* o) {
  auto progress = TerminalProgress(command);
  auto lock = std::make_shared<std::mutex>();
  o->dof_planned = [progress, lock](model::Dof dof) {
    const std::lock_guard<std::mutex> held(*lock);
    progress(std::string(model::DofName(dof)) + " planned");
  };
  return progress;
}

}  // namespace uuvplan::cli
