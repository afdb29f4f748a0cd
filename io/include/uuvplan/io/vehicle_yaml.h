// The vehicle file (contract §Vehicle): read with every fault reported as model::InputError
// "<file>:<line>: <key.path>: expected <what>, got <value>", and written so that it reads back
// to the same vehicle.
#pragma once

#include <map>
#include <string>

#include "uuvplan/model/truth.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::io {

model::Vehicle ReadVehicle(const std::string& path);

/// Writes a vehicle file that ReadVehicle reads back to the vehicle it prints (atomically),
/// headed by `comment` (one "# " line per line). A DOF's model (vehicle.models: its parameters
/// as dofs.<dof>.params and .effects, as a truth file gives them, and their σ as
/// dofs.<dof>.sigma, docs/formats.md) is written beside the a priori keys; ReadTruth reads it
/// back too (`score`, `simulate`).
void WriteVehicleYaml(const std::string& path, const model::Vehicle& vehicle,
                      const std::string& comment = "written by uuvplan");

}  // namespace uuvplan::io
