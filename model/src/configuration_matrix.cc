#include "uuvplan/model/configuration_matrix.h"

#include <Eigen/Geometry>

namespace uuvplan::model {

Eigen::MatrixXd ConfigurationMatrix(const std::vector<Thruster>& thrusters) {
  Eigen::MatrixXd b = Eigen::MatrixXd::Zero(6, static_cast<Eigen::Index>(thrusters.size()));
  for (std::size_t i = 0; i < thrusters.size(); ++i) {
    if (!thrusters[i].geometry) continue;
    const Eigen::Vector3d r(thrusters[i].geometry->position.data());
    const Eigen::Vector3d d(thrusters[i].geometry->direction.data());
    const auto column = static_cast<Eigen::Index>(i);
    b.block<3, 1>(0, column) = d;           // force
    b.block<3, 1>(3, column) = r.cross(d);  // moment about the origin: r × F
  }
  return b;
}

bool HasFullGeometry(const std::vector<Thruster>& thrusters) {
  for (const Thruster& t : thrusters) {
    if (!t.geometry) return false;
  }
  return !thrusters.empty();
}

double DerivationLength(const std::array<double, 3>& size) {
  return (size[0] + size[1] + size[2]) / 6.0;
}

}  // namespace uuvplan::model
