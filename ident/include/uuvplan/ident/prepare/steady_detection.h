// The steady-state part of each constant-force piece (ref 000 §III): the speed must have settled
// within the noise, tested on the data, never assumed after a fixed time; its speed is then
// fitted (speed_fit.h).
#pragma once

#include <string>
#include <vector>

#include "uuvplan/ident/prepare/signal.h"
#include "uuvplan/ident/prepare/speed_fit.h"

namespace uuvplan::ident {

/// A time interval during which the commanded force and mapping are constant.
struct ForcePiece {
  double t0 = 0.0, t1 = 0.0;
  double force = 0.0;
  int mapping = -1;
};

struct SteadyDetectionOptions {
  double min_duration_s = 5.0;  ///< shortest steady segment kept
  int min_samples = 10;         ///< fewest samples in a steady segment
  /// Settling test: the speed change across the segment (quadratic fit) and the difference of
  /// the two halves' speeds must both lie within z·σ.
  double z = 2.0;
  /// Candidate starts are tried every `stride` samples (0: automatic, about 200 candidates).
  int stride = 0;
  /// Fit the tail of the transient (SettlingSpeedFit) instead of a constant speed: the start
  /// is the first candidate whose settling fit is consistent with the noise (χ² within 2σ of
  /// its degrees of freedom). False: ref 000's constant-speed fit after the settling tests.
  bool transient_model = true;
  bool IsValid(std::string* error) const;
};

struct SteadySegment {
  int piece = -1;  ///< index into the pieces given
  SpeedFit fit;
  bool user_marked = false;
};

/// The settled tail of each constant-force piece, from positions (`is_position`) or measured
/// velocities. `known_sigma` is the sensor's noise (negative: estimated from residuals).
std::vector<SteadySegment> DetectSteadySegments(const Signal& s, bool is_position,
                                                const std::vector<ForcePiece>& pieces,
                                                const SteadyDetectionOptions& options,
                                                double known_sigma = -1.0);

}  // namespace uuvplan::ident
