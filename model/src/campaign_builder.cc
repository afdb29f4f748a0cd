#include "uuvplan/model/campaign_builder.h"

#include <string>

#include "uuvplan/model/util/seed.h"
#include "uuvplan/model/virtual_pool.h"

namespace uuvplan::model {

VirtualCampaignBuilder::VirtualCampaignBuilder(const Truth& truth, VirtualCampaignOptions options)
    : truth_(truth), options_(std::move(options)) {
  campaign_.path = "<virtual>";
  campaign_.vehicle_file = "<virtual>";
  campaign_.vehicle = truth.vehicle;
  campaign_.pool = options_.pool;
}

const TrialEntry& VirtualCampaignBuilder::Append(const TrialDesign& design) {
  const std::size_t i = campaign_.trials.size();
  VirtualPoolOptions pool_options;
  pool_options.seed = StreamSeed(options_.seed, i);
  pool_options.command_rate_hz = options_.command_rate_hz;
  TrialEntry e;
  e.file = design.id.empty() ? "trial_" + std::to_string(i) : design.id;
  e.path = e.file;
  e.dof = design.dof;
  e.mapping = design.mapping;
  e.ballast_steps = design.ballast_steps;
  e.use = i < options_.uses.size() ? options_.uses[i] : TrialUse::kFit;
  e.start = clock_;
  e.has_start = true;
  e.log = RunVirtualTrial(truth_, design, clock_, pool_options);
  // The virtual pool wraps headings to (-pi, pi] as a compass does; reading the CSV unwraps.
  if (options_.unwrap_headings) UnwrapAngles(&e.log);
  campaign_.trials.push_back(std::move(e));
  clock_ += design.duration + options_.pause_s;
  return campaign_.trials.back();
}

Campaign BuildVirtualCampaign(const Truth& truth, const std::vector<TrialDesign>& designs,
                              const VirtualCampaignOptions& options) {
  VirtualCampaignBuilder builder(truth, options);
  for (const auto& design : designs) builder.Append(design);
  return builder.Take();
}

}  // namespace uuvplan::model
