#include "uuvplan/model/mapping.h"

namespace uuvplan::model {

std::string EtaName(const std::string& mapping, Direction d) {
  return "eta." + mapping + (d == Direction::kPos ? ".pos" : ".neg");
}

std::string_view OpenWaterName(OpenWater ow) { return kOpenWaterNames.Name(ow); }

}  // namespace uuvplan::model
