// Internal to the steady design (steady_design.h): the timing of a leg over the a priori box,
// the exact design's legs and their packing into trials.
#pragma once

#include <string>
#include <vector>

#include "design/travel_margin.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/design/steady_design.h"

namespace uuvplan::planner::internal {

// A direction's name in notes: "<mapping> (phi > 0)" or "<mapping> (phi < 0)".
std::string DirName(const std::string& mapping, int sign);

// Times steady legs over the a priori box of a DOF.
class SteadyLegTimer {
 public:
  SteadyLegTimer(const DofPlanningProblem& ctx, const SteadyDesignOptions& o) : ctx_(ctx), o_(o) {}

  // Hold time for measuring a speed of magnitude `speed` to speed_rel_sigma.
  double HoldTime(double speed) const;

  struct Timing {
    bool settled = false;
    double settle_s = 0.0;                    // whole seconds
    double hold_s = 0.0;                      // whole seconds
    double min_speed = 0.0;                   // smallest |xi*| over the check grid
    double centre_speed = 0.0;                // xi* at the box centre
    double travel_lo = 0.0, travel_hi = 0.0;  // over the whole prefix + leg (settle + hold)
  };

  // Times `leg` after the segments `prefix` (from rest): settle from the prefix's end state.
  Timing TimeLeg(const std::vector<model::SegmentDesign>& prefix, const SteadyLeg& leg,
                 double horizon) const;

  // A leg from rest at |force| in (mapping, sign), timed; travel = span over the box.
  bool MakeLeg(const std::string& mapping, int sign, double force_abs, SteadyLeg* leg) const;

  // The smallest |force| in [lo, hi] whose run settles and holds within t_max: lo itself when
  // it does, else by bisection in log force (a short --max-duration: ROMEO surge's min_thrust
  // run takes 63 s, its 25 s runs at 183 N were refused with it). A larger force takes less
  // of both: it settles sooner (the linearised drag grows with the speed, ref 000 eq. 13) and
  // holds shorter (HoldTime ∝ 1/speed). False when none does.
  bool SmallestTimely(const std::string& mapping, int sign, double lo, double hi, double t_max,
                      double* force, SteadyLeg* leg) const;

 private:
  const DofPlanningProblem& ctx_;
  const SteadyDesignOptions& o_;
};

// Step 3: efficient rounding of N·w; every direction with weight keeps a leg (steady_weights.cc).
std::vector<SteadyLeg> ExactDesign(const std::vector<SteadyLeg>& candidates,
                                   const std::vector<double>& weights, int N);

// Step 4: packs result->legs into trials (`id_prefix`-1, -2, ...), each a chain of legs
// alternating in direction, in compatible thrusters, within the pool and the trial duration
// limit; their checks and information summed at each design point (leg_packing.cc).
void PackTrials(const DofPlanningProblem& ctx, const SteadyDesignOptions& o,
                const std::string& id_prefix, SteadyDesignResult* result);

}  // namespace uuvplan::planner::internal
