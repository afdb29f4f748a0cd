// The truth file (contract §Truth, docs/formats.md): a vehicle file plus, per DOF, the true
// standard-model parameters and the effects the virtual vehicle has, and the virtual pool's
// defects. Effect settings are read by truth_effects.cc.
#include "uuvplan/io/truth_yaml.h"

#include <optional>
#include <string>
#include <utility>

#include "truth_effects.h"
#include "uuvplan/io/plausibility.h"
#include "uuvplan/model/effects.h"
#include "vehicle_keys.h"

namespace uuvplan::io {

using namespace model;  // NOLINT: the vocabulary of the truth file

namespace {

// params: the true standard-model parameters of the DOF. m is required; k, kq, bias and
// bias_step default to 0 (eta to 1, i.e. not listed).
void ParseParams(const Value& v, Dof dof, const Vehicle& vehicle, DofTruth* truth) {
  const MapValue m(v, "a map {m, k, kq, bias, bias_step, eta}");
  m.AllowOnly({"m", "k", "kq", "bias", "bias_step", "eta"});
  // Each value also against its family's plausible ratio to the vehicle (plausibility.h).
  const auto plausible = [&](const Value& x, double value, const char* name) {
    CheckPlausibleParameter(x, value, *FamilyNamed(name), dof, vehicle);
    return value;
  };
  const Value mass = m.Required("m");
  truth->params[param::kMass] = plausible(mass, Positive(mass), param::kMass);
  const auto optional = [&](const char* key, double (*read)(const Value&)) {
    const Value x = m.Optional(key);
    return x.absent() ? 0.0 : plausible(x, read(x), key);
  };
  truth->params[param::kLinearDrag] = optional("k", NonNegative);
  truth->params[param::kQuadraticDrag] = optional("kq", NonNegative);
  truth->params[param::kBias] = optional("bias", AnyNumber);
  truth->params[param::kBiasStep] = optional("bias_step", AnyNumber);
  if (const Value eta = m.Optional("eta"); !eta.absent()) {
    ParseQualified(*FamilyNamed(param::kEtaPrefix), eta, dof, vehicle, truth);
  }
}

// sigma: {<parameter>: σ}, σ >= 0 of parameters the DOF's params or effects give.
void ParseSigma(const Value& v, DofTruth* truth) {
  const MapValue m(v, "a map {<parameter>: sigma}");
  for (const MapValue::Entry& e : m.entries()) {
    if (!truth->params.count(e.key)) {
      e.key_value.Expected("a parameter given by this DOF's params or effects");
    }
    truth->sigma[e.key] = NonNegative(e.value);
  }
}

}  // namespace

// dofs.<dof>.params, .effects and .sigma of a truth file (or of a vehicle file with a model,
// as `diagnose --write-vehicle` writes it); nullopt when the DOF has no params.
std::optional<DofTruth> ParseTruthDof(const Value& v, Dof dof, const Vehicle& vehicle) {
  const MapValue m(v, "a map {drag, added_mass, params, effects, sigma, origin}");
  const Value effects = m.Optional("effects");
  if (!m.Has("params")) {
    if (!effects.absent()) m.Required("params");  // effects act on the true parameters
    return std::nullopt;
  }
  DofTruth truth;
  ParseParams(m.Required("params"), dof, vehicle, &truth);
  if (!effects.absent()) {
    const MapValue settings(effects, "a map {<effect>: {settings}}");
    for (const MapValue::Entry& e : settings.entries()) {
      const EffectEntry* effect = Effects().Find(e.key);
      if (!effect) e.key_value.Expected("an effect (" + Effects().NameList() + ")");
      ParseEffectSettings(*effect, e.value, dof, vehicle, &truth);
    }
  }
  if (const Value sigma = m.Optional("sigma"); !sigma.absent()) ParseSigma(sigma, &truth);
  if (const Value origin = m.Optional("origin"); !origin.absent()) {
    if (truth.sigma.empty()) origin.Expected("no origin without sigma (a model known to ±σ)");
    truth.origin = Name(origin, "where the model with σ comes from (a sentence)");
  }
  return truth;
}

namespace {

// virtual_pool: {step, dropout_probability, outlier_probability, outlier_size}.
void ParseVirtualPool(const Value& v, Truth* truth) {
  const MapValue m(v, "a map {step, dropout_probability, outlier_probability, outlier_size}");
  m.AllowOnly({"step", "dropout_probability", "outlier_probability", "outlier_size"});
  if (const Value x = m.Optional("step"); !x.absent()) {
    truth->integration_step_s = Positive(x);
    CheckPlausible(x, truth->integration_step_s, plausible::kIntegrationStep);
  }
  if (const Value x = m.Optional("dropout_probability"); !x.absent()) {
    truth->defects.dropout_probability = Probability(x);
  }
  if (const Value x = m.Optional("outlier_probability"); !x.absent()) {
    truth->defects.outlier_probability = Probability(x);
  }
  if (const Value x = m.Optional("outlier_size"); !x.absent()) {
    truth->defects.outlier_size = NonNegative(x);
  }
}

}  // namespace

Truth ReadTruth(const std::string& path) {
  return Guarded(path, [&] {
    const MapValue m = LoadYamlMap(path, "a truth file (a vehicle plus dofs.<dof>.params)",
                                   "a map of vehicle keys");
    Truth truth;
    truth.vehicle = ParseVehicle(m, true);
    if (const Value dofs = m.Optional("dofs"); !dofs.absent()) {
      const MapValue dof_map(dofs, "a map of DOFs");
      for (const MapValue::Entry& e : dof_map.entries()) {
        const Dof dof = DofKey(e);
        if (auto t = ParseTruthDof(e.value, dof, truth.vehicle)) truth.dofs[dof] = std::move(*t);
      }
    }
    if (truth.dofs.empty()) m.self().Fail("expected dofs.<dof>.params for at least one DOF");
    if (const Value v = m.Optional("virtual_pool"); !v.absent()) ParseVirtualPool(v, &truth);
    return truth;
  });
}

}  // namespace uuvplan::io
