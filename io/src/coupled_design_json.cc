#include "uuvplan/io/coupled_design_json.h"

#include <cmath>

#include "uuvplan/io/json_value.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::io {
namespace {

constexpr double kProfileStep = 0.1;  // s: issue #17's "at most 0.1 s apart"

nlohmann::json Profile(const planner::CoupledDesign& d, const model::Vehicle& vehicle) {
  nlohmann::json t = nlohmann::json::array();
  nlohmann::json force = nlohmann::json::object(), thrusters = nlohmann::json::object();
  const int n = static_cast<int>(std::floor(d.trial.duration / kProfileStep + 1e-9));
  for (int k = 0; k <= n; ++k) {
    const double s = k * kProfileStep;
    t.push_back(s);
    for (const model::TrialDesign& in : d.trial.inputs) {
      force[std::string(model::DofName(in.dof))].push_back(in.NominalForce(s));
    }
    const std::vector<double> tau = planner::ThrusterForces(vehicle, d.trial, s);
    for (std::size_t i = 0; i < tau.size(); ++i) thrusters[vehicle.thrusters[i].name].push_back(tau[i]);
  }
  return {{"t", t}, {"force", force}, {"thrusters", thrusters}};
}

}  // namespace

nlohmann::json CoupledDesignJson(const planner::CoupledDesign& d, const model::Vehicle& vehicle,
                                 const model::Pool& pool) {
  nlohmann::json inputs = nlohmann::json::array();
  for (const model::TrialDesign& in : d.trial.inputs) {
    inputs.push_back({{"dof", std::string(model::DofName(in.dof))},
                      {"mapping", in.mapping},
                      {"kind", "sine"},
                      {"offset", in.offset},
                      {"amplitude", in.amplitude},
                      {"omega", in.omega}});
  }
  nlohmann::json cr = nlohmann::json::object();
  for (std::size_t c = 0; c < d.parameters.size(); ++c) {
    const double rel = d.worst_relative_sigma[c];
    cr[d.parameters[c]] = {{"sigma", d.worst_sigma[c]},
                           {"relative", std::isfinite(rel) ? nlohmann::json(rel) : nlohmann::json()}};
  }
  nlohmann::json j;
  j["model"] = "coupled-horizontal";
  j["pool"] = pool.name;
  j["fits"] = d.fits;
  j["reasons"] = d.reasons;
  j["notes"] = d.notes;
  j["trial"] = {{"id", d.trial.id},
                {"mode", std::string(model::kCombinedModeNames.Name(d.trial.mode))},
                {"duration", d.trial.duration},
                {"inputs", inputs},
                {"start", {{"x", d.start_x}, {"y", d.start_y}, {"heading", d.start_heading}}},
                {"profile", Profile(d, vehicle)}};
  j["envelope"] = {{"x", d.envelope.x}, {"y", d.envelope.y}, {"turns", d.envelope.turns},
                   {"thrust_margin", d.envelope.thrust_margin},
                   {"thrust_load", d.envelope.thrust_load},
                   {"closed_water_force", d.envelope.closed_water_force}};
  j["cramer_rao"] = cr;
  j["cramer_rao_assumption"] = planner::kCoupledSigmaAssumption;
  j["criterion"] = d.criterion;
  j["solver"] = d.solver.BriefReport();
  return j;
}

bool IsCoupledScheduleJson(const nlohmann::json& root) {
  return root.is_object() && root.contains("model") && root.at("model") == "coupled-horizontal";
}

namespace {

model::TrialDesign InputOfJson(const JsonValue& v) {
  model::TrialDesign in;
  const JsonValue dof = v.Required("dof");
  const auto parsed = model::ParseDof(String(dof, "surge, sway or yaw"));
  if (!parsed || model::HorizontalIndex(*parsed) < 0) dof.Expected("surge, sway or yaw");
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

model::CoupledTrialDesign CoupledTrialOfJson(const nlohmann::json& root, const std::string& path) {
  const JsonValue trial = JsonValue(root, path, "").Required("trial");
  model::CoupledTrialDesign d;
  d.id = String(trial.Required("id"), "a trial id");
  const JsonValue mode = trial.Required("mode");
  const auto parsed = model::kCombinedModeNames.Parse(String(mode, "a combined mode"));
  if (!parsed) mode.Expected("surge+yaw, sway+yaw or surge+sway+yaw");
  d.mode = *parsed;
  d.duration = PositiveNumber(trial.Required("duration"), "s");
  const JsonValue inputs = trial.Required("inputs");
  if (!inputs.json().is_array()) inputs.Expected("an array of inputs, one per DOF the mode moves");
  for (std::size_t i = 0; i < inputs.json().size(); ++i) {
    d.inputs.push_back(InputOfJson(inputs.Item(i)));
    d.inputs.back().duration = d.duration;
  }
  if (const std::string error = d.Check(); !error.empty()) {
    inputs.Expected("one input per DOF the mode moves", error);
  }
  return d;
}

}  // namespace uuvplan::io
