// A combined-mode trial of the coupled horizontal model (seed 003 Table I: the horizontal
// mappings pushing surge, sway and yaw at once): one input per DOF the mode moves, each a
// 1-DOF trial design (trial_design.h: steady, sine, segments, switched) in a mapping of that
// DOF, all over the same duration from rest. The DOFs the mode does not move are commanded 0.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::model {

/// The combined motion modes: the horizontal DOFs pushed together (seed 003 Table I
/// "horizontal all" and its surge/sway modes with N free).
enum class CombinedMode { kSurgeYaw, kSwayYaw, kSurgeSwayYaw };
inline constexpr EnumNames<CombinedMode, 3> kCombinedModeNames{{{
    {CombinedMode::kSurgeYaw, "surge+yaw"},
    {CombinedMode::kSwayYaw, "sway+yaw"},
    {CombinedMode::kSurgeSwayYaw, "surge+sway+yaw"},
}}};

/// Whether `mode` pushes `dof`.
bool ModeMoves(CombinedMode mode, Dof dof);

struct CoupledTrialDesign {
  std::string id;
  CombinedMode mode = CombinedMode::kSurgeSwayYaw;
  double duration = 0.0;  ///< s
  /// One design per DOF the mode moves (its `dof`, `mapping`, kind and force law; its own
  /// duration is ignored: the trial's holds).
  std::vector<TrialDesign> inputs;

  /// "" when the inputs are exactly one per DOF the mode moves, else what is wrong.
  std::string Check() const;
};

}  // namespace uuvplan::model
