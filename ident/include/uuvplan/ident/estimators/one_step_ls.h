// One-step integral least squares of refs 002 (eqs. 13–35) and 004 (eqs. 2–14).
//
// Dividing the model by m gives, per DOF (ref 002 eq. 4, Table 2):
//
//   dξ/dt = α·ξ + β·ξ|ξ| + γ·φ + δ,   α = −k/m, β = −kq/m, γ = 1/m, δ = bias/m
//
// and integrating between consecutive knots t_{k−1}, t_k of the filtered velocity ξ̃:
//
//   ξ̃(t_k) − ξ̃(t_{k−1}) = [∫ φ(ξ̃, φ) ds]·θ + ε_k                      (002 eqs. 20–26)
//
// stacked into Y = H·θ + ε (eqs. 27–34) and solved with measurement weights W⁻¹ (eq. 35);
// several DOFs at once with block weights Λ_k (ref 004 eqs. 4, 12–14). Generalised to the
// model's terms: ψ = [γ, θ_j/m …] where γ multiplies the known force (open-water thrust and
// fixed terms) and θ_j/m the integral of term j's regressor; the standard model gives
// α = −ψ_k, β = −ψ_kq, δ = ψ_bias. The physical parameters follow (002 Table 2) with their
// covariance by the delta method: m = 1/γ, θ_j = ψ_j/γ.
//
// Knots: the papers use every sample; with a noisy filtered velocity in the regressors that
// biases m low (errors in variables, notes/pitfalls.md), so by default knots are one
// Savitzky–Golay window apart (the endpoint errors of consecutive rows are then nearly
// independent, and the integrals of ξ̃ average the noise away). Rows share an endpoint, so
// the residuals are an MA(1) within each run (differenced endpoint noise plus the white errors
// of the integrals): the covariance estimates that structure instead of assuming white
// residuals, which overstates σ several-fold for position-derived velocities. With the
// instrumental variables (default) it is a sandwich over a heteroscedastic MA(1) fitted to the
// leverage-corrected residuals (Ma1VarianceModelCovariance): variance v_k = c0 + c1·A_k +
// c2·A_k², A_k = (∂F_k/∂ξ)·ψ the row's sensitivity to a velocity error held over it (the
// integral errors grow with the speed where the drag is quadratic), lag-1 correlation ρ pooled;
// without them (iv_iterations = 0) the homoscedastic MA(1) (CovarianceKind::kDifferenced). Rows
// never span a large command step (runs are split there), and rows are weighted by their trial's
// noise (trials filtered with different windows differ tenfold).
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/ident/estimate.h"
#include "uuvplan/ident/estimators/least_squares.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/model/dof_model.h"

