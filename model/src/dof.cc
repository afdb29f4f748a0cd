#include "uuvplan/model/dof.h"

namespace uuvplan::model {

namespace {
constexpr std::array<std::string_view, kNumDofs> kNames = {"surge", "sway",  "heave",
                                                          "roll",  "pitch", "yaw"};
constexpr std::array<char, kNumDofs> kLetters = {'u', 'v', 'w', 'p', 'q', 'r'};
}  // namespace

std::string_view DofName(Dof dof) { return kNames[Index(dof)]; }

std::optional<Dof> ParseDof(std::string_view name) {
  for (Dof d : kAllDofs) {
    if (kNames[Index(d)] == name) return d;
  }
  return std::nullopt;
}

char VelocityLetter(Dof dof) { return kLetters[Index(dof)]; }

bool IsRotational(Dof dof) { return Index(dof) >= Index(Dof::kRoll); }

std::string_view PositionUnit(Dof dof) { return IsRotational(dof) ? "rad" : "m"; }
std::string_view VelocityUnit(Dof dof) { return IsRotational(dof) ? "rad/s" : "m/s"; }
std::string_view ForceUnit(Dof dof) { return IsRotational(dof) ? "N·m" : "N"; }
std::string_view InertiaUnit(Dof dof) { return IsRotational(dof) ? "kg·m²" : "kg"; }

}  // namespace uuvplan::model
