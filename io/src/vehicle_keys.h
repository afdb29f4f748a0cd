// Internal to the YAML readers: the vehicle keys, shared by the vehicle and the truth file.
#pragma once

#include <optional>

#include "uuvplan/io/yaml_value.h"
#include "uuvplan/model/truth.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::io {

/// The vehicle keys of `root`; a truth file (`truth`) may also have virtual_pool and per-DOF
/// params and effects (read by the truth reader).
model::Vehicle ParseVehicle(const MapValue& root, bool truth);

/// dofs.<dof>.params, .effects and .sigma (a truth, or a model written into a vehicle file);
/// nullopt when the DOF has no params.
std::optional<model::DofTruth> ParseTruthDof(const Value& v, model::Dof dof,
                                             const model::Vehicle& vehicle);

}  // namespace uuvplan::io
