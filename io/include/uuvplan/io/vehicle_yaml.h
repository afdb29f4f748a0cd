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

/// How the header of a file a command writes begins: "written by `uuvplan identify …".
inline constexpr std::string_view kWrittenByPrefix = "written by `uuvplan ";

/// Writes `vehicle`, read from the vehicle file `source` as its user wrote it, as that file
/// updated: its text — keys, order, numbers and comments — kept, its top-level `dofs:` block
/// (a priori drag, identified models) replaced by the vehicle's, or added at its end; the header
/// an earlier `--write-vehicle` wrote replaced by `comment`. A file that names a `base:` (a
/// payload) is written whole by WriteVehicleYaml instead. Throws model::InputError naming
/// `source` when it cannot be read.
void WriteVehicleYamlOver(const std::string& path, const std::string& source,
                          const model::Vehicle& vehicle, const std::string& comment);

}  // namespace uuvplan::io
