// A surge model with every effect of the table on, on a vehicle with the mappings "front" and
// "rear": the model the simulator's tests check (tests/model/model_simulator_test.cc) and its
// benchmark times (bench/simulate_bench.cc, docs/performance.md).
#pragma once

#include <map>
#include <string>

#include "uuvplan/model/model_structure.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::testing {

/// A 450 kg vehicle (ROMEO's mass and size) with the surge mappings "front" (open water forward)
/// and "rear" (open water backward) and no thrusters: the DOF model needs only the mappings.
inline model::Vehicle FrontRearVehicle() {
  model::Vehicle v;
  v.name = "test";
  v.mass = 450;
  v.size = {1.3, 0.9, 1.0};
  v.mappings = {{"front", model::Dof::kSurge, {}, model::OpenWater::kPositive},
                {"rear", model::Dof::kSurge, {}, model::OpenWater::kNegative}};
  return v;
}

/// Asymmetric drag, ballast, a free η of front.neg and rear.pos, thruster lag, dead zone,
/// advance loss, coupling to the yaw rate (coupling.rr), drift, sensor delay and the thrust
/// map's shape at `thrust_reference` (N).
inline model::ModelStructure EveryEffectStructure(double thrust_reference) {
  model::ModelStructure s;
  s.dof = model::Dof::kSurge;
  s.parameters = {"k",
                  "k_neg",
                  "kq",
                  "kq_neg",
                  "bias",
                  "bias_step",
                  "eta.front.neg",
                  "eta.rear.pos",
                  "lag",
                  "deadzone",
                  "advance_loss",
                  "coupling.rr",
                  "sensor_delay",
                  "drift",
                  "thrust_exponent"};
  s.settings["thrust_reference"] = thrust_reference;
  return s;
}

/// Values of m and of every parameter of EveryEffectStructure (drag: ref 000 Table IV, ROMEO
/// forward surge).
inline std::map<std::string, double> EveryEffectValues() {
  return {{"m", 890},
          {"k", 46.9},
          {"k_neg", 57.9},
          {"kq", 306.2},
          {"kq_neg", 331.4},
          {"bias", 1.5},
          {"bias_step", 0.7},
          {"eta.front.neg", 0.89},
          {"eta.rear.pos", 0.73},
          {"advance_loss", 2.0},
          {"coupling.rr", 30.0},
          {"drift", -2e-4},
          {"lag", 0.4},
          {"deadzone", 3.0},
          {"sensor_delay", 0.3},
          {"thrust_exponent", -0.3}};
}

}  // namespace uuvplan::testing
