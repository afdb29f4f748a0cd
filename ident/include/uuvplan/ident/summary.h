// The result shape shared by the staged pipelines (identification, diagnosis), in the manner of
// Ceres' Solver::Summary: the pipeline's name, a status word, a message, the wall time of each
// stage in order, and one line per DOF, as a one-line Brief() and a few-line Full() text.
#pragma once

#include <chrono>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"

namespace uuvplan::ident {

/// Wall time of one stage of a pipeline (s).
struct StageTime {
  std::string stage;
  double seconds = 0.0;
};

/// Wall time between laps (s), on std::chrono::steady_clock.
class Stopwatch {
 public:
  double Lap() {
    const auto now = Clock::now();
    const double s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    return s;
  }

 private:
  using Clock = std::chrono::steady_clock;
  Clock::time_point last_ = Clock::now();
};

/// Wall time summed per stage: each Lap(stage) adds the time since the previous lap (or since
/// construction) to `stage`, so that the stages add up to the whole elapsed time.
class StageClock {
 public:
  /// The stages, in the order they are reported, all at 0 s.
  explicit StageClock(const std::vector<std::string>& stages);
  /// Adds the time since the previous lap to `stage` (appended when not yet known).
  void Lap(const std::string& stage);
  const std::vector<StageTime>& times() const { return times_; }

 private:
  Stopwatch watch_;
  std::vector<StageTime> times_;
};

struct PipelineSummary {
  /// One DOF's part: a few words for Brief() ("surge output_error") and a line for Full().
  struct DofLine {
    model::Dof dof = model::Dof::kSurge;
    std::string brief;   ///< after the DOF's name in Brief()
    std::string detail;  ///< after "<dof>: " in Full()
  };
  std::string pipeline;  ///< "identify", "diagnose"
  std::string status;    ///< the pipeline's status word ("ok", "findings", "failed", …)
  std::string message;
  int num_trials = 0;
  std::vector<StageTime> stages;  ///< in the order the pipeline runs them
  std::vector<DofLine> dofs;

  double total_seconds() const;
  /// One line: "<pipeline>: <status>, <n> DOF(s) from <m> trial(s) in <t> s (<dof> <brief>, …)".
  std::string Brief() const;
  /// A few lines: the brief line, the message, the stage timings, one line per DOF.
  std::string Full() const;
};

}  // namespace uuvplan::ident
