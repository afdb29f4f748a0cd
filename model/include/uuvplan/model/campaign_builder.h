// The one builder of virtual campaigns: a truth vehicle runs trial designs in order in the
// virtual pool (virtual_pool.h), each from rest with its own seed, and the logs are kept in
// memory. Monte Carlo, the design–identify loop and `uuvplan simulate`/`demo` (through
// io::SimulateCampaign, which writes the campaign after building it) all build campaigns
// here, so trial i of any of them draws the same noise for the same seed.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include "uuvplan/model/campaign.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/truth.h"

namespace uuvplan::model {

struct VirtualCampaignOptions {
  std::uint64_t seed = 1;         ///< trial i draws from StreamSeed(seed, i) (util/seed.h)
  double command_rate_hz = 20.0;  ///< the virtual pool's command rate (VirtualPoolOptions)
  double pause_s = 60.0;       ///< the campaign clock advances by each trial's duration + pause_s
  std::vector<TrialUse> uses;  ///< use of trial i (may be shorter: the rest are fit trials)
  /// Unwrap headings as reading the trial CSV does; off, the logs hold the compass's wrapped
  /// angles, as written to disk.
  bool unwrap_headings = false;
  std::optional<Pool> pool;  ///< recorded in the campaign
};

/// Builds a campaign one trial at a time (the loop designs trial i + 1 after seeing trial i).
/// Trial entries are named by the design's id ("trial_<i>" without one); the campaign's path
/// and vehicle file are "<virtual>".
class VirtualCampaignBuilder {
 public:
  /// `truth` must outlive the builder.
  VirtualCampaignBuilder(const Truth& truth, VirtualCampaignOptions options);

  /// Runs `design` as the next trial, from rest at the campaign clock, and appends its entry.
  /// Throws InputError when the truth or the vehicle cannot run it.
  const TrialEntry& Append(const TrialDesign& design);

  const Campaign& campaign() const { return campaign_; }
  /// The campaign built so far, moved out (the builder is spent).
  Campaign Take() { return std::move(campaign_); }
  /// Campaign clock (s): the start of the next trial.
  double clock() const { return clock_; }

 private:
  const Truth& truth_;
  VirtualCampaignOptions options_;
  Campaign campaign_;
  double clock_ = 0.0;
};

/// Every design in order: trial i is design i (see VirtualCampaignBuilder).
Campaign BuildVirtualCampaign(const Truth& truth, const std::vector<TrialDesign>& designs,
                              const VirtualCampaignOptions& options);

}  // namespace uuvplan::model
