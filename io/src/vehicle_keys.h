// Internal to the YAML readers: the vehicle keys, shared by the vehicle and the truth file.
#pragma once

#include <array>
#include <optional>

#include "uuvplan/io/yaml_value.h"
#include "uuvplan/model/truth.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::io {

/// The vehicle keys of `root`; a truth file (`truth`) may also have virtual_pool and per-DOF
/// params and effects (read by the truth reader).
model::Vehicle ParseVehicle(const MapValue& root, bool truth);

/// A file that names its base vehicle (`base`, read by ReadVehicle relative to this file) and
/// the `payload` on it (model/payload.h): the combined vehicle called `name`, with the file's
/// own `sensors` in place of the base's. A truth file (`truth`) may also have dofs and
/// virtual_pool (read by the truth reader).
model::Vehicle ParsePayloadVehicle(const MapValue& root, bool truth);

/// `sensors` {<dof>: {position, velocity}} into the vehicle (its σ checked against its size).
void ParseSensors(const Value& v, model::Vehicle* vehicle);

/// [lo, hi] added-mass fractions of the rigid-body value, 0 <= lo <= hi.
std::array<double, 2> AddedMassBounds(const Value& v);

/// dofs.<dof>.params, .effects and .sigma (a truth, or a model written into a vehicle file);
/// nullopt when the DOF has no params.
std::optional<model::DofTruth> ParseTruthDof(const Value& v, model::Dof dof,
                                             const model::Vehicle& vehicle);

}  // namespace uuvplan::io
