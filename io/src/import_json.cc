#include "uuvplan/io/import_json.h"

#include <filesystem>

namespace uuvplan::io {

nlohmann::json ImportJson(const ImportedCampaign& imported, const std::string& campaign_path) {
  nlohmann::json trials = nlohmann::json::array();
  for (std::size_t i = 0; i < imported.trials.size(); ++i) {
    const model::TrialEntry& e = imported.campaign.trials[i];
    const ImportedTrial& t = imported.trials[i];
    trials.push_back({{"id", std::filesystem::path(e.file).stem().string()},
                      {"dof", model::DofName(e.dof)},
                      {"mapping", e.mapping},
                      {"use", model::TrialUseName(e.use)},
                      {"file", e.file},
                      {"recording", t.recording},
                      {"rows", e.log.size()},
                      {"span_s", t.span_s},
                      {"rate_hz", t.rate_hz},
                      {"start_s", e.start}});
  }
  return {
      {"campaign", campaign_path}, {"vehicle", imported.campaign.vehicle_file}, {"trials", trials}};
}

}  // namespace uuvplan::io
