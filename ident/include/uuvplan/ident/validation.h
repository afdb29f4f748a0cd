// How well an identified model reproduces a trial (what users look at):
//  - free-run simulation of the trial from its initial state with the logged force, compared
//    with the measurement: the velocity mean absolute error of ref 002 eq. 37,
//    e = mean(|ν_model − ν_measured|), and the position RMS error;
//  - residual analysis as ref 004 §5.2: mean, standard deviation, normalised autocorrelation
//    with its 95% bounds ±1.96/√N (white unless more lags fall outside than white noise puts
//    there 99% of the time: 3 of 20), and a histogram summary (bins, skewness, kurtosis).
// Done on `fit` and `validate` trials alike, for cross-validation across trials (002 §6.1).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/model/campaign.h"
#include "uuvplan/model/dof_model.h"

namespace uuvplan::ident {

struct Histogram {
  std::vector<double> edges;  ///< bins + 1 edges
  std::vector<int> counts;
  double skewness = 0.0;
  double excess_kurtosis = 0.0;
};

struct ResidualAnalysis {
  int n = 0;
  double mean = 0.0;
  double std = 0.0;
  double rms = 0.0;
  std::vector<double> autocorrelation;  ///< lags 0..max_lag (lag 0 = 1)
  double bound95 = 0.0;                 ///< 1.96/√n
  int lags_outside = 0;                 ///< lags 1..max_lag with |ρ| > bound95
  bool white = false;                   ///< lags_outside <= 99% quantile of Binomial(lags, 0.05)
  double lag_step_s = 0.0;              ///< time between residual samples (median)
  Histogram histogram;
};

/// Residual statistics of `r` (samples `step_s` apart) up to `max_lag` lags, `bins` bins.
/// Instantiated for double and float (a long trial's residuals kept in float: their rounding,
/// 6e-8 relative, is far below the smallest figure reported, the bound 1.96/√n ≥ 2e-3 of a
/// million samples).
template <class Real>
ResidualAnalysis AnalyzeResiduals(const std::vector<Real>& r, int max_lag = 20, int bins = 11,
                                  double step_s = 0.0);
extern template ResidualAnalysis AnalyzeResiduals(const std::vector<double>&, int, int, double);
extern template ResidualAnalysis AnalyzeResiduals(const std::vector<float>&, int, int, double);

struct ValidationOptions {
  double step_s = 0.02;  ///< RK4 step of the free-run simulation
  int max_lag = 20;
  int bins = 11;
  /// Keep the free run beside the measurement at up to this many sample times (evenly
  /// decimated) in TrialFit::curve, for figures; 0 keeps nothing.
  int curve_points = 0;
};

/// The measured and simulated signal (the one the residuals are of) at a trial's sample times.
struct FreeRunCurve {
  std::vector<double> t;          ///< s from the trial's start
  std::vector<double> measured;   ///< m or rad (position), m/s or rad/s (velocity)
  std::vector<double> simulated;  ///< the free run at the same times
};

struct TrialFit {
  int trial = -1;
  std::string name;
  model::TrialUse use = model::TrialUse::kFit;
  double velocity_mae = 0.0;  ///< ref 002 eq. 37 (m/s or rad/s)
  int velocity_samples = 0;
  /// The same error of the zero-velocity model (ν ≡ 0: mean |ν_measured|) on the same samples:
  /// the baseline a usable model must beat (docs/identification.md, "Failure statuses").
  double zero_velocity_mae = 0.0;
  /// "measured" (vel_ column) or "estimated" (Savitzky–Golay derivative of the positions).
  std::string velocity_reference;
  double position_rms = 0.0;  ///< m or rad; NaN without positions
  int position_samples = 0;
  ResidualAnalysis residuals;   ///< of the position (if measured) else velocity errors
  std::string residual_signal;  ///< "position" or "velocity"
  FreeRunCurve curve;           ///< with ValidationOptions::curve_points > 0, else empty
  double initial_position = 0.0, initial_velocity = 0.0;  ///< the free run's initial state
};

/// Free-run simulation of `trial` with `theta` from an initial state taken from the data
/// (smoothed position and velocity at t = 0, or the given x0) and its scores.
TrialFit ValidateTrial(const model::DofModel& model, const Eigen::VectorXd& theta,
                       const TrialData& trial, const ValidationOptions& options,
                       const Eigen::VectorXd* x0 = nullptr);

struct FitSummary {
  std::vector<TrialFit> trials;
  /// Pooled over the samples of the trials of each use (NaN when none).
  double velocity_mae_fit = 0.0, velocity_mae_validate = 0.0, velocity_mae_all = 0.0;
  double position_rms_fit = 0.0, position_rms_validate = 0.0, position_rms_all = 0.0;
  /// The zero-velocity model's velocity MAE, pooled the same way (the baseline to beat).
  double zero_velocity_mae_fit = 0.0, zero_velocity_mae_validate = 0.0;
};
FitSummary Summarize(std::vector<TrialFit> trials);

}  // namespace uuvplan::ident
