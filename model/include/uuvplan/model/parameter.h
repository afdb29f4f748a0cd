// The parameter vocabulary: every parameter of a DOF model is named by a family, plain ("m",
// "lag") or qualified ("eta.<mapping>.<pos|neg>", "coupling.<ab>"). A family declares its
// unit, its null value (the value that means "no effect") and its admissible range. The
// standard model's families are listed here (contract §Conventions, ref 000 eq. 3 and
// eq. 20); each effect declares its own in the effect table (effects.h). Identification,
// planning and diagnosis ask this vocabulary, never a hand-written list of names.
#pragma once

#include <cmath>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "uuvplan/model/dof.h"

namespace uuvplan::model {

struct ParameterFamily {
  /// Plain name ("kq"), or the prefix of a qualified family ending in '.' ("eta.").
  std::string_view name{};
  std::string_view meaning{};
  /// Unit for a translational / rotational DOF (N, N·m, ...); "1" for a pure number.
  std::string_view unit_linear{};
  std::string_view unit_rotational{};
  double null_value = 0.0;                                  ///< "no effect" (eta: 1)
  double lower = -std::numeric_limits<double>::infinity();  ///< admissible range
  double upper = std::numeric_limits<double>::infinity();
  /// Value before any fit where the null value cannot serve (a lag of 0 s has no 1/T);
  /// NaN: the null value.
  double a_priori = std::numeric_limits<double>::quiet_NaN();
  bool lower_open = false;  ///< the lower bound itself is not admissible (a lag of 0 s)
  /// What a file must hold for it ("a positive number"); empty: said from the bounds.
  std::string_view expected{};
  /// Truth file: the key of a qualified family's map ("eta: {<mapping>.<dir>: v}"); a plain
  /// family's key is its name. Empty for a qualified family: not in truth files.
  std::string_view file_key{};
  /// Qualified family: "" when `qualifier` is valid on `dof` of `vehicle`, else what was
  /// expected (for the message).
  std::string (*check_qualifier)(std::string_view qualifier, Dof dof,
                                 const struct Vehicle& vehicle) = nullptr;
  /// A qualified family whose unit depends on the qualifier (coupling.<ab>: c_ab·a·b is a force,
  /// so c_ab's unit is the force's over a's and b's): the unit of the parameter so qualified on
  /// `dof`; null: unit_linear / unit_rotational.
  std::string (*unit_of)(std::string_view qualifier, Dof dof) = nullptr;
  /// A value not given in a truth file defaults to this parameter's (k_neg: k); empty: required.
  std::string_view defaults_to{};
  /// Where a fit may go: the model is undefined (or unidentifiable) below this; NaN: anywhere.
  double fit_lower = std::numeric_limits<double>::quiet_NaN();
  bool fit_lower_open = false;
  /// Physically admissible identified values (drag >= 0, 0 < η <= 1.2, m above the
  /// dry mass), where narrower than the file range [lower, upper]: the largest value a vehicle
  /// can have (NaN: `upper`), and whether a translational value must exceed the vehicle's dry
  /// mass (a rotational inertia in a vehicle file is computed, not weighed: no bound). An
  /// estimate outside is non-physical: a fit the loop must not converge on.
  double physical_upper = std::numeric_limits<double>::quiet_NaN();
  bool above_dry_mass = false;

  /// `value` is finite and within the fit's range.
  bool Fittable(double value) const {
    if (!std::isfinite(value)) return false;
    if (fit_lower != fit_lower) return true;
    return fit_lower_open ? value > fit_lower : value >= fit_lower;
  }

  double APriori() const { return a_priori == a_priori ? a_priori : null_value; }
  bool qualified() const { return !name.empty() && name.back() == '.'; }
  /// True when `parameter` belongs to this family.
  bool Matches(std::string_view parameter) const;
  std::string_view Unit(Dof dof) const { return IsRotational(dof) ? unit_rotational : unit_linear; }
  bool Admissible(double value) const {
    return (lower_open ? value > lower : value >= lower) && value <= upper;
  }
  /// Admissible and within the physical range (the vehicle's rigid inertia is checked by the
  /// caller: planner::NonPhysical).
  bool Physical(double value) const { return Admissible(value) && !(value > physical_upper); }
  /// The physical range in words: "a number >= 0", "a number in (0, 1.2]".
  std::string PhysicalExpected() const;
  /// `expected`, or the admissible range in words: "a positive number", "a number >= 0".
  std::string Expected() const;
};

namespace param {
// The standard model (contract §Conventions): m·dξ/dt = −k·ξ − kq·ξ|ξ| + η·φⁿ + bias
// (+ bias_step per ballast step, ref 000 eq. 20).
inline constexpr const char* kMass = "m";
inline constexpr const char* kLinearDrag = "k";
inline constexpr const char* kQuadraticDrag = "kq";
inline constexpr const char* kBias = "bias";
inline constexpr const char* kBiasStep = "bias_step";
inline constexpr const char* kEtaPrefix = "eta.";
// Parameters of the built-in effects (effect_table.cc declares their units and ranges).
inline constexpr const char* kLinearDragNeg = "k_neg";
inline constexpr const char* kQuadraticDragNeg = "kq_neg";
inline constexpr const char* kLag = "lag";
inline constexpr const char* kDeadzone = "deadzone";
inline constexpr const char* kAdvanceLoss = "advance_loss";
inline constexpr const char* kCouplingPrefix = "coupling.";
inline constexpr const char* kSensorDelay = "sensor_delay";
inline constexpr const char* kDrift = "drift";
inline constexpr const char* kThrustExponent = "thrust_exponent";
/// Structure setting: the commanded force at which a thrust map of the wrong shape is right.
inline constexpr const char* kThrustReference = "thrust_reference";
}  // namespace param

/// The standard model's families: m, k, kq, bias, bias_step.
const std::vector<ParameterFamily>& StandardFamilies();

/// The family of a parameter name, among the standard ones and every registered effect's;
/// nullptr for a name outside the vocabulary.
const ParameterFamily* FamilyOf(std::string_view parameter);

/// The family called `name` ("kq", "eta."), or nullptr.
const ParameterFamily* FamilyNamed(std::string_view name);

/// The parameter's unit on `dof` ("?" outside the vocabulary).
std::string Unit(std::string_view parameter, Dof dof);

/// Its null value: 1 for an installation coefficient, 0 for every other effect parameter.
double NullValue(std::string_view parameter);

/// The qualifier of a qualified name: "surge-front.neg" for "eta.surge-front.neg".
std::string_view Qualifier(std::string_view parameter);

}  // namespace uuvplan::model
