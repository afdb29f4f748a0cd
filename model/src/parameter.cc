#include "uuvplan/model/parameter.h"

#include <algorithm>

#include "uuvplan/model/effects.h"
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

const std::vector<ParameterFamily>& StandardFamilies() {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  static const std::vector<ParameterFamily> families = [] {
    std::vector<ParameterFamily> f = {
        {param::kMass, "inertia including added mass", "kg", "kg·m²", 0.0, 0.0, kInf},
        {param::kLinearDrag, "linear drag", "N·s/m", "N·m·s/rad", 0.0, 0.0, kInf},
        {param::kQuadraticDrag, "quadratic drag", "N·s²/m²", "N·m·s²/rad²", 0.0, 0.0, kInf},
        {param::kBias, "constant force (weight − buoyancy, tether)", "N", "N·m", 0.0, -kInf, kInf},
        {param::kBiasStep, "force of one ballast step (seed 000 eq. 20)", "N", "N·m", 0.0, -kInf,
         kInf},
    };
    f[0].lower_open = true;  // m > 0: no inertia is not a body
    f[0].fit_lower = 0.0;    // the DOF model divides by it
    f[0].fit_lower_open = true;
    f[0].above_dry_mass = true;  // added mass is positive for a body in water
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
  if (f == nullptr) return "?";
  return f->unit_of ? f->unit_of(Qualifier(parameter), dof) : std::string(f->Unit(dof));
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
