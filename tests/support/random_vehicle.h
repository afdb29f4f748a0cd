// Seeded random vehicles and pools for the feasibility tests (issue #13): 15-500 kg, 1-4
// thrusters per DOF (surge, sway, heave, yaw), pools 4-30 m long. Every draw comes from the
// seed (std::mt19937_64), so a failing case is reproduced by its seed alone.
#pragma once

#include <cstdint>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::testing {

struct RandomCase {
  model::Vehicle vehicle;
  model::Pool pool;
  std::vector<model::Dof> dofs;  ///< the DOFs to plan (a random non-empty subset, in order)
};

/// The case of `seed`: mass log-uniform in [15, 500] kg, a box of density 1000 kg/m³ with
/// aspect ratios in [1, 2.5]; per DOF 1-4 thrusters of 0.2-1 N per kg^0.75 each,
/// each mapping open water both ways or one way only (then an η to identify); min_thrust 2-5% of
/// the weakest thruster; position sensors; a pool 4-30 m long, 4-length wide, 2-8 m deep with
/// a margin of half the vehicle's length; `max_dofs` DOFs planned.
RandomCase MakeRandomCase(std::uint64_t seed, int max_dofs = 4);

}  // namespace uuvplan::testing
