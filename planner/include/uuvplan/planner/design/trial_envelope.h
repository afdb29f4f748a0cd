// What a planned trial does over the a priori box, as time series for figures and run sheets:
// the position of the centre vehicle and the envelope of the box's check grid (the extreme
// vehicles the pool check simulates, dof_planning_problem.h), and each thruster's force
// tau_i(t) = share_i·phi_n(t) of the mapping in force (ref 000 Table I).
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/pool.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/planner/design/centred_travel.h"
#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/schedule.h"

namespace uuvplan::planner {

struct PositionEnvelope {
  std::vector<double> t;        ///< s, uniform from 0 to the trial's duration
  std::vector<double> nominal;  ///< m or rad: the box's centre vehicle
  std::vector<double> low;      ///< smallest position over the check grid at t
  std::vector<double> high;     ///< largest
};

/// The position of `design` from rest over `ctx`'s check grid at `points` (>= 2) times.
PositionEnvelope EnvelopeOf(const DofPlanningProblem& ctx, const model::TrialDesign& design,
                            int points);

struct ThrusterForces {
  std::vector<double> t;  ///< s
  /// Per thruster of the vehicle (its index), tau_i(t) in N; 0 while the thruster is idle.
  std::vector<std::vector<double>> force;
  /// Whether thruster i works at some time of the trial (share != 0 in a mapping used).
  std::vector<bool> used;
  std::vector<double> nominal;  ///< phi_n(t), the designed input (N or N·m)
};

/// The designed input and each thruster's force at `points` (>= 2) times, plus both sides of
/// every breakpoint of the input (so a step is drawn as a step).
ThrusterForces ThrusterForcesOf(const model::Vehicle& vehicle, const model::TrialDesign& design,
                                int points);

/// The nominal input phi_n(t) and the mapping in force, sampled for replay (the
/// schedule's trials at 0.1 s or 40 samples per period of a wave's fastest component): a
/// uniform grid at most `max_spacing_s` apart from 0 to the duration, plus both sides of every
/// jump (1e-9·duration before it and at it), so that a zero-order hold or a linear
/// interpolation of the samples reproduces the design.
TrialProfile SampleProfile(const model::Vehicle& vehicle, const model::TrialDesign& design,
                           double max_spacing_s = 0.1);

/// Where a trial whose travel over the box is [travel[0], travel[1]] (from its start) starts so
/// that the travel is centred in the pool's free length, width or depth (or in the tether's
/// turns): metres from the rear wall (surge), the port wall (sway) or the surface (heave), or
/// degrees clockwise from the heading at the tether's counter-clockwise end for a rotation.
StartPosition StartOf(const model::Pool& pool, model::Dof dof, const std::array<double, 2>& travel);

/// The schedule's replay fields of a planned trial: its sampled profile and its start.
void AddReplayFields(const model::Vehicle& vehicle, const model::Pool& pool, PlannedTrial* trial);

}  // namespace uuvplan::planner
