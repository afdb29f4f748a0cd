// The model's force as a regression on its parameters, for the least-squares estimators. With
// theta laid out as model::DofModel::parameter_names():
//
//   Σ_j F_j(ξ, φ_a, context; θ_j) = h·θ + h0
//
// where h holds the regressors of the terms that are linear in their parameters
// (ForceTerm::Regressor) and zero for m and for parameters of non-linear terms, and h0 holds
// the known part (the open-water thrust, η = 1) plus the value of every non-linear term at
// fixed parameter values. Along a measured trial, the integrals of h and h0 over time
// intervals are the columns of the integral methods (ref 000 eq. 16, ref 002 eqs. 20–23,
// ref 004 eq. 10).
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/model/dof_model.h"

namespace uuvplan::ident {

/// Indices in theta of the parameters of regressor-linear terms (never m).
std::vector<int> LinearParameters(const model::DofModel& model);

/// h (num_parameters entries) and h0 at one context; `theta` supplies the values of the
/// parameters of non-linear terms (and is not read for linear ones).
void EvaluateRegressor(const model::DofModel& model, const model::TermInputs& context,
                       const Eigen::VectorXd& theta, double* h, double* h0);

/// The term context of a trial at time t with velocity xi (the actuator force is the held
/// command through the model's dead zone at `theta`; thruster lag is not represented).
model::TermInputs MeasuredTermInputs(const model::DofModel& model, const TrialData& trial, double t,
                                     double xi, const Eigen::VectorXd& theta);

/// Integrals of h and h0 along a trial's estimated velocity over the intervals
/// [b_{i}, b_{i+1}] of `boundaries` (sorted, within [0, duration]). H is (intervals ×
/// num_parameters), h0 has one entry per interval. Two-point Gauss–Legendre on a grid that
/// includes every input breakpoint (so the held force is integrated exactly) and steps of at
/// most max_step_s.
struct IntegratedRegressors {
  Eigen::MatrixXd H;
  Eigen::VectorXd h0;
};
/// `velocity` (may be null: the trial's velocity_estimate) replaces the measured velocity, e.g.
/// by a simulated one to build instrumental variables: its `value` is the velocity and its
/// `derivative` (may be empty: linear interpolation) the acceleration at its times.
/// `velocity_shift` is added to that velocity (a velocity error held over the trial).
IntegratedRegressors IntegrateRegressors(const model::DofModel& model, const TrialData& trial,
                                         model::TimesView boundaries, const Eigen::VectorXd& theta,
                                         double max_step_s,
                                         const SmoothedSignal* velocity = nullptr,
                                         double velocity_shift = 0.0);

}  // namespace uuvplan::ident
