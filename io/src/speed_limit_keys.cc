#include "speed_limit_keys.h"

#include "uuvplan/io/number_text.h"

namespace uuvplan::io {

model::SpeedLimits ParseSpeedLimits(const MapValue& root) {
  model::SpeedLimits limits;
  if (const Value v = root.Optional("max_translation_speed"); !v.absent()) {
    limits.translation = Positive(v);
  }
  if (const Value v = root.Optional("max_rotation_rate"); !v.absent()) {
    limits.rotation = Positive(v);
  }
  return limits;
}

void EmitSpeedLimits(YAML::Emitter& out, const model::SpeedLimits& limits) {
  if (limits.translation) {
    out << YAML::Key << "max_translation_speed" << YAML::Value << FileNumber(*limits.translation);
  }
  if (limits.rotation) {
    out << YAML::Key << "max_rotation_rate" << YAML::Value << FileNumber(*limits.rotation);
  }
}

}  // namespace uuvplan::io
