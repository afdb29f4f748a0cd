// Is a logged trial the trial that was planned (`uuvplan log --plan`)? The
// log's nominal force column is what the vehicle was commanded, so it must follow the design's
// φ_n(t) (trial_design.h) on the design's DOF, for about the design's duration.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/trial_log.h"

namespace uuvplan::planner {

struct LogCheckOptions {
  /// Shortest and longest logged span as fractions of the design's duration. CHOSEN 0.9 and
  /// 1.5: a log starts a little before and ends a little after the commands; a run aborted
  /// before 90% of its time is not the planned trial (log it without --plan).
  double min_duration_fraction = 0.9;
  double max_duration_fraction = 1.5;
  /// Largest median |F_log(t) − φ_n(t)| as a fraction of max |φ_n|. CHOSEN 5%: a thrust
  /// controller's quantisation and a logged command rounded to 2-3 digits stay far below it,
  /// a different trial (another force level, the other direction) far above.
  double max_force_deviation = 0.05;
};

/// Each way the log departs from the design, as a sentence with figures; empty when it is the
/// planned trial. `dof` and `mapping` are the trial's as it is logged.
std::vector<std::string> CompareLogWithDesign(const model::TrialDesign& design, model::Dof dof,
                                              const std::string& mapping,
                                              const model::TrialLog& log,
                                              const LogCheckOptions& options = {});

}  // namespace uuvplan::planner
