#include "uuvplan/model/model_structure.h"

#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

ModelStructure ModelStructure::Standard(const Vehicle& vehicle, Dof dof,
                                        const std::vector<std::string>& mappings_used,
                                        bool ballast) {
  ModelStructure s;
  s.dof = dof;
  s.ballast = ballast;
  for (const auto& name : mappings_used) {
    const int i = vehicle.MappingIndex(name);
    if (i < 0) continue;
    const ThrustMapping& m = vehicle.mappings[i];
    for (Direction d : {Direction::kPos, Direction::kNeg}) {
      if (!m.IsOpenWater(d)) s.free_eta.push_back(EtaName(m.name, d));
    }
  }
  return s;
}

}  // namespace uuvplan::model
