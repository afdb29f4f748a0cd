// The thruster configuration matrix B (Fossen 2011 eq. 11.3): the generalised force of the
// thrusters' forces, tau_body = B·tau. Column i is [d_i; r_i × d_i] for thruster i at r_i
// pushing along the unit vector d_i; rows surge, sway, heave, roll, pitch, yaw (dof.h order).
#pragma once

#include <Eigen/Core>
#include <array>
#include <vector>

#include "uuvplan/model/thruster.h"

namespace uuvplan::model {

/// 6 × n; a thruster without geometry has a zero column.
Eigen::MatrixXd ConfigurationMatrix(const std::vector<Thruster>& thrusters);

/// True when every thruster has a position and a direction.
bool HasFullGeometry(const std::vector<Thruster>& thrusters);

/// The length that turns a moment into a comparable force, F = M / L: the mean half-side of
/// the vehicle's size box, (length + width + height)/6 (m).
double DerivationLength(const std::array<double, 3>& size);

}  // namespace uuvplan::model
