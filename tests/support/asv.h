// The ASV of cases/asv (ref 003's coupled horizontal model), as the tests of the multi-DOF
// model, its simulation and its least squares use it.
#pragma once

#include <Eigen/Dense>
#include <string>

#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/model/coupled_model.h"

namespace uuvplan::testing {

/// cases/asv/truth.yaml: the ASV (the vehicle of cases/asv/vehicle.yaml) and its true
/// parameters.
inline model::Truth AsvTruth() {
  return io::ReadTruth(std::string(UUVPLAN_SOURCE_DIR) + "/cases/asv/truth.yaml");
}

/// The ASV's coupled horizontal model.
inline model::MultiDofModel AsvCoupledModel() {
  return model::CoupledHorizontalModel(AsvTruth().vehicle);
}

/// A θ of that model: [m, k, kq, bias] of surge, sway, yaw.
inline Eigen::VectorXd AsvTheta() {
  Eigen::VectorXd theta(12);
  theta << 330, 30, 90, 1.5, 510, 80, 260, -2.0, 177, 40, 60, 0.5;
  return theta;
}

}  // namespace uuvplan::testing
