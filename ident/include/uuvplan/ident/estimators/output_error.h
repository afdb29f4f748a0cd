// Output-error (maximum-likelihood) refinement: the free-run simulation of every trial is fitted
// to the measured positions and velocities, beyond the papers' equation-error methods.
//
//   min_z  ½ Σ_trials Σ_i ((y_i − ŷ_i(z)) / σ_i)²,   z = [θ_free, χ0 and ξ0 of each trial]
//
// ŷ = model::SimulateMeasured (RK4 with the forward sensitivities S = ∂x/∂θ); ∂ŷ/∂χ0 = 1 for
// positions; ∂ŷ/∂ξ0 by a finite difference (ξ0 is only estimated for trials that do not start
// at rest). Levenberg–Marquardt with Marquardt's diagonal scaling, started from the
// least-squares answer; steps leaving the admissible set (m, lag > 0; dead zone, delay >= 0)
// are rejected. With Gaussian white noise of the declared σ this is the maximum-likelihood
// estimate: no errors-in-variables bias (no velocity is differentiated), and its covariance
//
//   Cov(z) = s²·(JᵀJ)⁻¹,   J = ∂r/∂z,  s² = ‖r‖²/(N − P)
//
// tends to the Cramér–Rao bound (JᵀJ)⁻¹ computed from the same sensitivities at the truth. When
// the residuals are not white (model error, real data) an autocorrelation-robust sandwich is
// used instead (the scores prewhitened by an AR(1) of the residuals per trial and sensor, then
// batch means: covariance.h; never below the white-noise covariance), and said so. Sensor samples
// faster than the RK4 step are averaged into one-step bins (weight √n/σ) before fitting.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/ident/estimate.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/ident/stats/model_selection_options.h"
#include "uuvplan/model/dof_model.h"

namespace uuvplan::ident {

/// Each trial's initial velocity ξ0: kAuto fixes it at 0 where the first samples say the trial
/// starts at rest (TrialData::starts_at_rest) and estimates it elsewhere — and estimates every
/// one when the fit refutes those starts (a score test of the fixed ξ0 at P < 1e-4,
/// docs/identification.md §6); kZero fixes every one at 0; kEstimate estimates every one.
enum class InitialVelocity { kAuto, kZero, kEstimate };

struct OutputErrorOptions {
  int max_iterations = 40;
  double tolerance = 1e-8;  ///< relative decrease of the cost and of the step to stop
  double step_s = 0.02;     ///< RK4 step of the simulations (s)
  /// Samples closer than half this are averaged into bins this long (s): the mean is a
  /// sufficient statistic while the motion is linear across a bin (τ of 0.3 s and more).
  double bin_s = 0.02;
  /// Dense measurements (more sample times than this grid has points): the simulation reports
  /// the state only on a grid of every input breakpoint and points at most grid_s apart (its RK4
  /// steps stay <= step_s), and is interpolated to the sample times: cubic Hermite for position
  /// and velocity (dx/dt from the model; error ~ grid_s^4·|d⁴x/dt⁴|/384), linear for the
  /// sensitivities (they only steer the iterations and set the covariance: relative error
  /// ~ (grid_s/τ)²/8). Not used with a sensor delay. 0 = always simulate at the sample times.
  double grid_s = 0.05;
  InitialVelocity initial_velocity = InitialVelocity::kAuto;
  bool use_position = true;
  bool use_velocity = true;
  /// Residual lag-1 autocorrelation above which the covariance switches to the prewhitened
  /// sandwich (covariance.h). 0.1: AR(1) noise of ρ = 0.1 makes the white-noise σ 10% small
  /// ((1 + ρ)/(1 − ρ) = 1.22 in variance, 95% intervals cover ~92%); lower would switch on the
  /// scatter of a white residual's lag-1 (±2/√n, 0.06 at 1000 residuals).
  double whiteness_threshold = 0.1;
  ModelSelectionOptions selection;
  double max_condition = 1e12;
  /// Multi-resolution start for long records: with more than 2× this many measurements, the
  /// fit first runs on bins of about duration/coarse_measurements s (RK4 step up to 5× step_s,
  /// at most 0.1 s), and Levenberg–Marquardt on every measurement starts where that stopped,
  /// so the full-size simulations only polish (a 10⁶-sample trial: 2 instead of 6). The answer
  /// is the full-size fit's, judged by its own convergence test. 0 = off.
  int coarse_measurements = 100000;
  bool IsValid(std::string* error) const;
};

enum class OutputErrorStatus { kConverged, kMaxIterations, kIllConditioned, kFailed };
std::string_view OutputErrorStatusName(OutputErrorStatus s);

/// Initial state of a trial as estimated (or fixed).
struct TrialInitialState {
  int trial = -1;
  double chi0 = 0.0, xi0 = 0.0;
  bool chi0_estimated = false, xi0_estimated = false;
};

struct OutputErrorResult {
  OutputErrorStatus status = OutputErrorStatus::kFailed;
  std::string message;
  std::vector<std::string> names;  ///< model layout
  Eigen::VectorXd theta;
  Eigen::MatrixXd covariance;  ///< model layout, zero for fixed/dropped parameters
  Eigen::MatrixXd crb;         ///< (JᵀJ)⁻¹ at the solution with the declared σ (model layout)
  std::vector<ParameterState> state;
  std::vector<ParameterEstimate> estimates;  ///< estimated and dropped parameters
  std::vector<TrialInitialState> initial;
  int iterations = 0;
  double cost = 0.0;    ///< ½‖r‖²
  double sigma2 = 0.0;  ///< s²
  int num_residuals = 0;
  double condition_number = 0.0;
  std::vector<std::string> not_identifiable;
  double residual_lag1 = 0.0;  ///< mean lag-1 autocorrelation of the residuals
  bool hac_covariance = false;
  std::vector<std::string> notes;
  bool ok() const {
    return status == OutputErrorStatus::kConverged || status == OutputErrorStatus::kMaxIterations;
  }
};

/// Refines `theta0` on `trials` (all of one DOF). Parameters whose `state0` is kEstimated are
/// free; the others keep their value in theta0 (kDropped ones stay dropped).
OutputErrorResult OutputErrorFit(const model::DofModel& model,
                                 const std::vector<const TrialData*>& trials,
                                 const Eigen::VectorXd& theta0,
                                 const std::vector<ParameterState>& state0,
                                 const OutputErrorOptions& options);

/// The fitted initial state (χ0, ξ0) of trial `trial` when its initial velocity was estimated
/// (the trial starts moving), else empty: a free run of a moving trial from the data alone starts
/// at the noisy edge of a filter and drifts by that error times the trial's length.
Eigen::VectorXd FittedMovingStart(const OutputErrorResult& fit, int trial);

/// The Cramér–Rao bound of the free parameters (model layout; zero elsewhere) for these trials'
/// sample times, inputs and declared noise, at `theta`, with the same nuisance parameters as
/// OutputErrorFit would estimate (initial position; initial velocity when `initial` says so).
/// `initial` may be empty (rest at the first sample, positions' offset free).
Eigen::MatrixXd CramerRaoBound(const model::DofModel& model,
                               const std::vector<const TrialData*>& trials,
                               const Eigen::VectorXd& theta,
                               const std::vector<ParameterState>& state,
                               const std::vector<TrialInitialState>& initial,
                               const OutputErrorOptions& options);

}  // namespace uuvplan::ident
