#include "uuvplan/io/virtual_campaign.h"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "uuvplan/io/campaign_yaml.h"
#include "uuvplan/io/output_claim.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/model/work_limits.h"

namespace uuvplan::io {

namespace {

// The work each designed trial asks of the virtual pool, against the work limits, before any
// is simulated: RK4 steps (duration / step) and rows (duration × the fastest sensor or command
// rate), for the whole plan too.
void CheckSimulationWork(const model::Truth& truth, const std::vector<model::TrialDesign>& designs,
                         const model::VirtualCampaignOptions& options) {
  using model::Significant;
  double rate = options.command_rate_hz;
  for (const auto& [dof, sensors] : truth.vehicle.sensors) {
    for (const auto& spec : {sensors.position, sensors.velocity}) {
      if (spec) rate = std::max(rate, spec->rate_hz);
    }
  }
  double rows = 0;
  for (std::size_t i = 0; i < designs.size(); ++i) {
    const model::TrialDesign& d = designs[i];
    const std::string key = "plan: trials[" + std::to_string(i) + "] '" + d.id + "'";
    const double steps = d.duration / truth.integration_step_s;
    if (!(steps <= model::limits::kMaxSimulationSteps)) {
      throw model::InputError(
          key, "duration " + Significant(d.duration, 4) + " s / integration step " +
                   Significant(truth.integration_step_s, 4) +
                   " s (virtual_pool.step or --step) needs " + Significant(steps, 3) +
                   " RK4 steps, at most " + Significant(model::limits::kMaxSimulationSteps, 3));
    }
    rows += d.duration * rate;
    if (!(rows <= model::limits::kMaxCampaignRows)) {
      throw model::InputError(key, "the plan's trials up to this one last " +
                                       Significant(rows / rate, 4) + " s, " + Significant(rows, 3) +
                                       " rows at " + Significant(rate, 4) + " Hz (the fastest " +
                                       "sensor or command), at most " +
                                       Significant(model::limits::kMaxCampaignRows, 3));
    }
  }
}

}  // namespace

model::Campaign SimulateCampaign(const model::Truth& truth,
                                 const std::vector<model::TrialDesign>& designs,
                                 const std::string& dir,
                                 const model::VirtualCampaignOptions& options) {
  CheckSimulationWork(truth, designs, options);
  const OutputClaim claim(dir);  // before the work: a second run on `dir` fails at once
  model::Campaign campaign = model::BuildVirtualCampaign(truth, designs, options);
  std::vector<std::string> comments;
  for (std::size_t i = 0; i < designs.size(); ++i) {
    campaign.trials[i].file = "trials/" + designs[i].id + ".csv";
    comments.push_back("uuvplan virtual pool: truth vehicle '" + truth.vehicle.name + "', trial '" +
                       designs[i].id + "', seed " + std::to_string(options.seed));
  }
  return WriteCampaign(dir, std::move(campaign), truth.vehicle, comments);
}

}  // namespace uuvplan::io
