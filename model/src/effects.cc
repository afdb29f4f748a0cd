#include "uuvplan/model/effects.h"

#include <array>

namespace uuvplan::model {

namespace {
constexpr std::array<std::string_view, 9> kNames = {
    "installation_loss", "asymmetric_drag", "thruster_lag",    "deadzone",  "advance_speed_loss",
    "coupling",          "sensor_delay",    "parameter_drift", "thrust_map"};
}

std::string_view EffectName(Effect e) { return kNames[static_cast<int>(e)]; }

std::optional<Effect> ParseEffect(std::string_view name) {
  for (std::size_t i = 0; i < kNames.size(); ++i) {
    if (kNames[i] == name) return static_cast<Effect>(i);
  }
  return std::nullopt;
}

}  // namespace uuvplan::model
