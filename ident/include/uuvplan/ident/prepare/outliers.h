// Outliers (sonar multipath, ref 000 Fig. 14) and gaps (drop-outs, ref 000 Fig. 14 "missing
// sonar measurements") in a sampled signal. Each sample is predicted by a local quadratic fitted
// to its neighbours (itself left out) between the same command steps; a sample whose residual
// exceeds `threshold` robust standard deviations (1.4826·MAD of all residuals, at least
// `noise_floor` known σ) by more than the allowed truncation is an outlier. The truncation is
// |quadratic − quartic| through the same neighbours (and through them without the worst one)
// beyond that limit: neither prediction sees the sample, so a spike shows, while fast motion
// measured by a precise sensor is followed by the quartic. The neighbourhoods of flagged
// samples are re-tested, so an outlier does not hide its neighbour. Excluded samples are
// reported, never dropped silently.
#pragma once

#include <string>
#include <vector>

#include "uuvplan/ident/prepare/velocity_estimation.h"

namespace uuvplan::ident {

struct OutlierOptions {
  int half_window = 5;     ///< neighbours on each side used for the prediction
  double threshold = 6.0;  ///< robust standard deviations
  /// Residuals smaller than this many known noise σ are never outliers (0: no floor).
  double noise_floor = 4.0;
  /// A residual beyond the noise limit is allowed this many times the quadratic's truncation
  /// error beyond that limit, (|quadratic − quartic| − limit)₊ (0: the plain quadratic test).
  /// Positions of a precise sensor need it: after a command step their truncation error
  /// exceeds the noise a hundredfold, and a 1 µm camera on URIS lost 27–60% of its samples.
  double truncation_allowance = 2.0;
  /// More than this fraction of a signal's samples excluded is itself a finding (a sensor
  /// fault, a unit or timing mistake, or motion the test takes for noise): reported as a
  /// warning of the DOF, with the count and the trial.
  double finding_fraction = 0.05;
  bool IsValid(std::string* error) const;
};

struct Outlier {
  std::size_t index = 0;  ///< in the input signal
  double t = 0.0;
  double value = 0.0;
  double residual = 0.0;  ///< measured − predicted
};

/// Command steps in a signal's record: the motion is smooth between them, and at each the
/// acceleration jumps (a kink in velocity, a jump of curvature in position).
struct CommandSteps {
  std::vector<double> t;        ///< times of the steps, sorted
  double protect_radius = 0.0;  ///< samples this close to a step are never outliers (s)
};

/// The outliers of `s` (sorted by index). `known_sigma` (<= 0: unknown) sets the noise floor.
/// With `steps`, each sample is predicted from the neighbours between the same two steps
/// (where at least 4 are), and those within `protect_radius` of a step are not tested.
std::vector<Outlier> DetectOutliers(const Signal& s, const OutlierOptions& options,
                                    double known_sigma = -1.0, const CommandSteps* steps = nullptr);

/// The warning for `excluded` of `total` samples of `signal` ("velocity") of `trial` excluded,
/// or "" when at most `options.finding_fraction` of them.
std::string OutlierFinding(const std::string& trial, const std::string& signal,
                           std::size_t excluded, std::size_t total, const OutlierOptions& options);

/// `s` without the given samples.
Signal RemoveSamples(const Signal& s, const std::vector<Outlier>& outliers);

struct Gap {
  double t0 = 0.0;  ///< last sample before the gap
  double t1 = 0.0;  ///< first sample after it
};

/// Steps longer than `factor` × the median step.
std::vector<Gap> FindGaps(model::TimesView t, double factor = 3.0);

}  // namespace uuvplan::ident
