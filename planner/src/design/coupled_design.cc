#include "uuvplan/planner/design/coupled_design.h"

namespace uuvplan::planner {

CombinedDesignOptions CoupledDesignOptions(std::vector<model::Dof> dofs) {
  CombinedDesignOptions o;
  o.dofs = std::move(dofs);
  // offset/F, amplitude/F, (ω − ω_min)/(ω_max − ω_min): ω 0.24, 0.31 and 0.8 rad/s where the
  // sensors resolve 1.5 rad/s (the ASV's 10 Hz).
  o.start = {{model::Dof::kSurge, {0.0, 0.1, 0.1}},
             {model::Dof::kSway, {0.0, 0.1, 0.15}},
             {model::Dof::kYaw, {0.5, 0.1, 0.5}}};
  o.swept_axis = "yaw.drag";
  return o;
}

}  // namespace uuvplan::planner
