// Where a thruster sits and which way it pushes, in the body frame of Fossen/SNAME (x forward,
// y starboard, z down; origin at the vehicle's centre, the reference point of its DOFs).
#pragma once

#include <array>

namespace uuvplan::model {

struct ThrusterGeometry {
  std::array<double, 3> position = {0, 0, 0};   ///< m, body frame
  std::array<double, 3> direction = {1, 0, 0};  ///< unit vector of positive thrust, body frame
};

}  // namespace uuvplan::model
