#include "uuvplan/model/mapping.h"

namespace uuvplan::model {

std::string EtaName(const std::string& mapping, Direction d) {
  return "eta." + mapping + (d == Direction::kPos ? ".pos" : ".neg");
}

std::optional<std::pair<std::string, Direction>> ParseEtaQualifier(std::string_view qualifier) {
  const std::size_t dot = qualifier.rfind('.');
  if (dot == std::string_view::npos || dot == 0) return std::nullopt;
  const std::string_view direction = qualifier.substr(dot + 1);
  if (direction != "pos" && direction != "neg") return std::nullopt;
  return std::make_pair(std::string(qualifier.substr(0, dot)),
                        direction == "pos" ? Direction::kPos : Direction::kNeg);
}

std::string_view OpenWaterName(OpenWater ow) { return kOpenWaterNames.Name(ow); }

}  // namespace uuvplan::model
