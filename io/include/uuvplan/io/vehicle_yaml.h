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

/// Writes a vehicle file that ReadVehicle reads back to the same vehicle (atomically).
void WriteVehicleYaml(const std::string& path, const model::Vehicle& vehicle);

/// Writes a vehicle file with a model of some DOFs: per DOF its parameters (dofs.<dof>.params
/// and .effects, as a truth file gives them, docs/formats.md) and their σ (dofs.<dof>.sigma).
/// Every command reads it as a vehicle; ReadTruth reads the model back (`score`, `simulate`).
/// `comment` heads the file (one "# " line per line).
void WriteVehicleYaml(const std::string& path, const model::Vehicle& vehicle,
                      const std::map<model::Dof, model::DofTruth>& models,
                      const std::string& comment);

}  // namespace uuvplan::io
