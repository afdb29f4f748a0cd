#include "uuvplan/io/combined_design_json.h"

#include <algorithm>
#include <cmath>

#include "uuvplan/io/json_value.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io {
namespace {

constexpr double kProfileStep = 0.1;  // s: a replay's samples at most 0.1 s apart

nlohmann::json Profile(const planner::CombinedDesign& d, const model::Vehicle& vehicle) {
  nlohmann::json t = nlohmann::json::array();
  nlohmann::json force = nlohmann::json::object(), thrusters = nlohmann::json::object();
  const int n = static_cast<int>(std::floor(d.trial.duration / kProfileStep + 1e-9));
  for (int k = 0; k <= n; ++k) {
    const double s = k * kProfileStep;
    t.push_back(s);
    for (const model::TrialDesign& in : d.trial.inputs) {
      force[std::string(model::DofName(in.dof))].push_back(in.NominalForce(s));
    }
    const std::vector<double> tau = planner::ThrusterForcesAt(vehicle, d.trial, s);
    for (std::size_t i = 0; i < tau.size(); ++i)
      thrusters[vehicle.thrusters[i].name].push_back(tau[i]);
  }
  return {{"t", t}, {"force", force}, {"thrusters", thrusters}};
}

nlohmann::json TrialJson(const planner::CombinedDesign& d, const model::MultiDofModel& model,
                         const model::Vehicle& vehicle) {
  nlohmann::json inputs = nlohmann::json::array();
  for (const model::TrialDesign& in : d.trial.inputs) {
    inputs.push_back({{"dof", std::string(model::DofName(in.dof))},
                      {"mapping", in.mapping},
                      {"kind", "sine"},
                      {"offset", in.offset},
                      {"amplitude", in.amplitude},
                      {"omega", in.omega}});
  }
  nlohmann::json start = nlohmann::json::object();
  for (int i = 0; i < model.num_dofs() && i < static_cast<int>(d.start.size()); ++i) {
    start[model.PositionName(i)] = d.start[i];
  }
  return {{"id", d.trial.id},
          {"mode", model::DofList(d.trial.dofs)},
          {"duration", d.trial.duration},
          {"inputs", inputs},
          {"start", start},
          {"profile", Profile(d, vehicle)}};
}

nlohmann::json EnvelopeJson(const planner::CombinedEnvelope& e, const model::MultiDofModel& model) {
  nlohmann::json j = {{"turns", e.turns},
                      {"thrust_margin", e.thrust_margin},
                      {"thrust_load", e.thrust_load},
                      {"closed_water_force", e.closed_water_force}};
  for (int i = 0; i < model.num_dofs() && i < static_cast<int>(e.travel.size()); ++i) {
    if (!model::IsRotational(model.dof(i))) j[model.PositionName(i)] = e.travel[i];
  }
  return j;
}

}  // namespace

nlohmann::json CombinedDesignJson(const planner::CombinedDesign& d,
                                  const model::MultiDofModel& model, const model::Vehicle& vehicle,
                                  const model::Pool& pool, const CombinedModelText& text) {
  nlohmann::json cr = nlohmann::json::object();
  for (std::size_t c = 0; c < d.parameters.size(); ++c) {
    const double rel = d.worst_relative_sigma[c];
    cr[d.parameters[c]] = {
        {"sigma", d.worst_sigma[c]},
        {"relative", std::isfinite(rel) ? nlohmann::json(rel) : nlohmann::json()}};
  }
  nlohmann::json j;
  j["model"] = text.name;
  j["pool"] = pool.name;
  j["fits"] = d.fits;
  j["reasons"] = d.reasons;
  j["notes"] = d.notes;
  j["trial"] = TrialJson(d, model, vehicle);
  j["envelope"] = EnvelopeJson(d.envelope, model);
  j["cramer_rao"] = cr;
  j["cramer_rao_assumption"] = text.sigma_assumption;
  j["criterion"] = d.criterion;
  j["solver"] = d.solver.BriefReport();
  return j;
}

bool IsCombinedScheduleJson(const nlohmann::json& root, const std::string& model_name) {
  return root.is_object() && root.contains("model") && root.at("model") == model_name;
}

namespace {

// "surge, sway or yaw": the model's DOFs.
std::string DofChoice(const model::MultiDofModel& model) {
  std::string s;
  for (int i = 0; i < model.num_dofs(); ++i) {
    s += (i == 0                      ? ""
          : i + 1 == model.num_dofs() ? " or "
                                      : ", ") +
         std::string(model::DofName(model.dof(i)));
  }
  return s;
}

model::TrialDesign InputOfJson(const JsonValue& v, const model::MultiDofModel& model) {
  model::TrialDesign in;
  const JsonValue dof = v.Required("dof");
  const auto parsed = model::ParseDof(String(dof, DofChoice(model)));
  if (!parsed || model.DofIndex(*parsed) < 0) dof.Expected(DofChoice(model));
  in.dof = *parsed;
  in.kind = model::TrialKind::kSine;
  if (const JsonValue kind = v.Required("kind"); String(kind, "\"sine\"") != "sine") {
    kind.Expected("\"sine\" (the only kind of a combined design)");
  }
  in.mapping = String(v.Required("mapping"), "a mapping name");
  in.offset = Number(v.Required("offset"), "a number (N or N·m)");
  in.amplitude = NonNegativeNumber(v.Required("amplitude"), "a number >= 0 (N or N·m)");
  in.omega = PositiveNumber(v.Required("omega"), "rad/s");
  return in;
}

}  // namespace

model::CombinedTrialDesign CombinedTrialOfJson(const nlohmann::json& root, const std::string& path,
                                               const model::MultiDofModel& model) {
  const JsonValue trial = JsonValue(root, path, "").Required("trial");
  model::CombinedTrialDesign d;
  d.id = String(trial.Required("id"), "a trial id");
  const JsonValue mode = trial.Required("mode");
  const auto dofs = model::ParseDofList(String(mode, "a combined mode"));
  if (!dofs || std::any_of(dofs->begin(), dofs->end(),
                           [&](model::Dof x) { return model.DofIndex(x) < 0; })) {
    mode.Expected("DOFs of " + DofChoice(model) + " joined by '+' (e.g. surge+sway+yaw)");
  }
  d.dofs = *dofs;
  d.duration = PositiveNumber(trial.Required("duration"), "s");
  const JsonValue inputs = trial.Required("inputs");
  if (!inputs.json().is_array()) inputs.Expected("an array of inputs, one per DOF the mode moves");
  for (std::size_t i = 0; i < inputs.json().size(); ++i) {
    d.inputs.push_back(InputOfJson(inputs.Item(i), model));
    d.inputs.back().duration = d.duration;
  }
  if (const std::string error = d.Check(); !error.empty()) {
    inputs.Expected("one input per DOF the mode moves", error);
  }
  return d;
}

}  // namespace uuvplan::io
