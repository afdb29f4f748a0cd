// Cross-checks of a campaign's trials, beyond each file's own format: what makes
// identification silently meaningless. Run by ReadCampaign on each trial as it is read.
//  - work: all rows of the campaign within the work limits (model/work_limits.h; refused
//    whatever the user accepts);
//  - plausibility (io/plausibility.h, --accept-implausible): the same log listed twice (a trial
//    fit and validated on the same data validates nothing), a time column whose sampling
//    interval does not fit the sensor's declared rate (×1000: a time column in ms), a trial
//    longer than a day, a logged force beyond a thousand weights of the vehicle (1e308 in one
//    cell).
#pragma once

#include <vector>

#include "uuvplan/io/yaml_value.h"
#include "uuvplan/model/campaign.h"

namespace uuvplan::io {

/// Checks `campaign.trials[index]` (read from `item`) against itself and the trials before it.
void CheckCampaignTrial(const model::Campaign& campaign, std::size_t index, const Value& item);

/// Checks the whole campaign's work limits; `trials` is the campaign's `trials` key.
void CheckCampaignWork(const model::Campaign& campaign, const Value& trials);

}  // namespace uuvplan::io
