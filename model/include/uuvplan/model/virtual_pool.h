// The virtual pool: runs a planned trial on a truth vehicle from rest and logs it as a pool
// team would — commands at the controller's rate (held between rows), each sensor at its own
// rate with Gaussian noise, drop-outs and occasional multipath outliers. Deterministic for a
// given seed.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "uuvplan/model/model_structure.h"
#include "uuvplan/model/multi_dof_model.h"
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

/// The truth's noise-free position over one trial run from rest as RunVirtualTrial runs it (m or
/// rad from where it starts): its least and largest, sampled 0.05 s apart.
std::array<double, 2> TrueTravel(const Truth& truth, const TrialDesign& design, double start_time,
                                 double command_rate_hz);

/// Runs one combined trial (trial_design.h) on `model`, the joint model of `truth` at θ
/// `theta`: each moved DOF's commands at the controller's rate, held between rows; each
/// position and velocity sensor the vehicle declares for the model's DOFs sampled as above.
/// Logged for every DOF of the model: force_<dof> (0 for a DOF the trial does not move),
/// pos_<dof> its position state (the planar model: the pool-frame x, y of the start's heading,
/// and the heading ψ wrapped) and vel_<dof> its body-frame velocity. InputError when the trial
/// does not Check() or moves a DOF the model does not have.
TrialLog RunCombinedTrial(const Truth& truth, const MultiDofModel& model,
                          const Eigen::VectorXd& theta, const CombinedTrialDesign& design,
                          const VirtualPoolOptions& options);

}  // namespace uuvplan::model
