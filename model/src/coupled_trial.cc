#include "uuvplan/model/coupled_trial.h"

#include <algorithm>

namespace uuvplan::model {

bool ModeMoves(CombinedMode mode, Dof dof) {
  switch (mode) {
    case CombinedMode::kSurgeYaw:
      return dof == Dof::kSurge || dof == Dof::kYaw;
    case CombinedMode::kSwayYaw:
      return dof == Dof::kSway || dof == Dof::kYaw;
    case CombinedMode::kSurgeSwayYaw:
      return dof == Dof::kSurge || dof == Dof::kSway || dof == Dof::kYaw;
  }
  return false;
}

std::string CoupledTrialDesign::Check() const {
  const std::string where = "combined trial '" + id + "' (" +
                            std::string(kCombinedModeNames.Name(mode)) + ")";
  if (!(duration > 0)) return where + ": duration must be a positive number of seconds";
  for (Dof d : {Dof::kSurge, Dof::kSway, Dof::kYaw}) {
    const long n = std::count_if(inputs.begin(), inputs.end(),
                                 [&](const TrialDesign& in) { return in.dof == d; });
    if (n != (ModeMoves(mode, d) ? 1 : 0)) {
      return where + ": expected " + (ModeMoves(mode, d) ? "one input" : "no input") + " for " +
             std::string(DofName(d)) + ", found " + std::to_string(n);
    }
  }
  if (inputs.size() != static_cast<std::size_t>(mode == CombinedMode::kSurgeSwayYaw ? 3 : 2)) {
    return where + ": inputs on DOFs outside surge, sway, yaw";
  }
  return "";
}

}  // namespace uuvplan::model
