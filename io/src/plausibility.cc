#include "uuvplan/io/plausibility.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "uuvplan/model/util/text.h"

namespace uuvplan::io {

using model::InputQuantity;

namespace {

std::function<void(const std::string&)>& Warn() {
  static std::function<void(const std::string&)> warn;
  return warn;
}

std::string Got(double x) { return model::Significant(x, 4); }

}  // namespace

void AcceptImplausible(std::function<void(const std::string& warning)> warn) {
  Warn() = std::move(warn);
}

void Implausible(const Place& where, const std::string& what) {
  if (Warn()) {
    const std::string key = where.key_path().empty() ? "" : where.key_path() + ": ";
    Warn()(where.Where() + ": " + key + "implausible: " + what +
           " (accepted by --accept-implausible)");
    return;
  }
  where.Fail("implausible: " + what + " (if it is right, pass --accept-implausible)");
}

void CheckPlausible(const Place& where, double x, const InputQuantity& quantity) {
  if (!quantity.Holds(x)) Implausible(where, "expected " + quantity.Expected() + ", got " + Got(x));
}

void CheckPlausibleLength(const Place& where, double x, const InputQuantity& quantity) {
  if (quantity.Holds(x)) return;
  std::string hint;
  for (const auto& [unit, per_metre] : {std::pair{"cm", 100.0}, std::pair{"mm", 1000.0}}) {
    if (x > quantity.upper && quantity.Holds(x / per_metre)) {
      hint = ": is it in " + std::string(unit) + "? " + Got(x / per_metre) + " m would be plausible";
      break;
    }
  }
  Implausible(where, "expected " + quantity.Expected() + ", got " + Got(x) + hint);
}

void CheckPlausibleParameter(const Place& where, double x, const model::ParameterFamily& family,
                             model::Dof dof, const model::Vehicle& vehicle) {
  const double scale = model::PlausibleScale(family, dof, vehicle);
  if (!(scale > 0)) return;
  const double lo = family.plausible_ratio_lower * scale;
  const double hi = family.plausible_ratio_upper * scale;
  const double magnitude = std::abs(x);
  if (magnitude >= lo && magnitude <= hi) return;
  const std::string unit(family.Unit(dof));
  Implausible(where, "expected |" + std::string(family.name) + "| in [" + model::Significant(lo, 3) +
                         ", " + model::Significant(hi, 3) + "] " + unit + " for a " +
                         Got(vehicle.mass) + " kg vehicle, got " + Got(x) + " " + unit);
}

void CheckPlausibleThruster(const Place& where, const model::Thruster& thruster, double mass) {
  const double weight = model::plausible::kGravity * mass;
  const double largest =
      std::max(std::abs(thruster.MaxForwardThrust()), std::abs(thruster.MaxReverseThrust()));
  if (!model::plausible::kThrustToWeight.Holds(largest / weight)) {
    Implausible(where, "expected " + model::plausible::kThrustToWeight.Expected() + ", got " +
                           model::Significant(largest, 3) + " N for a " +
                           model::Significant(weight, 3) + " N vehicle");
  }
}

}  // namespace uuvplan::io
