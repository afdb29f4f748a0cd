// The vehicle file (contract §Vehicle, docs/formats.md): thrusters, mappings, a priori
// knowledge and sensors. A truth file is a vehicle file with more keys (truth_yaml.cc).
#include "uuvplan/io/vehicle_yaml.h"

#include <algorithm>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "derived_mapping_keys.h"
#include "speed_limit_keys.h"
#include "thruster_installation_yaml.h"
#include "uuvplan/io/plausibility.h"
#include "uuvplan/model/util/text.h"
#include "vehicle_keys.h"

namespace uuvplan::io {

using namespace model;  // NOLINT: the vocabulary of the vehicle file

// Added-mass bounds are fractions of the rigid-body value: 0 <= lo <= hi.
std::array<double, 2> AddedMassBounds(const Value& v) {
  const std::string expectation = "[lo, hi] with 0 <= lo <= hi (fractions of the rigid-body value)";
  const auto b = Pair(v, expectation);
  if (!(b[0] >= 0 && b[0] <= b[1])) v.Expected(expectation);
  return b;
}

namespace {

ThrustModel ParseThrust(const Value& v) {
  const MapValue m(v, "a map {model: square, c_pos, c_neg} or {model: poly2, a, b}");
  ThrustModel model;
  const Value kind = m.Required("model");
  if (Choice(kind, {"square", "poly2"}, "a thrust model") == 0) {
    // ref 000 eq. 6: tau = c·V|V|, c by sign of V.
    m.AllowOnly({"model", "c_pos", "c_neg", "deduction", "dead_band"});
    model.kind = ThrustModel::Kind::kSquare;
    model.c_pos = Positive(m.Required("c_pos"));
    model.c_neg = Positive(m.Required("c_neg"));
  } else {
    // ref 002 eq. 1: tau = a·V² + b·V for V >= 0, which must grow to give thrust at all.
    m.AllowOnly({"model", "a", "b", "deduction", "dead_band"});
    model.kind = ThrustModel::Kind::kPoly2;
    model.a = NonNegative(m.Required("a"));
    model.b = AnyNumber(m.Required("b"));
    if (!(model.a > 0 || model.b > 0)) {
      v.Fail("poly2 thrust must grow with the command: expected a > 0 or b > 0");
    }
  }
  if (const Value d = m.Optional("deduction"); !d.absent()) {
    model.deduction =
        NumberIf(d, "a thrust deduction in [0, 1)", [](double t) { return t >= 0 && t < 1; });
  }
  return model;
}

// neutral: the command at which the thruster stops, within its range (0 when not given, which
// the range must then hold: a PWM range [1100, 1900] read as distances from 0 would make every
// command a full one).
double ParseNeutral(const MapValue& m, const Value& command, const Thruster& t) {
  const std::string range = "[" + model::Significant(t.command_min, 6) + ", " +
                            model::Significant(t.command_max, 6) + "]";
  const Value neutral = m.Optional("neutral");
  if (neutral.absent()) {
    if (t.command_min <= 0 && 0 <= t.command_max) return 0.0;
    command.Fail("the command range " + range +
                 " does not hold 0: give the command at which the thruster stops as "
                 "`neutral:` (1500 for a PWM ESC driven from 1100 to 1900 µs)");
  }
  return NumberIf(neutral, "the command at which the thruster stops, within its range " + range,
                  [&t](double x) { return x >= t.command_min && x <= t.command_max; });
}

Thruster ParseThruster(const Value& v, const std::vector<Thruster>& previous, double mass,
                       const std::array<double, 3>& size) {
  const MapValue m(v, "a thruster {name, thrust, command}");
  std::vector<std::string_view> keys = {"name", "thrust", "command", "neutral"};
  keys.insert(keys.end(), kThrusterInstallationKeys.begin(), kThrusterInstallationKeys.end());
  m.AllowOnly(keys);
  Thruster t;
  const Value name = m.Required("name");
  t.name = Name(name, "a thruster name");
  for (const Thruster& p : previous) {
    if (p.name == t.name) name.Fail("thruster '" + t.name + "' is defined twice");
  }
  t.model = ParseThrust(m.Required("thrust"));
  const Value command = m.Required("command");
  const std::string expectation = "a command range [lo, hi] with lo < hi";
  const auto range = Pair(command, expectation);
  if (!(range[0] < range[1])) command.Expected(expectation);
  t.command_min = range[0];
  t.command_max = range[1];
  t.neutral = ParseNeutral(m, command, t);
  ParseThrusterInstallation(m, size, &t);
  CheckPlausibleThruster(v, t, mass);
  return t;
}

std::vector<Thruster> ParseThrusters(const Value& v, double mass,
                                     const std::array<double, 3>& size) {
  const std::string expectation = "a list of at least one thruster {name, thrust, command}";
  std::vector<Thruster> thrusters;
  for (const Value& item : List(v, expectation)) {
    thrusters.push_back(ParseThruster(item, thrusters, mass, size));
  }
  if (thrusters.empty()) v.Expected(expectation);
  return thrusters;
}

std::vector<std::string> ThrusterNames(const std::vector<Thruster>& thrusters) {
  std::vector<std::string> names;
  for (const Thruster& t : thrusters) names.push_back(t.name);
  return names;
}

// shares: {thruster: share}, tau_i = share_i·phi (ref 000 Table I).
std::vector<std::pair<int, double>> ParseShares(const Value& v,
                                                const std::vector<Thruster>& thrusters) {
  const MapValue m(v, "a map {thruster: share}");
  std::vector<std::pair<int, double>> shares;
  for (const MapValue::Entry& e : m.entries()) {
    int index = -1;
    for (std::size_t i = 0; i < thrusters.size(); ++i) {
      if (thrusters[i].name == e.key) index = static_cast<int>(i);
    }
    if (index < 0) {
      e.key_value.Fail("unknown thruster '" + e.key +
                       "' (thrusters: " + Join(ThrusterNames(thrusters)) + ")");
    }
    shares.emplace_back(index,
                        NumberIf(e.value, "a non-zero share (thruster force per unit DOF force)",
                                 [](double s) { return s != 0; }));
  }
  if (shares.empty()) v.Expected("at least one thruster share");
  return shares;
}

ThrustMapping ParseMapping(const std::string& name, const Value& v,
                           const std::vector<Thruster>& thrusters) {
  const MapValue m(v, "a mapping {dof, shares, open_water}");
  m.AllowOnly({"dof", "shares", "open_water"});
  ThrustMapping mapping;
  mapping.name = name;
  mapping.dof = DofValue(m.Required("dof"));
  mapping.shares = ParseShares(m.Required("shares"), thrusters);
  if (const Value ow = m.Optional("open_water"); !ow.absent()) {
    mapping.open_water =
        EnumValue(ow, model::kOpenWaterNames, "the direction of open-water thrust");
  }
  return mapping;
}

std::vector<ThrustMapping> ParseMappings(const Value& v, const std::vector<Thruster>& thrusters) {
  const MapValue m(v, "a map of mappings {<name>: {dof, shares, open_water}}");
  std::vector<ThrustMapping> mappings;
  for (const MapValue::Entry& e : m.entries()) {
    mappings.push_back(ParseMapping(e.key, e.value, thrusters));
  }
  if (mappings.empty()) v.Expected("at least one mapping");
  return mappings;
}

std::map<Dof, double> ParseInertia(const Value& v, double mass_size2) {
  const MapValue m(v, "a map {<rotational DOF>: kg·m²}");
  std::map<Dof, double> inertia;
  for (const MapValue::Entry& e : m.entries()) {
    const Dof dof = DofKey(e);
    if (!IsRotational(dof)) {
      e.key_value.Fail("inertia is given for rotational DOFs only (roll, pitch, yaw), got '" +
                       e.key + "' (the inertia of a translation is the mass)");
    }
    inertia[dof] = Positive(e.value);
    CheckPlausible(e.value, inertia[dof] / mass_size2, plausible::kInertiaRatio);
  }
  return inertia;
}

// A priori drag, plausible for the vehicle as a truth's k and kq (parameter.h).
DragPrior ParseDrag(const Value& v, Dof dof, const Vehicle& vehicle) {
  const MapValue m(v, "a drag prior {k, kq, rel_sigma}");
  m.AllowOnly({"k", "kq", "rel_sigma"});
  DragPrior drag;
  const auto coefficient = [&](const char* name) {
    const Value x = m.Required(name);
    const double value = NonNegative(x);
    CheckPlausibleParameter(x, value, *FamilyNamed(name), dof, vehicle);
    return value;
  };
  drag.k = coefficient(param::kLinearDrag);
  drag.kq = coefficient(param::kQuadraticDrag);
  if (const Value s = m.Optional("rel_sigma"); !s.absent()) drag.rel_sigma = Positive(s);
  return drag;
}

// dofs.<dof> of a vehicle: a priori drag and added mass. A truth file, or a vehicle file with
// an identified model (`diagnose --write-vehicle`), adds params, effects and sigma (read by
// ParseTruthDof).
DofPrior ParsePrior(const Value& v, Dof dof, const Vehicle& vehicle) {
  const MapValue m(v, "a map {drag, added_mass, params, effects, sigma, origin}");
  m.AllowOnly({"drag", "added_mass", "params", "effects", "sigma", "origin"});
  DofPrior prior;
  if (const Value d = m.Optional("drag"); !d.absent()) prior.drag = ParseDrag(d, dof, vehicle);
  if (const Value a = m.Optional("added_mass"); !a.absent()) prior.added_mass = AddedMassBounds(a);
  return prior;
}

// `size`: the scale of the sensor's σ (the vehicle's largest dimension, 1 rad for an angle).
SensorSpec ParseSensorSpec(const Value& v, double size) {
  const MapValue m(v, "a sensor {rate, sigma}");
  m.AllowOnly({"rate", "sigma"});
  SensorSpec spec;
  const Value rate = m.Required("rate"), sigma = m.Required("sigma");
  spec.rate_hz = Positive(rate);
  spec.sigma = Positive(sigma);
  CheckPlausible(rate, spec.rate_hz, plausible::kSensorRate);
  CheckPlausible(sigma, spec.sigma / size, plausible::kSensorSigmaRatio);
  return spec;
}

DofSensors ParseDofSensors(const Value& v, double size) {
  const MapValue m(v, "a map {position: {rate, sigma}, velocity: {rate, sigma}}");
  m.AllowOnly({"position", "velocity"});
  DofSensors sensors;
  if (const Value p = m.Optional("position"); !p.absent())
    sensors.position = ParseSensorSpec(p, size);
  if (const Value s = m.Optional("velocity"); !s.absent())
    sensors.velocity = ParseSensorSpec(s, size);
  if (!sensors.position && !sensors.velocity) v.Expected("a position and/or a velocity sensor");
  return sensors;
}

}  // namespace

// The vehicle keys of `root`; a truth file may also have virtual_pool (read by ReadTruth).
Vehicle ParseVehicle(const MapValue& root, bool truth) {
  if (root.Has("base")) return ParsePayloadVehicle(root, truth);
  if (truth) {
    root.AllowOnly({"name", "mass", "size", "inertia", "added_mass", "thrusters", "min_thrust",
                    "mappings", "jet_clearance", "restoring", "max_translation_speed",
                    "max_rotation_rate", "dofs", "sensors", "virtual_pool"});
  } else {
    root.AllowOnly({"name", "mass", "size", "inertia", "added_mass", "thrusters", "min_thrust",
                    "mappings", "jet_clearance", "restoring", "max_translation_speed",
                    "max_rotation_rate", "dofs", "sensors"});
  }
  Vehicle vehicle;
  vehicle.name = Name(root.Required("name"), "a vehicle name");
  const Value mass = root.Required("mass");
  vehicle.mass = Positive(mass);
  CheckPlausible(mass, vehicle.mass, plausible::kVehicleMass);
  const Value size = root.Required("size");
  const std::vector<Value> sides = List(size, "[length, width, height] in m");
  if (sides.size() != 3) size.Expected("[length, width, height] in m");
  for (int i = 0; i < 3; ++i) {
    vehicle.size[i] = Positive(sides[i]);
    CheckPlausible(sides[i], vehicle.size[i], plausible::kVehicleSize);
  }
  const double largest = *std::max_element(vehicle.size.begin(), vehicle.size.end());
  if (const Value v = root.Optional("inertia"); !v.absent()) {
    vehicle.inertia = ParseInertia(v, vehicle.mass * largest * largest);
  }
  if (const Value v = root.Optional("added_mass"); !v.absent()) {
    vehicle.added_mass = AddedMassBounds(v);
  }
  vehicle.thrusters = ParseThrusters(root.Required("thrusters"), vehicle.mass, vehicle.size);
  if (const Value v = root.Optional("min_thrust"); !v.absent()) vehicle.min_thrust = NonNegative(v);
  vehicle.speed_limits = ParseSpeedLimits(root);
  if (const Value v = root.Optional("mappings"); !v.absent()) {
    vehicle.mappings = ParseMappings(v, vehicle.thrusters);
  }
  vehicle.mapping_derivation = ParseMappingDerivation(root);
  AddDerivedMappings(root, &vehicle);
  if (const Value v = root.Optional("dofs"); !v.absent()) {
    const MapValue priors(v, "a map {<dof>: {drag, added_mass}}");
    for (const MapValue::Entry& e : priors.entries()) {
      vehicle.priors[DofKey(e)] = ParsePrior(e.value, DofKey(e), vehicle);
    }
  }
  if (const Value v = root.Optional("sensors"); !v.absent()) ParseSensors(v, &vehicle);
  return vehicle;
}

void ParseSensors(const Value& v, Vehicle* vehicle) {
  const double largest = *std::max_element(vehicle->size.begin(), vehicle->size.end());
  const MapValue sensors(v, "a map {<dof>: {position, velocity}}");
  for (const MapValue::Entry& e : sensors.entries()) {
    const Dof dof = DofKey(e);
    vehicle->sensors[dof] = ParseDofSensors(e.value, IsRotational(dof) ? 1.0 : largest);
  }
}

Vehicle ReadVehicle(const std::string& path) {
  return Guarded(path, [&] {
    const MapValue root = LoadYamlMap(
        path, "a vehicle (name, mass, size, thrusters, mappings, ...)", "a map of vehicle keys");
    Vehicle vehicle = ParseVehicle(root, false);
    // A model written into the vehicle file (dofs.<dof>.params, effects, sigma).
    if (const Value v = root.Optional("dofs"); !v.absent()) {
      const MapValue dofs(v, "a map of DOFs");
      for (const MapValue::Entry& e : dofs.entries()) {
        if (auto model = ParseTruthDof(e.value, DofKey(e), vehicle)) {
          vehicle.models[DofKey(e)] = std::move(*model);
        }
      }
    }
    return vehicle;
  });
}

}  // namespace uuvplan::io
