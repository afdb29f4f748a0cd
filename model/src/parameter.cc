#include "uuvplan/model/parameter.h"

#include <algorithm>

#include "uuvplan/model/effects.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::model {

bool ParameterFamily::Matches(std::string_view parameter) const {
  return qualified() ? StartsWith(parameter, name) && parameter.size() > name.size()
                     : parameter == name;
}

std::string ParameterFamily::Expected() const {
  if (!expected.empty()) return std::string(expected);
  const bool no_upper = upper == std::numeric_limits<double>::infinity();
  if (lower == -std::numeric_limits<double>::infinity() && no_upper) return "a number";
  if (lower == 0.0 && no_upper) return lower_open ? "a positive number" : "a number >= 0";
  const std::string lo = (lower_open ? "(" : "[") + ShortestNumber(lower);
  return "a number in " + lo + ", " + ShortestNumber(upper) + "]";
}

std::string ParameterFamily::PhysicalExpected() const {
  if (!(physical_upper < upper)) return Expected();
  return std::string("a number in ") + (lower_open ? "(" : "[") + ShortestNumber(lower) + ", " +
         ShortestNumber(physical_upper) + "]";
}

std::string InputQuantity::Expected() const {
  return std::string(what) + " in [" + ShortestNumber(lower) + ", " + ShortestNumber(upper) +
         "]" + (unit == "1" ? "" : " " + std::string(unit));
}

double PlausibleScale(const ParameterFamily& family, Dof dof, const Vehicle& vehicle) {
  using plausible::kGravity;
  const double size = std::max({vehicle.size[0], vehicle.size[1], vehicle.size[2]});
  const double lever = IsRotational(dof) ? size : 1.0;  // m: torque = force × lever
  using Scale = ParameterFamily::Scale;
  switch (family.plausible_scale) {
    case Scale::kInertia:
      return vehicle.mass * lever * lever;
    case Scale::kForcePerSpeed:   // the force at 1 m/s (1 rad/s)
    case Scale::kForcePerSpeed2:  // at (1 m/s)² ((1 rad/s)²)
    case Scale::kForce:
      return vehicle.mass * kGravity * lever;
    case Scale::kNone:
      break;
  }
  return 0.0;
}

const std::vector<ParameterFamily>& StandardFamilies() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  static const std::vector<ParameterFamily> families = [] {
    std::vector<ParameterFamily> f = {
        {param::kMass, "inertia including added mass", "kg", "kg·m²", 0.0, 0.0, kInf},
        {param::kLinearDrag, "linear drag", "N·s/m", "N·m·s/rad", 0.0, 0.0, kInf},
        {param::kQuadraticDrag, "quadratic drag", "N·s²/m²", "N·m·s²/rad²", 0.0, 0.0, kInf},
        {param::kBias, "constant force (weight − buoyancy, tether)", "N", "N·m", 0.0, -kInf,
         kInf},
        {param::kBiasStep, "force of one ballast step (seed 000 eq. 20)", "N", "N·m", 0.0, -kInf,
         kInf},
    };
    f[0].lower_open = true;  // m > 0: no inertia is not a body
    f[0].fit_lower = 0.0;    // the DOF model divides by it
    f[0].fit_lower_open = true;
    f[0].above_dry_mass = true;  // added mass is positive for a body in water
    // Plausible (issue #15), relative to the vehicle: m from 1e-3 of its mass (or M·L²) to 50×
    // (added mass is at most a few times the body's); drag forces at 1 m/s and constant forces
    // up to 100 and 10 weights.
    using Scale = ParameterFamily::Scale;
    f[0].plausible_scale = Scale::kInertia;
    f[0].plausible_ratio_lower = 1e-3;
    f[0].plausible_ratio_upper = 50;
    f[1].plausible_scale = Scale::kForcePerSpeed;
    f[1].plausible_ratio_upper = 100;
    f[2].plausible_scale = Scale::kForcePerSpeed2;
    f[2].plausible_ratio_upper = 100;
    f[3].plausible_scale = Scale::kForce;
    f[3].plausible_ratio_upper = 10;
    f[4].plausible_scale = Scale::kForce;
    f[4].plausible_ratio_upper = 10;
    return f;
  }();
  return families;
}

const ParameterFamily* FamilyOf(std::string_view parameter) {
  for (const ParameterFamily& f : StandardFamilies()) {
    if (f.Matches(parameter)) return &f;
  }
  for (const EffectEntry& e : Effects().entries()) {
    for (const ParameterFamily& f : e.parameters) {
      if (f.Matches(parameter)) return &f;
    }
  }
  return nullptr;
}

const ParameterFamily* FamilyNamed(std::string_view name) {
  for (const ParameterFamily& f : StandardFamilies()) {
    if (f.name == name) return &f;
  }
  for (const EffectEntry& e : Effects().entries()) {
    for (const ParameterFamily& f : e.parameters) {
      if (f.name == name) return &f;
    }
  }
  return nullptr;
}

std::string Unit(std::string_view parameter, Dof dof) {
  const ParameterFamily* f = FamilyOf(parameter);
  return f ? std::string(f->Unit(dof)) : "?";
}

double NullValue(std::string_view parameter) {
  const ParameterFamily* f = FamilyOf(parameter);
  return f ? f->null_value : 0.0;
}

std::string_view Qualifier(std::string_view parameter) {
  const ParameterFamily* f = FamilyOf(parameter);
  return f && f->qualified() ? parameter.substr(f->name.size()) : std::string_view();
}

}  // namespace uuvplan::model
