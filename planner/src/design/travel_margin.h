// How far inside the pool's free travel (DofPlanningProblem::available) a design keeps its travel
// over the box, so that the final check (DofPlanningProblem::Check: a finer step, a denser box
// grid) agrees with the travel the design computed for itself. Two values, one per kind of design:
// the sine family traces its travel on the design points and steady legs on their own timing, and
// each kept the margin it was tuned with.
#pragma once

#include <algorithm>

namespace uuvplan::planner {

/// Sine-family designs: the single sine (sine_design.cc) and the mapping-switched square, sine
/// and multisine (switched_design.cc), m.
inline constexpr double kSineTravelMargin = 0.005;
/// Steady legs and the chains of them (steady_design.cc), m.
inline constexpr double kSteadyTravelMargin = 0.01;
/// The largest margin any design keeps: a pool offered for a travel need gets this much more
/// free travel (pool_verdict.cc), so that every kind of design can use the whole need.
inline constexpr double kLargestTravelMargin = std::max(kSineTravelMargin, kSteadyTravelMargin);

}  // namespace uuvplan::planner
