#include "uuvplan/io/plausibility.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "uuvplan/model/util/text.h"

namespace uuvplan::io {

namespace {

std::function<void(const std::string&)>& Warn() {
  static std::function<void(const std::string&)> warn;
  return warn;
}

std::string Got(double x) { return model::Significant(x, 4); }

// A standard family's plausible ratio to the vehicle's scale: |value| / scale within
// [lower, upper]; the scale is the vehicle's inertia (M, or M·L² for a rotation) or its weight
// (M·g, or M·g·L for a rotation: torque = force × lever).
struct ParameterRange {
  std::string_view family;
  bool inertia;
  double lower, upper;
};
constexpr ParameterRange kParameterRanges[] = {{model::param::kMass, true, 1e-3, 50},
                                               {model::param::kLinearDrag, false, 0, 100},
                                               {model::param::kQuadraticDrag, false, 0, 100},
                                               {model::param::kBias, false, 0, 10},
                                               {model::param::kBiasStep, false, 0, 10}};

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
      hint =
          ": is it in " + std::string(unit) + "? " + Got(x / per_metre) + " m would be plausible";
      break;
    }
  }
  Implausible(where, "expected " + quantity.Expected() + ", got " + Got(x) + hint);
}

std::string InputQuantity::Expected() const {
  return std::string(what) + " in [" + model::ShortestNumber(lower) + ", " +
         model::ShortestNumber(upper) + "]" + (unit == "1" ? "" : " " + std::string(unit));
}

void CheckPlausibleParameter(const Place& where, double x, const model::ParameterFamily& family,
                             model::Dof dof, const model::Vehicle& vehicle) {
  const ParameterRange* range = nullptr;
  for (const ParameterRange& r : kParameterRanges) {
    if (r.family == family.name) range = &r;
  }
  if (!range) return;
  const double size = std::max({vehicle.size[0], vehicle.size[1], vehicle.size[2]});
  const double lever = model::IsRotational(dof) ? size : 1.0;  // m
  const double scale =
      range->inertia ? vehicle.mass * lever * lever : vehicle.mass * plausible::kGravity * lever;
  if (!(scale > 0)) return;
  const double lo = range->lower * scale;
  const double hi = range->upper * scale;
  const double magnitude = std::abs(x);
  if (magnitude >= lo && magnitude <= hi) return;
  const std::string unit(family.Unit(dof));
  Implausible(where, "expected |" + std::string(family.name) + "| in [" +
                         model::Significant(lo, 3) + ", " + model::Significant(hi, 3) + "] " +
                         unit + " for a " + Got(vehicle.mass) + " kg vehicle, got " + Got(x) + " " +
                         unit);
}

void CheckPlausibleThruster(const Place& where, const model::Thruster& thruster, double mass) {
  const double weight = plausible::kGravity * mass;
  const double largest =
      std::max(std::abs(thruster.MaxForwardThrust()), std::abs(thruster.MaxReverseThrust()));
  if (!plausible::kThrustToWeight.Holds(largest / weight)) {
    Implausible(where, "expected " + plausible::kThrustToWeight.Expected() + ", got " +
                           model::Significant(largest, 3) + " N for a " +
                           model::Significant(weight, 3) + " N vehicle");
  }
}

}  // namespace uuvplan::io
