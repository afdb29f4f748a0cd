// The effect settings of a truth file (dofs.<dof>.effects: {<effect>: {...}}, docs/formats.md):
// each effect's keys read into the true parameters of the DOF.
#include "truth_effects.h"

#include <algorithm>
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

// A qualified family's map in a truth file, {<qualifier>: value} (e.g. eta:
// {<mapping>.<pos|neg>: v}, ref 000 eq. 3), each qualifier and value checked by the family.
void ParseQualified(const ParameterFamily& family, const Value& v, Dof dof, const Vehicle& vehicle,
                    DofTruth* truth) {
  const MapValue m(v, "a map {<" + std::string(family.meaning) + ">: value}");
  for (const MapValue::Entry& e : m.entries()) {
    const std::string problem = family.check_qualifier(e.key, dof, vehicle);
    if (!problem.empty()) e.key_value.Expected(problem);
    const double x =
        NumberIf(e.value, family.Expected(), [&family](double y) { return family.Admissible(y); });
    SetParam(truth, std::string(family.name) + e.key, x, e.value);
  }
  if (m.entries().empty()) v.Expected("at least one entry");
}

// coupling's `motion: {<dof>: {offset, amplitude, omega}}`: the other DOFs' velocities that
// drive a term reading them, in the virtual pool (truth.h AuxMotion).
void ParseOtherMotion(const Value& motion, Dof dof, DofTruth* truth) {
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

// The keys an effect's settings may hold: its parameters (a qualified family by its file
// key), its settings, and `motion` where its terms read other DOFs.
std::vector<std::string> SettingKeys(const EffectEntry& effect) {
  std::vector<std::string> keys;
  for (const ParameterFamily& f : effect.parameters) {
    keys.emplace_back(f.qualified() ? f.file_key : f.name);
  }
  for (const EffectSetting& s : effect.settings) keys.emplace_back(s.file_key);
  if (effect.reads_other_motion) keys.emplace_back("motion");
  return keys;
}

// dofs.<dof>.effects.<effect>: {settings}, as the effect table declares them (effects.h):
// each parameter in its admissible range (a value not given defaults to its `defaults_to`
// parameter's, else is required), each setting a positive number.
void ParseEffectSettings(const EffectEntry& effect, const Value& v, Dof dof, const Vehicle& vehicle,
                         DofTruth* truth) {
  const MapValue m(v, "the settings of effect " + effect.name);
  const std::vector<std::string> keys = SettingKeys(effect);
  m.AllowOnly(std::vector<std::string_view>(keys.begin(), keys.end()));
  const bool all_default =
      std::all_of(effect.parameters.begin(), effect.parameters.end(),
                  [](const ParameterFamily& f) { return !f.defaults_to.empty(); });
  if (m.entries().empty() && all_default) m.self().Expected(model::Join(keys, " and/or "));
  for (const ParameterFamily& f : effect.parameters) {
    if (f.qualified()) {
      ParseQualified(f, m.Required(f.file_key), dof, vehicle, truth);
      continue;
    }
    const Value x = m.Optional(f.name);
    if (x.absent() && !f.defaults_to.empty()) {
      SetParam(truth, std::string(f.name), truth->params.at(std::string(f.defaults_to)), m.self());
      continue;
    }
    const Value given = m.Required(f.name);
    SetParam(truth, std::string(f.name),
             NumberIf(given, f.Expected(), [&f](double y) { return f.Admissible(y); }), given);
  }
  for (const EffectSetting& s : effect.settings) {
    truth->settings[std::string(s.setting)] = Positive(m.Required(s.file_key));
  }
  if (effect.reads_other_motion) {
    if (const Value motion = m.Optional("motion"); !motion.absent()) {
      ParseOtherMotion(motion, dof, truth);
    }
  }
}

}  // namespace uuvplan::io
