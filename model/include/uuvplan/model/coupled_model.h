// The coupled 3-DOF horizontal model of ref 003 ("ASV dynamics model": surge, sway, yaw), a
// multi-DOF model (multi_dof_model.h):
//
//   m_u·u̇ =  m_v·v·r − k_u·u − kq_u·|u|u + b_u + τ_X          (ref 003 speed equation)
//   m_v·v̇ = −m_u·u·r − k_v·v − kq_v·|v|v + b_v + τ_Y          (ref 003 steering, sway)
//   m_r·ṙ = (m_u − m_v)·u·v − k_r·r − kq_r·|r|r + b_r + τ_N   (ref 003 steering, yaw: the
//                                                              Munk moment −(X_u̇ − Y_v̇)·u·v)
//
// with the centre of gravity on the yaw axis (x_g = 0), no sway–yaw added mass (Y_ṙ = 0) and no
// cross-coupling drag (ref 003, "simplified model"): M is diagonal, m_u = m − X_u̇,
// m_v = m − Y_v̇, m_r = I_z − N_ṙ, and the rigid-body plus added-mass Coriolis and centripetal
// terms are fixed by those same inertias. Each DOF is the 1-DOF model of its structure (by
// default m, k, kq, bias; τ_ξ = η·φ_ξ of its mapping) plus the coupling term c·a·b of its
// Coriolis product (force_term.h), c tied to the inertias: surge c_vr = m_v, sway c_ur = −m_u,
// yaw c_uv = m_u − m_v. θ: "surge.m", "surge.k", …, "yaw.bias" — the coupling adds none.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "uuvplan/model/multi_dof_model.h"
#include "uuvplan/model/truth.h"

namespace uuvplan::model {

/// The DOFs of the coupled horizontal model, in θ order.
inline constexpr std::array<Dof, 3> kHorizontalDofs = {Dof::kSurge, Dof::kSway, Dof::kYaw};
/// The model's name in the files it reads and writes ({"model": "coupled-horizontal"}).
inline constexpr const char* kCoupledModelName = "coupled-horizontal";
/// ref 003 Table I's combined modes: the horizontal DOFs pushed together (DofList names).
inline constexpr std::array<const char*, 3> kCombinedModes = {"surge+yaw", "sway+yaw",
                                                              "surge+sway+yaw"};

/// The model on `vehicle`, DOF i of kHorizontalDofs with `structures[i]` (default: m, k, kq,
/// bias), plus the Coriolis coupling.
MultiDofModel CoupledHorizontalModel(const Vehicle& vehicle,
                                     std::vector<ModelStructure> structures = {});
/// The model a truth file describes: its surge, sway and yaw structures (TruthStructure).
MultiDofModel CoupledModelOfTruth(const Truth& truth);
/// θ of `model` (this one, or CoupledHorizontalModel's of fewer parameters) from the truth's
/// surge, sway and yaw params (k, kq, bias 0 when not given); InputError naming the DOF whose
/// m is missing.
Eigen::VectorXd CoupledThetaOfTruth(const MultiDofModel& model, const Truth& truth);

/// DOF `dof`'s Coriolis term (above) as a 1-DOF model sees it: a coefficient times the product
/// of two measured velocities, named as the coupling effect names its pair ("vr": surge
/// m_v·v·r, "ur": sway −m_u·u·r, "uv": yaw (m_u − m_v)·u·v); empty strings for a DOF outside
/// the horizontal model.
struct CoriolisTerm {
  std::string pair;         ///< the velocity letters, e.g. "vr"
  std::string coefficient;  ///< in the model's inertias, e.g. "m_v"
};
CoriolisTerm CoriolisTermOf(Dof dof);

}  // namespace uuvplan::model
