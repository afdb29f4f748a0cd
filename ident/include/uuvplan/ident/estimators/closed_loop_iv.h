// Identification under feedback: instrumental variables on the one-step integral rows, with the
// rows d knots earlier as instruments (docs/identification.md, "Closed-loop data").
//
// The one-step rows (refs 002/004) are Y_k = ξ̃(t_k) − ξ̃(t_{k−1}) = F_k·ψ + e_k, F_k the
// integrals over [t_{k−1}, t_k] of the commanded force and of the regressors along the
// measured velocity. Under feedback the command reacts to the measured velocity, so ∫φ in F_k
// carries the noise of ξ̃ at t_{k−1}, which is also in e_k: least squares (and the output
// error, which simulates from that command) is biased. The rows d knots earlier,
//
//   Z_k = [F_{k−d}, …, F_{k−d−L+1}]   (the commanded force and the measured motion up to t_{k−d}),
//
// are correlated with F_k through the vehicle's own dynamics (its time constant spans several
// knots) but not with e_k once d exceeds the correlation length of e (d = that length + 1, at
// least 2: rows share an endpoint). The estimate is the two-stage least squares
// ψ = (X̂ᵀF)⁻¹X̂ᵀY, X̂ = Z(ZᵀZ)⁻¹ZᵀF (Söderström & Stoica,
// "System Identification" §8: lagged inputs and outputs as instruments, valid when the noise
// is a moving average shorter than the lag) and its covariance the sandwich A⁻¹·X̂ᵀΩX̂·A⁻ᵀ,
// A = X̂ᵀF, Ω the MA(1) of the rows' residuals (consecutive rows share a knot), as the one-step
// least squares (least_squares.h Ma1VarianceModelCovariance). The same lag removes the
// errors-in-variables bias of the noisy ξ̃ in F. The rows are weighted per trial by the inverse of
// the trial's residual variance at a first pass weighted by the sensor (feasible GLS, two steps),
// since on real logs model error and disturbances, not the sensor, set the rows' error.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/ident/estimators/one_step_ls.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/ident/stats/model_selection_options.h"
#include "uuvplan/model/dof_model.h"

namespace uuvplan::ident {

struct ClosedLoopIvOptions {
  int min_lag_knots = 2;   ///< rows share an endpoint: a lag of 1 is never valid
  int max_lag_knots = 16;  ///< longer lags leave instruments too weak to be of use
  /// Knot spacing of the rows (s; the one-step default, one filter window, leaves ~20 rows in a
  /// minute of tartan surge): more rows, and a lag in knots chosen from their correlation.
  double knot_s = 0.5;
  /// Instruments: the rows d, d + 1, …, d + L − 1 knots earlier (L lags, over-identified for
  /// L > 1: two-stage least squares, whose projected regressors are the instruments). One lag
  /// alone is weak where ξ and ξ|ξ| move together (tartan: correlation 0.9).
  int instrument_lags = 4;
  /// Two-step weights: each trial's rows by 1/(its mean squared first-pass residual), not by
  /// its sensor's noise (closed_loop_iv.cc WeightTrialsByResiduals; docs/identification.md).
  bool weight_by_residuals = true;
  ModelSelectionOptions selection;
  bool IsValid(std::string* error) const;
};

struct ClosedLoopIvResult {
  OneStepDofResult fit;            ///< ψ, physical θ, covariance, estimates (one-step layout)
  int lag_knots = 0;               ///< d
  int instrument_lags = 1;         ///< L
  double lag_s = 0.0;              ///< d in seconds (mean knot spacing × d)
  bool residual_weights = false;   ///< the rows weighted by their trial's residuals
  std::vector<std::string> notes;  ///< model selection's (insignificant parameters kept)
  bool ok() const { return fit.ok(); }
};

/// The closed-loop estimate of `model`'s m and regressor-linear parameters from `trials`
/// (every other parameter at `theta`), with the one-step rows of `one_step`.
ClosedLoopIvResult ClosedLoopInstrumentalFit(const model::DofModel& model,
                                             const std::vector<const TrialData*>& trials,
                                             const Eigen::VectorXd& theta,
                                             const OneStepOptions& one_step,
                                             const ClosedLoopIvOptions& options);

}  // namespace uuvplan::ident
