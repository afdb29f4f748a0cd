// The virtual pool for a combined-mode trial (coupled_trial.h) on the coupled horizontal model
// of a truth (coupled_model.h): the commands of each moved DOF at the controller's rate, held
// between rows; the thrust τ_ξ = η_ξ·φ_ξ of the mapping in force (η from the truth's
// eta.<mapping>.<dir>, else 1); each horizontal sensor the vehicle declares sampled at its rate
// with the same noise, drop-outs and outliers as the 1-DOF trials (virtual_pool.h). Logged:
// force_<dof> of surge, sway and yaw (0 for a DOF the mode does not move), vel_<dof> as the
// body-frame velocities u, v, r, pos_yaw the heading ψ (wrapped), pos_surge / pos_sway the pool
// frame x, y of the start's heading. Deterministic for a given seed.
#pragma once

#include "uuvplan/model/coupled_trial.h"
#include "uuvplan/model/trial_log.h"
#include "uuvplan/model/truth.h"
#include "uuvplan/model/virtual_pool.h"

namespace uuvplan::model {

TrialLog RunCoupledVirtualTrial(const Truth& truth, const CoupledTrialDesign& design,
                                const VirtualPoolOptions& options);

}  // namespace uuvplan::model
