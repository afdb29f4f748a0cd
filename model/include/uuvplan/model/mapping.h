// Thrust mappings (ref 000 Table I): how a DOF's nominal force phi is shared among the
// thrusters, tau_i = share_i·phi, and in which direction of phi the thrusters work in open
// water (installation coefficient eta = 1, ref 000 §II-A).
#pragma once

#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::model {

enum class OpenWater { kPositive, kNegative, kBoth, kNone };
/// The vehicle file's names of OpenWater (its `open_water` key).
inline constexpr EnumNames<OpenWater, 4> kOpenWaterNames{{{
    {OpenWater::kPositive, "positive"},
    {OpenWater::kNegative, "negative"},
    {OpenWater::kBoth, "both"},
    {OpenWater::kNone, "none"},
}}};

/// Direction of the nominal force phi: eta is defined per mapping and per direction.
enum class Direction { kPos, kNeg };

struct ThrustMapping {
  std::string name;
  Dof dof = Dof::kSurge;
  std::vector<std::pair<int, double>> shares;  ///< (thruster index in Vehicle::thrusters, share)
  OpenWater open_water = OpenWater::kBoth;

  /// True when eta = 1 is assumed for this direction (not a parameter).
  bool IsOpenWater(Direction d) const {
    return open_water == OpenWater::kBoth ||
           (d == Direction::kPos ? open_water == OpenWater::kPositive
                                 : open_water == OpenWater::kNegative);
  }
};

/// "eta.<mapping>.pos" / "eta.<mapping>.neg" (contract §identify).
std::string EtaName(const std::string& mapping, Direction d);
/// The mapping and direction of "<mapping>.<pos|neg>" (an η name without "eta."), or nullopt.
std::optional<std::pair<std::string, Direction>> ParseEtaQualifier(std::string_view qualifier);
std::string_view OpenWaterName(OpenWater ow);

}  // namespace uuvplan::model
