// Which of a DOF's parameters of interest a set of trials determines, a priori, and the trials
// of the loop's own families that complete a schedule whose steady runs and sine leave some
// undetermined. One definition shared by the schedule, the pool verdict and (through the
// schedule) the loop: what the planner calls undeterminable in a pool, no family the loop uses
// can determine there either.
//
// Parameters of interest (as the loop's, design_loop.h): m; kq when determined, else k; every
// installation coefficient of a direction the thrusters can hold. Determined: the worst
// predicted σ over the box's design points is at most kInsignificantPercent (51.02%, seed 000
// §IV-D) of the parameter's smallest a priori value.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/planner/dof_context.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/planner/sine_design.h"
#include "uuvplan/planner/steady_design.h"

namespace uuvplan::planner {

struct Determinacy {
  bool determined = false;            ///< every parameter of interest determined
  std::string worst;                  ///< the parameter of interest with the largest error
  double worst_percent = 0.0;         ///< its 100·σ/|θ| (+inf: no trial reaches it)
  std::vector<std::string> undetermined;  ///< "name (σ x% of its value)" or "name (no trial)"
};

/// The determinacy of ctx's parameters of interest given the information `info` (absolute,
/// one matrix per design point of ctx's box).
Determinacy InterestDeterminacy(const DofContext& ctx, const std::vector<Eigen::MatrixXd>& info);

/// The trials the loop's next-trial design would add (DesignNextTrial's families: a sine
/// designed for D on every parameter — with an offset, from rest, in any mapping and
/// direction — and every steady leg from rest), one at a time on the information so far,
/// until every parameter of interest is determined or `max_trials` were added.
struct CompletionResult {
  std::vector<PlannedTrial> trials;
  std::vector<TrialCheck> checks;
  std::vector<std::string> notes;
};
CompletionResult CompleteWithLoopFamilies(const DofContext& ctx, const SineDesignOptions& sine,
                                          const SteadyDesignOptions& steady,
                                          std::vector<Eigen::MatrixXd>* info,
                                          const std::string& id_prefix, int max_trials);

}  // namespace uuvplan::planner
