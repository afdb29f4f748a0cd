// The virtual pool: runs a planned trial on a truth vehicle from rest and logs it as a pool
// team would — commands at the controller's rate (held between rows), each sensor at its own
// rate with Gaussian noise, drop-outs and occasional multipath outliers. Deterministic for a
// given seed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "uuvplan/model/model_structure.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/trial_log.h"
#include "uuvplan/model/truth.h"

namespace uuvplan::model {

struct VirtualPoolOptions {
  double command_rate_hz = 20.0;  ///< rate at which the force command is updated and logged
  std::uint64_t seed = 1;
};

/// The structure that a truth DOF's parameters describe (standard model + its effects).
ModelStructure TruthStructure(const Truth& truth, Dof dof);

/// Runs one trial; `start_time` is its start on the campaign clock (for drift).
TrialLog RunVirtualTrial(const Truth& truth, const TrialDesign& design, double start_time,
                         const VirtualPoolOptions& options);

}  // namespace uuvplan::model
