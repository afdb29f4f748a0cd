// Inertia by the integral method with the drag known (ref 000 §III-B, eqs. 16–19).
//
// Integrating the model (3) from the start t_s of a run of samples removes the acceleration:
//
//   m·ξ(t) − c − b·(t − t_s) = y(t),   y(t) = ∫_{t_s}^{t} (η·φ − k·ξ − kq·ξ|ξ| + …) dt   (16)
//
// (c = m·ξ_s + k·χ_s collects the initial conditions, b the mean disturbance and the
// integration bias.) With every force term except the constant ones known (from the
// steady-state fit), y(t_i) = H_i·[m, c, b]ᵀ (eqs. 17–19) with H_i = [ξ_i, −1, −(t_i − t_s)].
// Runs are split at gaps and at large command steps (the filtered velocity is distorted
// across the kink of the acceleration); each run has its own c, each trial its own b.
// The filtered ξ̃ in H is noisy: corrected least squares removes the errors-in-variables
// bias, θ = (HᵀH − tr(MΣ)·e₀e₀ᵀ)⁻¹Hᵀy, Σ the velocity noise's covariance (sensor σ, the
// filter's weights, the noise's AR(1)) and M the projection off the nuisance columns c and b.
//
// Uncertainty: the residuals are correlated over the Savitzky–Golay window (ξ is filtered),
// so the textbook eqs. 11–12 σ is too small (notes/pitfalls.md). The reported σ_m combines the
// exact propagation of the sensor noise (first order, plus the errors-in-variables term's
// second order m²·tr(Σ²)/b²; a Newey–West σ when rows are thinned) with the propagated
// uncertainty of the known drag: m̂ is linear in the known parameters, ∂m̂/∂θ_j = g_mᵀ·Y_j with
// Y_j = ∫h_j, so σ_m² = σ_noise² + Jᵀ·Σ_known·J. The eqs. 11–12 σ is reported alongside.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/ident/estimate.h"
#include "uuvplan/ident/estimators/least_squares.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/model/dof_model.h"

namespace uuvplan::ident {

struct IntegralInertiaOptions {
  /// Newey–West lags in filter windows (lags = windows × SG window samples).
  double newey_west_windows = 2.0;
  /// Propagate the covariance of the known parameters into σ_m.
  bool propagate_known_uncertainty = true;
  /// Correct the errors-in-variables bias of the noisy filtered velocity in H (corrected
  /// least squares with the filter's known noise variance).
  bool errors_in_variables = true;
  /// With a measured velocity, use its samples (white noise of the declared σ, removed by the
  /// errors-in-variables correction) in H and in the drag integrals instead of the smoothed
  /// ones; the noise part of σ_m is then the exact propagation of that white noise (σ_white).
  bool raw_measured_velocity = true;
  /// Integration step for the regressor integrals (s).
  double max_step_s = 0.05;
  double max_condition = 1e8;
  bool IsValid(std::string* error) const;
};

struct IntegralInertiaResult {
  FitStatus status = FitStatus::kNoData;
  std::string message;
  double m = 0.0;
  double sigma = 0.0;       ///< reported σ_m (HAC ⊕ propagated)
  double sigma_eq11 = 0.0;  ///< ref 000 eqs. 11–12
  double sigma_hac = 0.0;   ///< Newey–West only
  double sigma_white =
      0.0;  ///< known white sensor noise propagated (raw measured velocity; 0 otherwise)
  /// Second-order errors in variables, √tr(Σ²)·|m̂|/b (part of sigma_white).
  double sigma_quadratic = 0.0;
  double sigma_known = 0.0;          ///< from the known parameters' covariance
  std::vector<double> run_c, run_b;  ///< per run of samples
  std::vector<int> run_trial;        ///< trial index of each run
  int num_samples = 0;
  double condition_number = 0.0;
  ParameterEstimate estimate;  ///< "m"
  std::vector<std::string> notes;
  bool ok() const { return status == FitStatus::kOk; }
};

/// Estimates m of `model` from `trials` with every other parameter at `theta` (its constant
/// terms, bias and bias_step, are re-estimated per run as b). `known_covariance` (model
/// layout, may be null) is the covariance of the known parameters.
IntegralInertiaResult IntegralInertiaFit(const model::DofModel& model,
                                         const std::vector<const TrialData*>& trials,
                                         const Eigen::VectorXd& theta,
                                         const Eigen::MatrixXd* known_covariance,
                                         const IntegralInertiaOptions& options);

}  // namespace uuvplan::ident
