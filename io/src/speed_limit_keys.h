// Internal to the vehicle reader and writer: the keys max_translation_speed (m/s) and
// max_rotation_rate (rad/s), the steady speeds a trial may ask of the vehicle.
#pragma once

#include <yaml-cpp/yaml.h>

#include "uuvplan/io/yaml_value.h"
#include "uuvplan/model/speed_limits.h"

namespace uuvplan::io {

/// Both keys of the vehicle map `root`, each > 0 when given.
model::SpeedLimits ParseSpeedLimits(const MapValue& root);

/// Writes the keys that are set.
void EmitSpeedLimits(YAML::Emitter& out, const model::SpeedLimits& limits);

}  // namespace uuvplan::io
