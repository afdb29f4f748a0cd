// The information a schedule carries as JSON (information_json.h).
#include "uuvplan/io/information_json.h"

#include <cmath>
#include <string>

#include "uuvplan/io/json_value.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/planner/schedule.h"

namespace uuvplan::io {
nlohmann::json InformationJson(const planner::InformationSummary& s) {
  nlohmann::json units = nlohmann::json::array(), theta = nlohmann::json::array();
  nlohmann::json fisher = nlohmann::json::array(), sigma = nlohmann::json::object();
  for (std::size_t i = 0; i < s.names.size(); ++i) {
    units.push_back(model::Unit(s.names[i], s.dof));
    theta.push_back(s.theta[i]);
    nlohmann::json row = nlohmann::json::array();
    for (std::size_t j = 0; j < s.names.size(); ++j) row.push_back(s.fisher(i, j));
    fisher.push_back(row);
    sigma[s.names[i]] = JsonNumber(s.sigma[i]);
  }
  return {{"parameters", s.names},
          {"units", units},
          {"theta", theta},
          {"fisher", fisher},
          {"criteria", {{"D", s.d}, {"A", s.a}, {"E", s.e}, {"singular", s.singular}}},
          {"sigma", sigma},
          {"condition_number", JsonNumber(s.condition_number)}};
}

void AddInformationJson(const planner::ScheduleInformation& info, nlohmann::json* j) {
  nlohmann::json& trials = (*j)["trials"];
  for (std::size_t i = 0; i < info.trials.size() && i < trials.size(); ++i) {
    trials[i]["information"] = InformationJson(info.trials[i]);
  }
  nlohmann::json dofs = nlohmann::json::object();
  for (const auto& [dof, s] : info.dofs)
    dofs[std::string(model::DofName(dof))] = InformationJson(s);
  (*j)["information"] = {
      {"point", "the nominal parameters (centre of the a priori box)"},
      {"criteria",
       "relative information M_rel = D·M·D, D = diag(|theta|): D = log det, "
       "A = -log tr M_rel^-1, E = log lambda_min (natural log, larger is better)"},
      {"assumption", planner::kPredictedSigmaAssumption},
      {"dofs", dofs}};
}

}  // namespace uuvplan::io
