// The campaign (contract §Campaign): campaign.yaml with its vehicle, pool and trial logs, read
// whole; written as campaign.yaml alone or as a whole directory (vehicle, campaign, trials).
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/campaign.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::io {

/// Reads the campaign YAML (or DIR/campaign.yaml when `path` is a directory), its vehicle (and
/// pool) and every trial CSV.
model::Campaign ReadCampaign(const std::string& path);

/// Writes campaign.yaml; trial files are written by the caller (paths relative to `path`).
void WriteCampaignYaml(const std::string& path, const model::Campaign& campaign);

/// Throws InputError when the campaign directory `dir` exists and is not empty (WriteCampaign
/// refuses it: nothing is overwritten).
void CheckNewCampaignDirectory(const std::string& dir);

/// Writes a whole campaign into the new directory `dir`: `vehicle` as vehicle.yaml, each trial's
/// log at its `file` (relative to `dir`, headed by the comment `trial_comments[i]` when given)
/// and campaign.yaml naming them (and `campaign.pool_file` as given, if any). Everything goes to a
/// temporary sibling directory renamed into place, so the campaign is written whole or not at all;
/// `dir` must not exist or be empty. Returns `campaign` with its path and the trials' paths set to
/// where they were written.
model::Campaign WriteCampaign(const std::string& dir, model::Campaign campaign,
                              const model::Vehicle& vehicle,
                              const std::vector<std::string>& trial_comments = {});

}  // namespace uuvplan::io
