// `uuvplan simulate --json` (simulation_json.h).
#include "uuvplan/io/simulation_json.h"

namespace uuvplan::io {

CampaignTotals Totals(const model::Campaign& campaign,
                      const std::vector<model::TrialDesign>& designs) {
  CampaignTotals t;
  for (std::size_t i = 0; i < campaign.trials.size(); ++i) {
    t.rows += campaign.trials[i].log.size();
    t.trial_time += designs[i].duration;
  }
  if (!campaign.trials.empty()) t.clock = campaign.trials.back().start + designs.back().duration;
  return t;
}

nlohmann::json SimulationJson(const model::Campaign& campaign,
                              const std::vector<model::TrialDesign>& designs,
                              const std::string& campaign_path, std::uint64_t seed, double step_s) {
  nlohmann::json trials = nlohmann::json::array();
  for (std::size_t i = 0; i < campaign.trials.size(); ++i) {
    const auto& e = campaign.trials[i];
    const auto& d = designs[i];
    trials.push_back({{"id", d.id},
                      {"dof", std::string(model::DofName(d.dof))},
                      {"file", e.file},
                      {"rows", e.log.size()},
                      {"duration", d.duration},
                      {"start", e.start}});
  }
  const CampaignTotals totals = Totals(campaign, designs);
  return {{"campaign", campaign_path}, {"seed", seed},        {"step", step_s},
          {"trials", trials},          {"rows", totals.rows}, {"trial_time", totals.trial_time},
          {"pool_time", totals.clock}};
}

nlohmann::json CoupledSimulationJson(const model::CombinedTrialDesign& trial, std::size_t rows,
                                     const std::string& campaign_path, std::uint64_t seed,
                                     double step_s) {
  return {{"campaign", campaign_path},
          {"seed", seed},
          {"step", step_s},
          {"model", "coupled-horizontal"},
          {"trials",
           {{{"id", trial.id},
             {"mode", model::DofList(trial.dofs)},
             {"duration", trial.duration},
             {"rows", rows}}}}};
}

}  // namespace uuvplan::io
