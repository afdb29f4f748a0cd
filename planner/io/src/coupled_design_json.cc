#include "uuvplan/io/coupled_design_json.h"

#include <cmath>

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
  j["criterion"] = d.criterion;
  j["solver"] = d.solver.BriefReport();
  return j;
}

}  // namespace uuvplan::io
