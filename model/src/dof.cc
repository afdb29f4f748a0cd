#include "uuvplan/model/dof.h"

#include <algorithm>

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

std::string DofList(const std::vector<Dof>& dofs) {
  std::string s;
  for (Dof d : dofs) s += (s.empty() ? "" : "+") + std::string(DofName(d));
  return s;
}

std::optional<std::vector<Dof>> ParseDofList(std::string_view joined) {
  std::vector<Dof> dofs;
  for (std::size_t from = 0;;) {
    const std::size_t plus = std::min(joined.find('+', from), joined.size());
    const std::optional<Dof> d = ParseDof(joined.substr(from, plus - from));
    if (!d || std::find(dofs.begin(), dofs.end(), *d) != dofs.end()) return std::nullopt;
    dofs.push_back(*d);
    if (plus == joined.size()) return dofs;
    from = plus + 1;
  }
}

char VelocityLetter(Dof dof) { return kLetters[Index(dof)]; }

bool IsRotational(Dof dof) { return Index(dof) >= Index(Dof::kRoll); }

std::string_view PositionUnit(Dof dof) { return IsRotational(dof) ? "rad" : "m"; }
std::string_view VelocityUnit(Dof dof) { return IsRotational(dof) ? "rad/s" : "m/s"; }
std::string_view ForceUnit(Dof dof) { return IsRotational(dof) ? "N·m" : "N"; }
std::string_view InertiaUnit(Dof dof) { return IsRotational(dof) ? "kg·m²" : "kg"; }

}  // namespace uuvplan::model
