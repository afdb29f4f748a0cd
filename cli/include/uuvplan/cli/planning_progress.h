// Progress of a schedule's planning on a terminal (TerminalProgress, command.h): a line as each
// DOF's plan is done, then one as the pool verdict is judged. Planning a BlueROV2 takes tens of
// seconds of CPU; a person at the terminal sees it move.
#pragma once

#include <functional>
#include <string>

#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::cli {

/// Sets o->dof_planned to print "<dof> planned" through a TerminalProgress of `command` (its
/// calls serialised: the DOFs are planned on several threads) and returns that progress, for
/// the lines that follow ("judging the pool verdict ...").
std::function<void(const std::string&)> ShowPlanningProgress(const std::string& command,
                                                             planner::ScheduleOptions* o);

}  // namespace uuvplan::cli
