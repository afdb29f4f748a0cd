// The coupled 3-DOF horizontal model of seed 003 ("ASV dynamics model": surge, sway, yaw),
//
//   M·ν̇ + C_RB(ν)·ν + C_A(ν)·ν + D·ν + D_n(ν)·ν = τ,   ν = [u, v, r]ᵀ       (seed 003, 3-DOF)
//
// with the centre of gravity on the yaw axis (x_g = 0), no sway–yaw added mass (Y_ṙ = 0) and
// no cross-coupling drag (seed 003, "simplified model, neglecting cross-coupling drag terms").
// M is then diagonal, m_u = m − X_u̇, m_v = m − Y_v̇, m_r = I_z − N_ṙ, and the rigid-body plus
// added-mass Coriolis and centripetal terms are fixed by those same inertias:
//
//   m_u·u̇ =  m_v·v·r − k_u·u − kq_u·|u|u + b_u + τ_X          (seed 003 speed equation)
//   m_v·v̇ = −m_u·u·r − k_v·v − kq_v·|v|v + b_v + τ_Y          (seed 003 steering, sway)
//   m_r·ṙ = (m_u − m_v)·u·v − k_r·r − kq_r·|r|r + b_r + τ_N   (seed 003 steering, yaw: the
//                                                              Munk moment −(X_u̇ − Y_v̇)·u·v)
//
// In the model's vocabulary (parameter.h) each DOF keeps the standard parameters of the 1-DOF
// model (contract §Conventions): m (inertia including added mass), k = −X_u (−Y_v, −N_r),
// kq = −X_|u|u (…), bias (a constant force: current, tether). The coupling adds no parameter: it
// ties the DOFs through their inertias. τ is the thrust allocation of the vehicle's mappings:
// τ_ξ = η_ξ·φ_ξ, one mapping per DOF at a time (seed 003 Table I combined modes).
//
// θ layout (every vector of this file): [m, k, kq, bias] of surge, then sway, then yaw, named
// "<dof>.<parameter>" ("sway.kq").
#pragma once

#include <Eigen/Dense>
#include <array>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/truth.h"

namespace uuvplan::model {

/// The DOFs of the coupled horizontal model, in θ order.
inline constexpr std::array<Dof, 3> kHorizontalDofs = {Dof::kSurge, Dof::kSway, Dof::kYaw};
/// The per-DOF parameters, in θ order within a DOF.
inline constexpr std::array<const char*, 4> kCoupledDofParameters = {"m", "k", "kq", "bias"};
inline constexpr int kCoupledParameterCount = 12;

/// ν = [u, v, r] (m/s, m/s, rad/s) and a force vector τ = [X, Y, N] (N, N, N·m).
using Horizontal = Eigen::Vector3d;

/// The position of `dof` among the horizontal DOFs (0 surge, 1 sway, 2 yaw); -1 otherwise.
int HorizontalIndex(Dof dof);

/// θ's index of `parameter` ("m", "k", "kq", "bias") of horizontal DOF `i`.
int CoupledIndex(int i, const char* parameter);

/// "surge.m", "surge.k", …, "yaw.bias" (θ order).
std::vector<std::string> CoupledParameterNames();
/// The unit of θ entry `j` (from the vocabulary: Unit("kq", Dof::kYaw) = "N·m·s²/rad²").
std::string CoupledParameterUnit(int j);

struct CoupledHorizontalModel {
  Eigen::Matrix<double, kCoupledParameterCount, 1> theta =
      Eigen::Matrix<double, kCoupledParameterCount, 1>::Zero();

  double Inertia(int i) const { return theta[4 * i]; }
  /// The Coriolis and centripetal forces on the right-hand side (the equations above):
  /// [m_v·v·r, −m_u·u·r, (m_u − m_v)·u·v].
  Horizontal Coriolis(const Horizontal& nu) const;
  /// −k·ξ − kq·|ξ|ξ + bias per DOF.
  Horizontal DragAndBias(const Horizontal& nu) const;
  /// ν̇ for thrust τ: M⁻¹·(Coriolis + DragAndBias + τ).
  Horizontal Acceleration(const Horizontal& nu, const Horizontal& tau) const;
  /// Whether every parameter is admissible in its family (parameter.h: m > 0, drag >= 0) —
  /// the message names the first that is not.
  bool Admissible(std::string* why) const;
};

/// DOF `dof`'s Coriolis term (Coriolis() above) as a 1-DOF model sees it: a coefficient times
/// the product of two measured velocities, named as the coupling effect names its pair
/// ("vr": surge m_v·v·r, "ur": sway −m_u·u·r, "uv": yaw (m_u − m_v)·u·v); empty strings for a
/// DOF outside the horizontal model.
struct CoriolisTerm {
  std::string pair;         ///< the velocity letters, e.g. "vr"
  std::string coefficient;  ///< in the model's inertias, e.g. "m_v"
};
CoriolisTerm CoriolisTermOf(Dof dof);

/// The force balance of equation `i` written linear in θ (seed 003 H matrix, generalised):
///   h_acc·ν̇_i + h(ν)·θ = τ_i,
/// where h_acc multiplies the DOF's own inertia and `h` (12 entries, zero on that inertia)
/// holds the Coriolis columns (surge: −v·r on m_v; sway: u·r on m_u; yaw: −u·v on m_u, u·v on
/// m_v), the drag columns ξ and |ξ|ξ and −1 on the bias.
Eigen::Matrix<double, kCoupledParameterCount, 1> CoupledRegressor(int i, const Horizontal& nu);

/// The coupled model of a truth file: the params of its surge, sway and yaw DOFs (m required;
/// k, kq, bias default to 0). InputError naming the DOF when one is missing.
CoupledHorizontalModel CoupledModelOfTruth(const Truth& truth);

}  // namespace uuvplan::model