namespace uuvplan::ident {

/// Ref 002 Table 2: physical parameters of the coefficients [α, β, γ, δ].
struct SeedCoefficients {
  double alpha = 0.0, beta = 0.0, gamma = 0.0, delta = 0.0;
};
struct PhysicalParameters {
  double m = 0.0;    ///< 1/γ
  double d_L = 0.0;  ///< −α/γ (k)
  double d_Q = 0.0;  ///< −β/γ (kq)
  double b = 0.0;  ///< −δ/γ: VSOR's disturbance, τ = m·ẋ + d_L·x + d_Q·x|x| + b (002 eq. 2)
  double bias = 0.0;  ///< δ/γ = −b: the contract's bias, m·ξ̇ = … + φ + bias
};
PhysicalParameters ToPhysical(const SeedCoefficients& c);
/// Jacobian ∂[m, d_L, d_Q, bias]/∂[α, β, γ, δ] for the delta method.
Eigen::Matrix4d ToPhysicalJacobian(const SeedCoefficients& c);

struct OneStepOptions {
  /// Knot spacing (s): 0 = every sample (refs 002/004); negative = one Savitzky–Golay window.
  double window_s = -1.0;
  /// Rows share their endpoint ξ̃(t_k) with the next row: the residuals are differences of a
  /// level noise, whose covariance is known up to σ² (kDifferenced); kNeweyWest and the
  /// seeds' kResidual (white residuals) are available.
  CovarianceKind covariance = CovarianceKind::kDifferenced;
  int newey_west_lags = 1;
  double max_step_s = 0.05;  ///< integration sub-step
  double max_condition = 1e8;
  /// Errors in variables: ξ̃ in the integrals is noisy, which biases the plain least squares
  /// (m high by 10% on VSOR-like data). Instrumental variables remove the bias: the same
  /// integrals along the velocity simulated by the current estimate (uncorrelated with the
  /// measurement noise) are the instruments, ψ = (ZᵀF)⁻¹ZᵀY, iterated `iv_iterations` times
  /// from the plain least-squares answer. The same simulation also corrects F, for measured
  /// velocities, for what the interpolation between samples misses (the ripple of a held
  /// command faster than the sensor: F += ∫h(ξ_sim) − ∫h(interpolated ξ_sim samples)).
  /// 0 = the papers' plain least squares.
  int iv_iterations = 2;
  double simulation_step_s = 0.02;  ///< for the instruments' simulations
  /// Runs of rows end at large command steps (the filtered velocity is distorted across the
  /// kink of the acceleration: SmoothRuns). Closed-loop commands step all the time, which would
  /// leave almost no row: the closed-loop estimator keeps them (its lagged instruments do not
  /// see a distortion at the row's own endpoints).
  bool split_at_force_jumps = true;
  bool IsValid(std::string* error) const;
};

/// The rows of one DOF's regression: Y = F·ψ, with the model indices of ψ's entries.
struct OneStepRows {
  Eigen::MatrixXd F;       ///< rows × (1 + free.size()): [∫known, ∫h_free…]
  Eigen::VectorXd Y;       ///< ξ̃(t_k) − ξ̃(t_{k−1})
  std::vector<double> t;   ///< knot time t_k of each row (trial time)
  std::vector<int> group;  ///< trial index of each row
  std::vector<int> run;    ///< run of each row (rows of a run share endpoints), unique
  /// 1/σ² of each row's noise (its trial's filtered-velocity noise, 2·(gain·σ_sensor)²): rows
  /// of trials filtered with different windows differ in noise by an order of magnitude.
  std::vector<double> weight;
  std::vector<int> free;     ///< model indices of ψ[1..]
  double noise_sigma = 0.0;  ///< σ of Y's noise (√2·σ of ξ̃), for weights
};

/// Builds the rows for `trials` of one DOF; `free` lists the model parameters to estimate
/// (regressor-linear, not m); all others take their value in `theta`.
OneStepRows BuildOneStepRows(const model::DofModel& model,
                             const std::vector<const TrialData*>& trials,
                             const Eigen::VectorXd& theta, const std::vector<int>& free,
                             const OneStepOptions& options);

/// The F of BuildOneStepRows (same knots) computed along `instrument` (one velocity per trial,
/// same order) instead of the measured velocities — the instruments Z — or, without it, along
/// the measured ones plus `velocity_shift` (RowSensitivity's difference). F alone: Y and the
/// rows' bookkeeping are the data's, not built again.
Eigen::MatrixXd OneStepRegressors(const model::DofModel& model,
                                  const std::vector<const TrialData*>& trials,
                                  const Eigen::VectorXd& theta, const std::vector<int>& free,
                                  const OneStepOptions& options,
                                  const std::vector<SmoothedSignal>* instrument,
                                  double velocity_shift = 0.0);

/// BuildOneStepRows without the `free` parameters no row excites (their names appended to
/// `not_excited`; they keep their value in `theta`); empty `free`: every regressor-linear one.
/// Without any row (trials too short for the knots) the regressors between consecutive samples
/// decide: a parameter a trial moves is excited, and the output error fits it.
OneStepRows ExcitedOneStepRows(const model::DofModel& model,
                               const std::vector<const TrialData*>& trials,
                               const Eigen::VectorXd& theta, std::vector<int> free,
                               const OneStepOptions& options,
                               std::vector<std::string>* not_excited);

struct OneStepDofInput {
  const model::DofModel* model = nullptr;
  std::vector<const TrialData*> trials;
  Eigen::VectorXd theta;  ///< values of the parameters not estimated
  std::vector<int> free;  ///< empty: every regressor-linear parameter
  double weight = 0.0;    ///< Λ for this DOF; 0: 1/noise_sigma²
};

/// The instruments of rows R (built for `in`) at the physical parameters `theta_now`: Z, the
/// rows along the velocity `theta_now` simulates from each trial's initial state, and R's F
/// corrected for the interpolation defect seen on that path (F + Z − Zs, Zs the rows at the
/// samples' times). False when a simulation diverges or the rows do not match.
/// Whether no coefficient moved from `before` to `after` by more than `fraction` of its σ (the
/// instrumental iterations' stop: 5%).
bool MovedLessThan(const Eigen::VectorXd& before, const Eigen::VectorXd& after,
                   const Eigen::MatrixXd& covariance, double fraction);

bool OneStepInstruments(const OneStepDofInput& in, const OneStepRows& R, const OneStepOptions& o,
                        const Eigen::VectorXd& theta_now, Eigen::MatrixXd* Z,
                        Eigen::MatrixXd* F_corrected);

struct OneStepDofResult {
  FitStatus status = FitStatus::kNoData;
  std::string message;
  std::vector<std::string> coefficient_names;  ///< "gamma", "<name>/m" …
  Eigen::VectorXd psi;
  Eigen::MatrixXd psi_covariance;
  bool standard = false;  ///< [α, β, γ, δ] available
  SeedCoefficients seed;  ///< when standard
  Eigen::Matrix4d seed_covariance = Eigen::Matrix4d::Zero();
  /// Physical parameters in the model's layout (m and the free ones estimated; others as given).
  std::vector<std::string> names;
  Eigen::VectorXd theta;
  Eigen::MatrixXd covariance;
  std::vector<ParameterState> state;
  std::vector<ParameterEstimate> estimates;  ///< m and the free parameters
  double condition_number = 0.0;
  std::vector<std::string> not_identifiable;
  std::vector<std::string>
      not_excited;  ///< free parameters whose regressor is zero in these trials
  Eigen::VectorXd residuals;
  int num_rows = 0;
  double cost = 0.0;          ///< J = (1/N)·Σ ε² (ref 004 eq. 5)
  bool instrumental = false;  ///< the estimate is the instrumental-variable one
  bool ok() const { return status == FitStatus::kOk; }
};

/// Ref 004: all DOFs in one stacked, weighted regression (block diagonal, so each DOF's
/// estimate equals its own weighted fit; the weights Λ matter only for a common cost).
std::vector<OneStepDofResult> OneStepLeastSquares(const std::vector<OneStepDofInput>& dofs,
                                                  const OneStepOptions& options);

/// Converts ψ (layout of OneStepRows) with covariance into physical parameters in model layout.
void PsiToPhysical(const model::DofModel& model, const Eigen::VectorXd& theta_given,
                   const std::vector<int>& free, const Eigen::VectorXd& psi,
                   const Eigen::MatrixXd& psi_cov, Eigen::VectorXd* theta, Eigen::MatrixXd* cov);

}  // namespace uuvplan::ident
