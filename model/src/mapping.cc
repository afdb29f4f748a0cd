#include "uuvplan/model/mapping.h"

namespace uuvplan::model {

std::string EtaName(const std::string& mapping, Direction d) {
  return "eta." + mapping + (d == Direction::kPos ? ".pos" : ".neg");
}

std::string_view OpenWaterName(OpenWater ow) {
  switch (ow) {
    case OpenWater::kPositive:
      return "positive";
    case OpenWater::kNegative:
      return "negative";
    case OpenWater::kBoth:
      return "both";
    case OpenWater::kNone:
      return "none";
  }
  return "both";
}

}  // namespace uuvplan::model
