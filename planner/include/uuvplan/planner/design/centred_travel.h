// Where a trial starts in the pool: its travel over the box centred in the free travel along
// its DOF (the run sheet's start and abort lines, the schedule's start, the coupled design's
// start on each horizontal axis).
#pragma once

#include <array>

namespace uuvplan::planner {

/// A travel [travel[0], travel[1]] (from the start) centred in a free travel with `slack` =
/// free − (travel[1] − travel[0]) to spare, split evenly between both ends: the free travel's
/// ends (the margin lines, where a run is aborted) lie at travel[0] − slack/2 and
/// travel[1] + slack/2 from the start, and the start lies slack/2 − travel[0] beyond its
/// negative end (the margin line at the rear wall, the port wall or the surface; the tether's
/// counter-clockwise end for a rotation).
struct CentredTravel {
  std::array<double, 2> ends = {0.0, 0.0};  ///< m or rad from the start
  double start = 0.0;                       ///< m or rad from the negative end
};

inline CentredTravel CentreTravel(double slack, const std::array<double, 2>& travel) {
  CentredTravel c;
  c.ends = {travel[0] - slack / 2, travel[1] + slack / 2};
  c.start = slack / 2 - travel[0];
  return c;
}

}  // namespace uuvplan::planner
