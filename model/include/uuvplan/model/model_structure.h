// Which force terms a DOF's model has: the standard model of the contract plus any effects.
// A DofModel is built from a Vehicle and a ModelStructure; identification, planning and
// diagnosis change the structure, never the equations.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/dof.h"

namespace uuvplan::model {

struct ModelStructure {
  Dof dof = Dof::kSurge;
  bool linear_drag = true;
  bool quadratic_drag = true;
  bool bias = true;
  bool ballast = false;                 ///< bias_step per ballast step (seed 000 eq. 20)
  std::vector<std::string> free_eta;    ///< eta.<mapping>.<dir> estimated (others are 1)
  bool asymmetric_drag = false;
  bool thruster_lag = false;
  bool deadzone = false;
  bool advance_speed_loss = false;
  std::vector<std::string> coupling;    ///< velocity-letter pairs, e.g. "vr", "rr", "ur"
  bool sensor_delay = false;
  bool parameter_drift = false;
  bool thrust_map = false;
  /// thrust_map: the commanded force at which the nominal map is right, u_ref > 0 (N or N·m).
  double thrust_reference = 1.0;

  /// The standard structure of the contract: m, k, kq, bias, bias_step when `ballast`,
  /// and eta of every non-open-water direction of each of `mappings_used`.
  static ModelStructure Standard(const struct Vehicle& vehicle, Dof dof,
                                 const std::vector<std::string>& mappings_used, bool ballast);
};

}  // namespace uuvplan::model
