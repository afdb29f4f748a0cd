#include "uuvplan/io/virtual_campaign.h"

#include <string>
#include <utility>
#include <vector>

#include "uuvplan/io/campaign_yaml.h"

namespace uuvplan::io {

model::Campaign SimulateCampaign(const model::Truth& truth,
                                 const std::vector<model::TrialDesign>& designs,
                                 const std::string& dir,
                                 const model::VirtualCampaignOptions& options) {
  CheckNewCampaignDirectory(dir);
  model::Campaign campaign = model::BuildVirtualCampaign(truth, designs, options);
  std::vector<std::string> comments;
  for (std::size_t i = 0; i < designs.size(); ++i) {
    campaign.trials[i].file = "trials/" + designs[i].id + ".csv";
    comments.push_back("uuvplan virtual pool: truth vehicle '" + truth.vehicle.name +
                       "', trial '" + designs[i].id + "', seed " + std::to_string(options.seed));
  }
  return WriteCampaign(dir, std::move(campaign), truth.vehicle, comments);
}

}  // namespace uuvplan::io
