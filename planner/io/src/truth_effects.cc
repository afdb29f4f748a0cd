// The effect settings of a truth file (dofs.<dof>.effects: {<effect>: {...}}, docs/formats.md):
// each effect's keys read into the true parameters of the DOF.
#include "truth_effects.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "uuvplan/model/effects.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::io {

using namespace model;  // NOLINT: the vocabulary of the truth file

void SetParam(DofTruth* truth, const std::string& name, double value, const Value& where) {
  if (!truth->params.emplace(name, value).second) {
    where.Fail("parameter '" + name + "' is given twice");
  }
}

// eta: {<mapping>.<pos|neg>: v}, the installation coefficient of a mapping of this DOF for
// one direction of phi (seed 000 eq. 3); 0 < eta <= 2.
void ParseEta(const Value& v, Dof dof, const Vehicle& vehicle, DofTruth* truth) {
  const MapValue m(v, "a map {<mapping>.pos: eta, <mapping>.neg: eta}");
  std::vector<std::string> mappings;
  for (int i : vehicle.MappingsOf(dof)) mappings.push_back(vehicle.mappings[i].name);
  for (const MapValue::Entry& e : m.entries()) {
    const std::size_t dot = e.key.rfind('.');
    const std::string mapping = e.key.substr(0, dot == std::string::npos ? 0 : dot);
    const std::string direction = dot == std::string::npos ? "" : e.key.substr(dot + 1);
    const int index = vehicle.MappingIndex(mapping);
    if (index < 0 || vehicle.mappings[index].dof != dof ||
        (direction != "pos" && direction != "neg")) {
      e.key_value.Expected("'<mapping>.pos' or '<mapping>.neg' with a " +
                           std::string(DofName(dof)) + " mapping of the vehicle (" +
                           Join(mappings) + ")");
    }
    const double eta = NumberIf(e.value, "an installation coefficient in (0, 2]",
                                [](double x) { return x > 0 && x <= 2; });
    SetParam(truth, EtaName(mapping, direction == "pos" ? Direction::kPos : Direction::kNeg), eta,
             e.value);
  }
}

// An effect whose settings are one parameter: {<name>: value}.
void ParseSingle(const MapValue& m, const char* name, double (*read)(const Value&),
                 DofTruth* truth) {
  m.AllowOnly({name});
  const Value v = m.Required(name);
  SetParam(truth, name, read(v), v);
}

// thrust_map: {thrust_exponent: p > -1, reference: u_ref > 0}, u = u0·(|u0|/u_ref)^p.
void ParseThrustMap(const MapValue& m, DofTruth* truth) {
  m.AllowOnly({param::kThrustExponent, "reference"});
  const Value p = m.Required(param::kThrustExponent);
  SetParam(truth, param::kThrustExponent,
           NumberIf(p, "a number > -1 (the delivered force must grow with the command)",
                    [](double x) { return x > -1; }),
           p);
  truth->thrust_reference = Positive(m.Required("reference"));
}

// asymmetric_drag: {k_neg, kq_neg}, drag for xi < 0; a value not given is the same as for
// xi >= 0 (params k, kq).
void ParseAsymmetricDrag(const MapValue& m, DofTruth* truth) {
  m.AllowOnly({param::kLinearDragNeg, param::kQuadraticDragNeg});
  if (m.entries().empty()) m.self().Expected("k_neg and/or kq_neg");
  const std::pair<const char*, const char*> pairs[] = {
      {param::kLinearDragNeg, param::kLinearDrag},
      {param::kQuadraticDragNeg, param::kQuadraticDrag}};
  for (const auto& [negative, positive] : pairs) {
    const Value v = m.Optional(negative);
    SetParam(truth, negative, v.absent() ? truth->params.at(positive) : NonNegative(v), m.self());
  }
}

bool IsVelocityLetter(char c) {
  return std::string_view("uvwpqr").find(c) != std::string_view::npos;
}

// coupling: {coefficients: {<ab>: c}, motion: {<dof>: {offset, amplitude, omega}}}: the force
// c_ab·a·b (effects.h) and the other DOFs' velocities that drive it in the virtual pool.
void ParseCoupling(const MapValue& m, Dof dof, DofTruth* truth) {
  m.AllowOnly({"coefficients", "motion"});
  const Value coefficients = m.Required("coefficients");
  const MapValue c(coefficients,
                   "a map {<ab>: coefficient} with a, b velocity letters u v w p q r");
  for (const MapValue::Entry& e : c.entries()) {
    if (e.key.size() != 2 || !IsVelocityLetter(e.key[0]) || !IsVelocityLetter(e.key[1])) {
      e.key_value.Expected("two velocity letters of u v w p q r (e.g. 'vr')");
    }
    SetParam(truth, param::kCouplingPrefix + e.key, AnyNumber(e.value), e.value);
  }
  if (c.entries().empty()) coefficients.Expected("at least one coefficient");
  const Value motion = m.Optional("motion");
  if (motion.absent()) return;
  const MapValue motions(motion, "a map {<dof>: {offset, amplitude, omega}}");
  for (const MapValue::Entry& e : motions.entries()) {
    const Dof other = DofKey(e);
    if (other == dof) {
      e.key_value.Fail("motion of '" + e.key +
                       "' itself comes from the simulation; expected another DOF");
    }
    const MapValue s(e.value, "a velocity {offset, amplitude, omega}");
    s.AllowOnly({"offset", "amplitude", "omega"});
    AuxMotion aux;
    if (const Value x = s.Optional("offset"); !x.absent()) aux.offset = AnyNumber(x);
    if (const Value x = s.Optional("amplitude"); !x.absent()) aux.amplitude = AnyNumber(x);
    if (const Value x = s.Optional("omega"); !x.absent()) aux.omega = NonNegative(x);
    truth->aux_motion[VelocityLetter(other)] = aux;
  }
}

void ParseEffectSettings(Effect effect, const Value& v, Dof dof, const Vehicle& vehicle,
                         DofTruth* truth) {
  const MapValue m(v, "the settings of effect " + std::string(EffectName(effect)));
  switch (effect) {
    case Effect::kInstallationLoss:
      m.AllowOnly({"eta"});
      ParseEta(m.Required("eta"), dof, vehicle, truth);
      break;
    case Effect::kAsymmetricDrag:
      ParseAsymmetricDrag(m, truth);
      break;
    case Effect::kThrusterLag:
      ParseSingle(m, param::kLag, Positive, truth);
      break;
    case Effect::kDeadzone:
      ParseSingle(m, param::kDeadzone, NonNegative, truth);
      break;
    case Effect::kAdvanceSpeedLoss:
      ParseSingle(m, param::kAdvanceLoss, NonNegative, truth);
      break;
    case Effect::kCoupling:
      ParseCoupling(m, dof, truth);
      break;
    case Effect::kSensorDelay:
      ParseSingle(m, param::kSensorDelay, NonNegative, truth);
      break;
    case Effect::kParameterDrift:
      ParseSingle(m, param::kDrift, AnyNumber, truth);
      break;
    case Effect::kThrustMap:
      ParseThrustMap(m, truth);
      break;
  }
}

std::string EffectList() {
  std::vector<std::string> names;
  for (Effect e : kAllEffects) names.emplace_back(EffectName(e));
  return Join(names);
}

}  // namespace uuvplan::io
