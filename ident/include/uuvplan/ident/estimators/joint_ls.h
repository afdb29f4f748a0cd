// One-step integral least squares of a multi-DOF model (model/multi_dof_model.h; ref 003's
// coupled horizontal model) from combined trials (ref 003 Table I's combined modes).
//
// Every DOF's equation is linear in θ once the velocities are measured: its force terms'
// regressors (force_term.h) are functions of measured velocities — the coupling term's columns
// products of them, tied to other DOFs' parameters (the inertias). Integrating equation i
// between knots t_a, t_b of the smoothed velocities ν̃ (Savitzky–Golay, ref 000 §IV-D) removes
// the derivative (ref 002 eqs. 20–26, ref 004 eqs. 2–14):
//
//   m_i·(ν̃_i(t_b) − ν̃_i(t_a)) + [∫ r_i(ν̃) ds]·θ = ∫ φ_i ds          (one row)
//
// The rows of every equation of every trial are stacked into y = H·θ + ε, each equation
// weighted by 1/σ² of its own residuals (N·s and N·m·s rows differ in scale), and solved:
//  1. weighted least squares (the papers' estimator);
//  2. instrumental variables: ν̃ is noisy and sits in H (errors in variables, which bias the
//     least squares), so the instruments Z are the same rows along the velocities the current
//     estimate simulates under the logged thrust (uncorrelated with the sensor noise),
//     θ = (ZᵀWH)⁻¹ZᵀWy, iterated `iv_iterations` times;
//  3. where the fit is non-physical, model selection (ref 000 §IV-D): the negative drag term
//     with the largest percentile error above 51.02% is dropped and 1–2 redone, until no drag
//     is both negative and insignificant. A quadratic drag the trials' speeds cannot tell from
//     the linear one is dropped rather than reported negative; a physical fit keeps every
//     term (dropping one of two collinear terms moves the other by many of its σ).
// Knots are one Savitzky–Golay window apart, so the endpoint errors of consecutive rows are
// nearly independent but shared: the residuals are MA(1) within an equation of a trial, and the
// covariance is the sandwich A⁻¹·ZᵀΩZ·A⁻ᵀ over that MA(1) (least_squares.h Ma1Covariance),
// not the white-residual s²·(HᵀH)⁻¹. The thrust is φ_i: the combined modes use their mappings
// in open-water directions (η = 1, ref 003 practical model); the model's other terms must be
// linear in θ and free of the thrust.
#pragma once

#include <Eigen/Dense>
#include <algorithm>
#include <string>
#include <vector>

#include "uuvplan/model/multi_dof_model.h"
#include "uuvplan/model/trial_log.h"
#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::ident {

struct JointLsOptions {
  int sg_order = 4;
  /// Savitzky–Golay window (points, odd); 0: SavitzkyGolayWindow of the sensor rate and the
  /// input's time scale.
  int sg_window = 0;
  int iv_iterations = 2;  ///< 0: the papers' plain (weighted) least squares
  double step_s = 0.02;   ///< sub-step of the rows' integrals and the instruments' simulation
  /// Step 3: drop a negative, insignificant drag term (percentile error above 51.02%, ref 000
  /// §IV-D; never a DOF's last drag term) and refit, until none is left.
  bool prune = true;
  bool IsValid(std::string* error) const;
};

enum class JointLsStatus { kOk, kNoData, kTooFewData, kIllConditioned, kNonPhysical };
inline constexpr model::EnumNames<JointLsStatus, 5> kJointLsStatusNames{{{
    {JointLsStatus::kOk, "ok"},
    {JointLsStatus::kNoData, "no data"},
    {JointLsStatus::kTooFewData, "too few data"},
    {JointLsStatus::kIllConditioned, "ill-conditioned"},
    {JointLsStatus::kNonPhysical, "non-physical"},
}}};

struct JointLsResult {
  JointLsStatus status = JointLsStatus::kNoData;
  std::string message;
  std::vector<std::string> names;  ///< the model's global θ ("surge.m", …)
  std::vector<std::string> units;
  Eigen::VectorXd theta;
  Eigen::MatrixXd covariance;
  int num_rows = 0;
  double condition_number = 0.0;  ///< of the column-scaled weighted H
  bool instrumental = false;      ///< θ is the instrumental-variable estimate
  /// Terms dropped as insignificant (θ and covariance 0 there), with the estimate and σ they
  /// had in the last fit that kept them.
  struct Dropped {
    int index = -1;
    double value = 0.0, sigma = 0.0;
  };
  std::vector<Dropped> dropped;
  bool IsDropped(int j) const {
    return std::any_of(dropped.begin(), dropped.end(),
                       [j](const Dropped& d) { return d.index == j; });
  }
  std::vector<std::string> notes;
  bool ok() const { return status == JointLsStatus::kOk; }
  double Sigma(int j) const { return std::sqrt(covariance(j, j)); }
};

/// The estimate of `model`'s θ from combined trial logs (the force_ and vel_ columns of each of
/// its DOFs).
JointLsResult JointOneStepLeastSquares(const model::MultiDofModel& model,
                                       const std::vector<const model::TrialLog*>& trials,
                                       const JointLsOptions& options);

}  // namespace uuvplan::ident
