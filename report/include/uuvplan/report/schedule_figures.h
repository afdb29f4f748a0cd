// The figures of a schedule, one per trial: the position against time over the a
// priori box (the envelope of the extreme vehicles of the pool check's grid,
// dof_planning_problem.h) with the pool's walls and margins; each thruster's force against time
// with its limits, min_thrust and the zero line (a reversal would cross it); the designed input
// phi_n(t).
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/report/chart.h"

namespace uuvplan::report {

/// One figure per trial of `schedule`, simulated over each DOF's a priori box (`options`, the
/// schedule's planner options); assumptions the box makes are appended to `notes`.
std::vector<Figure> ScheduleFigures(const model::Vehicle& vehicle, const model::Pool& pool,
                                    const planner::Schedule& schedule,
                                    const planner::PlannerOptions& options,
                                    std::vector<std::string>* notes);

}  // namespace uuvplan::report
