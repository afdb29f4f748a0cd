// Internal to the vehicle reader: the vehicle keys that steer the mappings derived from the
// thrusters' geometry (`jet_clearance`, `restoring`), and their addition to the vehicle's table
// (model/derived_mappings.h, docs/formats.md "Mappings derived from the geometry").
#pragma once

#include "uuvplan/io/yaml_value.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::io {

/// jet_clearance and restoring of the vehicle map `root` (defaults when absent).
model::MappingDerivationOptions ParseMappingDerivation(const MapValue& root);

/// With every thruster's geometry given: appends to vehicle->mappings the mappings derived for
/// each DOF the `mappings` table leaves out (the table wins where it gives a DOF). Fails naming
/// the thruster when only some thrusters have geometry, and the vehicle when it has no mapping
/// at all (no table and no DOF the geometry drives alone: each DOF's reason).
void AddDerivedMappings(const MapValue& root, model::Vehicle* vehicle);

}  // namespace uuvplan::io
