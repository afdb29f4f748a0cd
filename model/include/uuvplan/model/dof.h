// Degrees of freedom of a marine vehicle, named and signed as in Fossen/SNAME:
// x forward (surge), y starboard (sway), z down (heave), roll/pitch/yaw about x/y/z.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace uuvplan::model {

enum class Dof { kSurge = 0, kSway, kHeave, kRoll, kPitch, kYaw };

inline constexpr int kNumDofs = 6;
inline constexpr std::array<Dof, kNumDofs> kAllDofs = {Dof::kSurge, Dof::kSway,  Dof::kHeave,
                                                       Dof::kRoll,  Dof::kPitch, Dof::kYaw};

/// "surge", "sway", "heave", "roll", "pitch", "yaw".
std::string_view DofName(Dof dof);
/// Inverse of DofName; nullopt for anything else.
std::optional<Dof> ParseDof(std::string_view name);
/// The DOFs of a combined trial's mode, named and joined by '+' ("surge+sway+yaw").
std::string DofList(const std::vector<Dof>& dofs);
/// Inverse of DofList; nullopt when a part is not a DOF name or names one twice.
std::optional<std::vector<Dof>> ParseDofList(std::string_view joined);
/// The SNAME velocity letter of the DOF: u v w p q r.
char VelocityLetter(Dof dof);
/// roll, pitch, yaw: positions are angles (rad), forces are torques (N·m).
bool IsRotational(Dof dof);
/// Unit strings for reports: "m" / "rad", "m/s" / "rad/s", "N" / "N·m", "kg" / "kg·m²".
std::string_view PositionUnit(Dof dof);
std::string_view VelocityUnit(Dof dof);
std::string_view ForceUnit(Dof dof);
std::string_view InertiaUnit(Dof dof);

inline int Index(Dof dof) { return static_cast<int>(dof); }

}  // namespace uuvplan::model
