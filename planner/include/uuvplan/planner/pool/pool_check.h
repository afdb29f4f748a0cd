// Can a pool host a schedule (contract §check-pool)? Every trial is checked against the hard
// constraints by simulation over the a priori box (dof_planning_problem.h): no propeller reversal,
// min_thrust, thruster limits, travel inside length/width/depth - 2·margin, trial duration.
// The answer says which constraint fails and by how much, the smallest pool that hosts the
// schedule, and — when the pool cannot host it — the best schedule that fits this pool and the
// information it loses (D-efficiency per DOF against the given schedule).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::planner {

struct TrialPoolCheck {
  std::string id;
  model::Dof dof = model::Dof::kSurge;
  TrialCheck check;
};

struct PoolCheckResult {
  bool feasible = false;
  std::vector<TrialPoolCheck> trials;
  /// Smallest pool that hosts every trial (m): the largest travel span on each axis + 2·margin
  /// (2·margin where no trial uses the axis).
  double required_length = 0.0;
  double required_width = 0.0;
  double required_depth = 0.0;
  /// When infeasible: the best schedule for this pool (same DOFs), and per DOF the fraction of
  /// information lost, 1 - D-efficiency = 1 - exp((D_fit - D_plan)/p) (p informed parameters;
  /// 1 when the DOF cannot be planned in this pool at all).
  bool has_alternative = false;
  ScheduleResult alternative;
  std::map<model::Dof, double> information_loss;
  std::vector<std::string> notes;
};

struct PoolCheckOptions {
  ScheduleOptions schedule;      ///< for the alternative and the box of the checks
  bool plan_alternative = true;  ///< plan the best fitting schedule when infeasible
};

PoolCheckResult CheckPool(const model::Vehicle& vehicle, const model::Pool& pool,
                          const Schedule& plan, const PoolCheckOptions& options);

}  // namespace uuvplan::planner
