// `uuvplan simulate --json` (docs/cli.md): the campaign a plan's run on the virtual vehicle
// wrote, trial by trial, with its totals.
#pragma once

#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "uuvplan/model/campaign.h"
#include "uuvplan/model/trial_design.h"

namespace uuvplan::io {

/// Figures of a simulated campaign (trial i run from designs[i]).
struct CampaignTotals {
  std::size_t rows = 0;
  double trial_time = 0.0;  ///< s of trials
  double clock = 0.0;       ///< s of pool time, pauses included
};
CampaignTotals Totals(const model::Campaign& campaign,
                      const std::vector<model::TrialDesign>& designs);

/// {"campaign" (its campaign.yaml), "seed", "step" (s), "trials": [{"id", "dof", "file",
/// "rows", "duration", "start"}], "rows", "trial_time", "pool_time"}.
nlohmann::json SimulationJson(const model::Campaign& campaign,
                              const std::vector<model::TrialDesign>& designs,
                              const std::string& campaign_path, std::uint64_t seed, double step_s);

/// A coupled plan's one combined trial: {"campaign", "seed", "step", "model":
/// "coupled-horizontal", "trials": [{"id", "mode", "duration", "rows"}]}.
nlohmann::json CoupledSimulationJson(const model::CombinedTrialDesign& trial, std::size_t rows,
                                     const std::string& campaign_path, std::uint64_t seed,
                                     double step_s);

}  // namespace uuvplan::io
