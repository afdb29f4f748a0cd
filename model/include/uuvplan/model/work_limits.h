// The largest work an input may ask for (no input may hang uuvplan or take more
// than 2 GB). Each limit is far above any pool trial and says what it bounds; the io layer
// checks inputs against them before any work starts, naming the key that is too large, and
// CheckedCount (util/checked_count.h) enforces them where a count is computed.
#pragma once

namespace uuvplan::model::limits {

/// Rows of one trial log or sampled trajectory (duration × rate): a day at 100 Hz is 8.6e6;
/// 1e7 rows × the log's ~5 columns × 8 B is 400 MB.
inline constexpr double kMaxTrialRows = 1e7;

/// RK4 steps of one simulated trial (duration / integration step): 1e8 steps are ~2 s of CPU
/// per simulation (bench/simulate_bench.cc), 1e4 s at a 0.1 ms step.
inline constexpr double kMaxSimulationSteps = 1e8;

/// Rows of all the trials of one campaign, read or simulated (the campaign is held in memory).
/// Identification holds ~245 B a row at worst (2,000 BlueROV gyro trials, 5.87e6 rows: 1,437 MB
/// peak RSS, docs/performance.md), so 6e6 rows keep a campaign under 2 GB.
inline constexpr double kMaxCampaignRows = 6e6;

/// Rows of one logged trial (a CSV's line count, checked before it is read): no more than
/// its campaign may hold.
inline constexpr double kMaxLogRows =
    kMaxCampaignRows < kMaxTrialRows ? kMaxCampaignRows : kMaxTrialRows;

// No limit on (fit rows) × (fit trials) any more: the output error accumulates its normal
// equations trial by trial (ident/estimators/block_least_squares.h), so its memory is O(rows +
// trials), not rows × trials (2,000 trials of 2,934 rows, docs/performance.md).

}  // namespace uuvplan::model::limits
