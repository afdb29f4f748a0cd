// What the pool team loads into the vehicle and reads at the pool side: for
// every trial of a schedule, each thruster's command against time — the trial's nominal force
// φ_n(t) shared by its mapping, τ_i = share_i·φ_n (ref 000 Table I), turned into the
// thruster's command units by the inverse of its thrust model (model::ThrustModel::Command) —
// and the expected position (the nominal vehicle, the centre of the a priori box); and the run
// sheet: where to start, which way to head, how long, how far the vehicle is expected to go
// over the whole box, and where to abort.
//
// Start and abort: the trial's travel over the box, [lo, hi] from the start, is centred in the
// pool's free travel F along its DOF (walls less the margin at both ends; for a rotation the
// tether's twist 2π·max_turns, centred on the untwisted tether). With slack = F − (hi − lo) the
// margin lines lie at a_neg = lo − slack/2 and a_pos = hi + slack/2 from the start (a_pos − a_neg
// = F; trial_envelope.h, CentreTravel): the run is aborted when the vehicle reaches either.
// The start is then margin − a_neg from the wall behind (from the surface for heave), or a
// twist of −F/2 − a_neg for a rotation. A person marks a translation's start and abort lines to
// the centimetre: the start is rounded to it, and the abort lines are the margin lines measured
// from that start, rounded to it too (each within 5 mm of the exact line; the designs keep their
// travel 5–10 mm inside, travel_margin.h).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::planner {

struct TrialCommands {
  std::string id;
  model::Dof dof = model::Dof::kSurge;
  model::TrialKind kind = model::TrialKind::kSteady;
  std::vector<std::string> mappings;  ///< in the order the trial uses them
  double duration = 0.0;              ///< s
  /// Rows: t (s) from the start, each thruster's command (vehicle order, command units) held
  /// until the next row, and the expected position (m or rad from the start). The last row,
  /// at the trial's end, stops every thruster.
  std::vector<double> t;
  Eigen::MatrixXd command;
  std::vector<double> expected_position;
  std::array<double, 2> travel = {0, 0};  ///< over the a priori box, from the start (m or rad)
  std::array<double, 2> abort = {0, 0};   ///< the margin lines from the start: a_neg, a_pos
  /// Start: x along the pool's length from the wall behind, y across its width from the left
  /// wall, z depth below the surface (m); the pool's centre on axes the trial does not move.
  std::array<double, 3> start = {0, 0, 0};
  double start_twist = 0.0;  ///< rotations: the tether's twist at the start (rad), else 0
};

struct CommandSheet {
  std::vector<std::string> thrusters;  ///< vehicle order
  double rate_hz = 0.0;
  std::vector<TrialCommands> trials;  ///< schedule order
};

struct CommandSheetOptions {
  /// Command rows per second. CHOSEN 20 Hz: the rate the virtual pool logs commands at and a
  /// usual thruster-controller rate; a segment's change also gets a row of its own.
  double rate_hz = 20.0;
  ScheduleOptions schedule;  ///< the box the travel and expected position are taken over
};

/// The commands and run sheet of every trial of `schedule`. Throws model::InputError when a
/// trial names a mapping the vehicle does not have.
CommandSheet MakeCommandSheet(const model::Vehicle& vehicle, const model::Pool& pool,
                              const Schedule& schedule, const CommandSheetOptions& options);

/// The commands of every thruster (vehicle order), as each takes them, for nominal force `phi`
/// in mapping `mapping` (-1: none, every thruster at its neutral).
Eigen::VectorXd ThrusterCommands(const model::Vehicle& vehicle, int mapping, double phi);

}  // namespace uuvplan::planner
