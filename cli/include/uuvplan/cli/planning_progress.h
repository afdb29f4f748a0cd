// Progress of a schedule's planning on a terminal (TerminalProgress, command.h): a line as each
// DOF's plan is done, then one as the pool verdict is judged. Planning a BlueROV2 takes tens of
// seconds of CPU; a person at the terminal sees it move.
#pragma once

#include <functional>
#include <string>

#include "uuvplan/model/dof.h"

namespace uuvplan::cli {

/// A TerminalProgress of `command` (command.h) for the lines of a run ("judging the pool
/// verdict ..."), and through it the one that prints "<dof> planned", for PlanSchedule's
/// dof_planned (its calls serialised: the DOFs are planned on several threads).
struct PlanningProgress {
  std::function<void(const std::string&)> line;
  std::function<void(model::Dof)> dof_planned;
};
PlanningProgress ShowPlanningProgress(const std::string& command);

}  // namespace uuvplan::cli
