// How thrust mappings are derived from the thrusters' geometry (derived_mappings.h): which
// residual forces a mapping may leave, and how close a jet may pass another thruster.
#pragma once

#include <optional>
#include <vector>

#include "uuvplan/model/dof.h"

namespace uuvplan::model {

struct MappingDerivationOptions {
  /// m: a jet whose axis passes, downstream, within this distance of another thruster or of the
  /// vehicle's centre is not in open water. Absent: DefaultJetClearance(size), the mean
  /// half-side of the size box (jet_clearance.h).
  std::optional<double> jet_clearance;
  /// DOFs held by a hydrostatic restoring moment (roll, pitch of a vehicle with metacentric
  /// height): a mapping may leave a moment on them, which tilts the vehicle to a steady angle
  /// instead of driving a motion. Default none: every other DOF must stay unforced.
  std::vector<Dof> restoring;
  /// The largest force on another DOF a mapping may leave, relative to its own DOF's force
  /// (moments read as forces at DerivationLength(size)). CHOSEN 1e-3: a geometry written with
  /// 3-4 significant digits allocates exactly to about that.
  double purity_tolerance = 1e-3;
  /// Subsets of thrusters are enumerated (2^n of them) up to this many thrusters; above, only
  /// each DOF's all-thrusters mapping is derived.
  int max_subset_thrusters = 12;

  bool IsValid() const {
    return (!jet_clearance || *jet_clearance > 0) && purity_tolerance > 0 && purity_tolerance < 1 &&
           max_subset_thrusters >= 0 && max_subset_thrusters <= 20;
  }
};

}  // namespace uuvplan::model
