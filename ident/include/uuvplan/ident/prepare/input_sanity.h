// Unit and sign sanity of a campaign's logs, checked before any identification:
// the mistakes that identification would otherwise fit without complaint.
//
//  - rate vs angle: the logged rate against the derivative of the logged position (too noisy:
//    the rate's integral against the position's changes over windows). A ratio of
//    180/π = 57.3 names degrees (vel_ in deg/s, or pos_ in degrees when the ratio is 1/57.3),
//    −1 an opposite sign convention, any other ratio far from 1 different units; a rotational
//    rate whose 99th percentile exceeds one turn per second is in degrees (no pool vehicle
//    turns that fast).
//  - position vs velocity: a pos_ column that follows vel_ instead of integrating it, or (no
//    vel_ column) whose force balance reads as a velocity's — m·dx/dt + k·x explains the logged
//    force far better than m·d²x/dt² + k·dx/dt, with m, k > 0 — holds a velocity.
//  - thrust sign vs motion: F = m·a + c·ν + b fitted to the logged force and the measured motion
//    gives m < 0 and c < 0 (the force and the motion it causes have opposite signs).
//  - a stuck sensor: a pos_ or vel_ column whose every value is the same while the force
//    commands thrust.
// Each finding names the trial's file, the column and the likely unit or fix. The checks look
// at each trial's own DOF (the one identified from it).
#pragma once

#include <string>
#include <vector>

#include "uuvplan/model/campaign.h"

namespace uuvplan::ident {

struct InputSanityOptions {
  /// |correlation| of the rate with the position's derivative needed before their ratio is
  /// read (below it, the motion is too small against the noise to tell). Below it, the ratio
  /// is read from the position's changes over windows of `increment_window_s` against the
  /// rate's integral over the same windows (noise averages out of an integral, not out of a
  /// derivative) when those agree in direction as closely (cosine ≥ min_correlation).
  double min_correlation = 0.8;
  double increment_window_s = 2.0;
  /// A ratio within ×/÷ this of 180/π (or of −1) names degrees (or a flipped sign).
  double ratio_tolerance = 1.3;
  /// A ratio outside [1/limit, limit] (and not one of the above): different units.
  double unit_ratio_limit = 2.0;
  /// Rotational rate above which (99th percentile of |rate|) the column is in degrees (rad/s).
  double max_rate = 6.283185307179586;
  /// A pos_ column follows its vel_ column when |corr(vel, pos)| reaches this while
  /// |corr(vel, d pos/dt)| stays below half of min_correlation.
  double follow_correlation = 0.9;
  /// The force balance that names a column (R²) must reach this, and beat the other by margin.
  double min_fit = 0.5;
  double fit_margin = 0.3;
  /// The sign fit must explain this much of the force (R²) before its signs are read.
  double min_sign_fit = 0.3;
  bool IsValid(std::string* error) const;
};

/// One finding: the trial's file (as resolved), the column, what the data show and the fix.
struct InputProblem {
  std::string file;
  std::string column;  ///< "vel_yaw"
  std::string finding;
  std::string fix;
  /// "<file>: column <column>: <finding> — <fix>".
  std::string Text() const;
};

/// The unit and sign problems of every trial of `campaign` (empty: none found).
std::vector<InputProblem> CheckInputSanity(const model::Campaign& campaign,
                                           const InputSanityOptions& options = {});
/// As above, with the logs' columns lent to the check instead of copied (the all-finite ones,
/// else one with few gaps compacted in place) and given back bit for bit before it returns, on
/// an exception too: a long log's check holds no second copy of it.
std::vector<InputProblem> CheckInputSanity(model::Campaign* campaign,
                                           const InputSanityOptions& options = {});

}  // namespace uuvplan::ident
