// A trial log as read from / written to CSV (contract §Trial log): time, and per DOF the
// nominal force, measured position and velocity, or per thruster its command. Missing samples
// are NaN.
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"

namespace uuvplan::model {

struct TrialLog {
  /// Columns per DOF (indexed by Index(dof)); empty vector = column absent; NaN = no sample.
  using DofColumns = std::array<std::vector<double>, kNumDofs>;

  std::vector<double> t;  ///< s, strictly increasing
  DofColumns force;       ///< force_<dof>: N or N·m
  DofColumns position;    ///< pos_<dof>: m or rad (unwrapped)
  DofColumns velocity;    ///< vel_<dof>: m/s or rad/s
  /// cmd_<thruster>: each thruster's command as it takes it (e.g. µs of PWM), by name; the
  /// force columns follow from them (ForceFromCommands, commanded_force.h).
  std::map<std::string, std::vector<double>> commands;
  /// Optional `mapping` column: index into mapping_names per row, -1 = empty cell.
  std::vector<int> mapping;
  std::vector<std::string> mapping_names;
  /// What the reader noticed and did not treat as an error (unknown columns, unwrapping).
  std::vector<std::string> notes;

  std::size_t size() const { return t.size(); }
  bool HasForce(Dof d) const { return !force[Index(d)].empty(); }
  bool HasPosition(Dof d) const { return !position[Index(d)].empty(); }
  bool HasVelocity(Dof d) const { return !velocity[Index(d)].empty(); }
  bool HasAnyForce() const {
    for (const auto& column : force) {
      if (!column.empty()) return true;
    }
    return false;
  }
};

/// One kind of a log's columns: &TrialLog::force, &TrialLog::position or &TrialLog::velocity.
using LogColumnKind = TrialLog::DofColumns TrialLog::*;

/// Unwraps pos_roll/pitch/yaw wrapped to one turn (what ReadTrialLog does): a column within
/// (-pi, pi] or [0, 2pi) (1e-3 of slack for rounding): wherever two consecutive samples differ
/// by more than pi, later samples shift by the multiple of 2·pi that brings the step back within
/// pi. A column outside both is not a wrapped angle in rad: unwrapped by 360 the same way when
/// it lies within (-180, 180] or [0, 360) and steps by more than 180 (degrees; the unit check
/// names them), else left as logged. Notes what it did in log->notes.
void UnwrapAngles(TrialLog* log);

}  // namespace uuvplan::model
