// Internal to the vehicle reader and writer: how a thruster is installed and run — its
// `position`, `direction` and `reversible` keys and its thrust model's `dead_band`
// (docs/formats.md, "Vehicle").
#pragma once

#include <yaml-cpp/yaml.h>

#include <array>

#include "uuvplan/io/yaml_value.h"
#include "uuvplan/model/thruster.h"

namespace uuvplan::io {

/// The keys a thruster map may hold besides name, thrust and command.
inline constexpr std::array<std::string_view, 3> kThrusterInstallationKeys = {
    "position", "direction", "reversible"};

/// Reads position and direction (both or neither), reversible, and thrust.dead_band of the
/// thruster map `m` into `t` (its command range already read). `size`: the vehicle's
/// [length, width, height] (m), which bounds a position.
void ParseThrusterInstallation(const MapValue& m, const std::array<double, 3>& size,
                               model::Thruster* t);

/// Writes position, direction and reversible (those that differ from the defaults) as keys of
/// the thruster map being emitted.
void EmitThrusterInstallation(YAML::Emitter& out, const model::Thruster& t);

}  // namespace uuvplan::io
