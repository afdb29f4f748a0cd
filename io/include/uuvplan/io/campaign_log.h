// A trial logged at the pool appended to its campaign (`uuvplan log`), so
// that `next` can run between two trials: the trial's CSV is copied into the campaign's
// trials/<id>.csv (the input file is never modified) and campaign.yaml rewritten with one more
// trial, each written atomically; the new campaign is read back whole (ReadCampaign's checks)
// before it replaces the old one, so a bad log leaves the campaign as it was.
#pragma once

#include <functional>
#include <optional>
#include <string>

#include "uuvplan/model/campaign.h"

namespace uuvplan::io {

struct LoggedTrial {
  std::string id;   ///< the trial's id: its file is trials/<id>.csv
  std::string csv;  ///< the logged CSV
  model::Dof dof = model::Dof::kSurge;
  std::string mapping;  ///< empty: the vehicle's only mapping on `dof`
  int ballast_steps = 0;
  model::TrialUse use = model::TrialUse::kFit;
  std::optional<double> start;  ///< campaign clock (s)
};

/// Appends `trial` to the campaign at `campaign_path` (campaign.yaml or its directory) and
/// returns the campaign as read back. model::InputError (nothing changed) when the campaign or
/// the CSV is bad, or the id is taken (in the campaign or as a file under trials/).
/// `check`, when given, sees the log as identification will (force columns from any commands)
/// before anything is written, and throws to refuse it.
using LogCheck = std::function<void(const model::TrialLog&)>;
model::Campaign AppendLoggedTrial(const std::string& campaign_path, const LoggedTrial& trial,
                                  const LogCheck& check = {});

}  // namespace uuvplan::io
