// Seeded random vehicles and pools for the feasibility tests: 15-500 kg, 1-4
// thrusters per DOF (surge, sway, heave, yaw), pools 4-30 m long. Every draw comes from the
// seed (std::mt19937_64), so a failing case is reproduced by its seed alone.
#pragma once

#include <cstdint>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/truth.h"
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

/// A virtual vehicle for `c` (the loop's validation), drawn from its own stream of
/// `seed` (the case's draws are unchanged): per DOF of `c.dofs`, m uniform in the vehicle's
/// inertia bounds; k and kq = model::DragOf's thrust-scaled a priori drag times one factor
/// log-uniform in [0.5, 2] (the a priori terminal speed of 1 m/s off by up to √2 either way);
/// bias uniform within ±2% of the DOF's largest thrust (ROMEO heave: 13.5 N of 600 N); every η
/// of a direction that is not open water uniform in [0.55, 0.95] (ref 000 Tables I–III:
/// 0.56–0.89). Position sensors as the case's, no sensor defects.
model::Truth MakeRandomTruth(const RandomCase& c, std::uint64_t seed);

}  // namespace uuvplan::testing
