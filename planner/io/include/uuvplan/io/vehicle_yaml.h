// The vehicle file (contract §Vehicle): read with every fault reported as model::InputError
// "<file>:<line>: <key.path>: expected <what>, got <value>", and written so that it reads back
// to the same vehicle.
#pragma once

#include <string>

#include "uuvplan/model/vehicle.h"

namespace uuvplan::io {

model::Vehicle ReadVehicle(const std::string& path);

/// Writes a vehicle file that ReadVehicle reads back to the same vehicle (atomically).
void WriteVehicleYaml(const std::string& path, const model::Vehicle& vehicle);

}  // namespace uuvplan::io
