// Drag, bias, ballast step and installation coefficients from steady-state tests
// (ref 000 §III-A, eqs. 7–12 and eq. 20).
//
// At a steady speed ξ* under a constant nominal force φ the model (3) reduces to (7):
//
//   0 = −k·ξ* − kq·ξ*|ξ*| + η(μ, sign φ)·φ + bias (+ i·ΔW, eq. 20)
//
// Every steady segment is one row of y = H·theta (eqs. 8–10): the known part (open-water
// thrust, η = 1) goes to y with its sign changed, each regressor-linear parameter gets a column
// (ref 000: θ = [k, kq, bias, η(μ₁)…η(μ_M)], heave: [k, kq, W, ΔW, η]). The terms and their
// regressors come from the model (ForceTerm::Regressor), so any structure whose terms are
// linear in their parameters is handled the same way (e.g. asymmetric drag, coupling).
//
// The noise is in the measured speeds ξ* (a regressor), not in y: by default each row is
// weighted by 1/σ_i², σ_i = |∂F/∂ξ|·σ_ξ* (effective variance, iterated from the OLS answer);
// ref 000 uses plain OLS with the covariance of eqs. 11–12 (Weighting::kNone,
// CovarianceKind::kResidual). Model selection (ref 000 §IV-D): while some prunable parameter
// has a percentile error above 51.02% it is insignificant at 95%; the worst is dropped (fixed
// to 0) and the rest refitted (Table III: yaw quadratic drag at low speed).
#pragma once

#include <Eigen/Dense>
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "uuvplan/ident/estimate.h"
#include "uuvplan/ident/estimators/least_squares.h"
#include "uuvplan/ident/prepare/steady_detection.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/ident/stats/model_selection_options.h"
#include "uuvplan/model/dof_model.h"

namespace uuvplan::ident {

/// One steady-state segment: its speed (with σ), the constant force and mapping, and the
/// conditions of its trial.
struct SteadyPoint {
  int trial = -1;             ///< campaign trial index
  double t0 = 0.0, t1 = 0.0;  ///< segment in trial time (s)
  double xi = 0.0;
  double sigma_xi = 0.0;
  double phi = 0.0;  ///< nominal force
  int mapping = -1;  ///< vehicle mapping index
  int ballast_steps = 0;
  double t_campaign = 0.0;                           ///< mid-segment on the campaign clock
  std::array<double, model::kNumDofs> velocities{};  ///< other DOFs at mid-segment
  bool user_marked = false;
  bool from_position = true;
  double noise_ar1 = 0.0;  ///< AR(1) ρ of the sensor's noise (PooledNoiseAr1), in sigma_xi
};

/// Steady segments of a trial: detected in every constant-force piece, or the user's windows
/// (trial time, s) when given (then no detection is done for that trial).
std::vector<SteadyPoint> SteadyPoints(
    const TrialData& trial, const SteadyDetectionOptions& options, double force_tolerance,
    const std::vector<std::pair<double, double>>* user_windows = nullptr);

/// Second pass over the steady speeds once a model is known: each point's segment is re-fitted
/// with the settling model at τ = m/k_L (k_L = −∂F/∂ξ at the point, ref 000 eq. 13) from
/// `theta`, which removes the transient tail without the imprecision of a free τ.
void RefineSteadyPoints(const model::DofModel& model, const Eigen::VectorXd& theta,
                        const std::vector<const TrialData*>& trials,
                        std::vector<SteadyPoint>* points);

struct SteadyStateOptions {
  SteadyDetectionOptions detection;
  enum class Weighting { kNone, kVelocityVariance };
  Weighting weighting = Weighting::kVelocityVariance;
  /// max(1, s²)·(HᵀWH)⁻¹: the points' σ from a segment's lag-1 under-resolves strongly coloured
  /// noise (ρ = 0.9: VSOR sd/σ 1.4–2.6 with kConservative, whose χ² test rarely fires on the
  /// few degrees of freedom of a steady-state fit).
  CovarianceKind covariance = CovarianceKind::kKnownNoiseAtLeast;
  ModelSelectionOptions selection;
  double max_condition = 1e8;
  int reweight_iterations = 3;
  bool IsValid(std::string* error) const;
};

enum class SteadyStatus { kOk, kTooFewSegments, kIllConditioned, kNotExcited };
std::string_view SteadyStatusName(SteadyStatus s);

struct SteadyStateResult {
  SteadyStatus status = SteadyStatus::kNotExcited;
  std::string message;
  std::vector<std::string> names;            ///< the model's parameter names (theta layout)
  Eigen::VectorXd theta;                     ///< model layout; non-estimated entries as given
  Eigen::MatrixXd covariance;                ///< model layout; zero for non-estimated entries
  std::vector<ParameterState> state;         ///< per model parameter
  std::vector<ParameterEstimate> estimates;  ///< the estimated and dropped parameters
  int num_points = 0;
  double sigma2 = 0.0;  ///< weighted residual variance s² (eq. 12)
  double condition_number = 0.0;
  std::vector<std::string> not_identifiable;  ///< in a near-null combination
  std::vector<std::string> not_excited;       ///< no steady segment informs them
  std::vector<double> residuals;              ///< force residuals (N or N·m) per point
  std::vector<std::string> notes;
  bool ok() const { return status == SteadyStatus::kOk; }
  /// True when parameter `name` was estimated (not fixed, not dropped).
  bool Estimated(const std::string& name) const;
};

/// Fits the regressor-linear parameters of `model` (except m) to the steady points;
/// `theta` supplies the values of every other parameter.
SteadyStateResult SteadyStateFit(const model::DofModel& model,
                                 const std::vector<SteadyPoint>& points,
                                 const Eigen::VectorXd& theta, const SteadyStateOptions& options);

}  // namespace uuvplan::ident
