// A virtual campaign on disk: built in memory by the model's campaign builder
// (model/campaign_builder.h) and written whole by io::WriteCampaign, as a pool team would
// log it: DIR/campaign.yaml, DIR/vehicle.yaml (the truth's vehicle) and DIR/trials/<id>.csv.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/campaign.h"
#include "uuvplan/model/campaign_builder.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/truth.h"

namespace uuvplan::io {

/// Runs `designs` in order on the virtual vehicle of `truth` (BuildVirtualCampaign with
/// `options`) and writes the campaign into the new directory `dir` (WriteCampaign): trial i
/// as trials/<design id>.csv, headed by a comment naming the truth vehicle, the trial and the
/// seed. `dir` must not exist or be empty (checked before anything is simulated). Returns the
/// campaign as written.
model::Campaign SimulateCampaign(const model::Truth& truth,
                                 const std::vector<model::TrialDesign>& designs,
                                 const std::string& dir,
                                 const model::VirtualCampaignOptions& options);

}  // namespace uuvplan::io
