// Stage 2 of identifying a DOF, estimate: the least-squares answer that starts the refinement.
// Steady-state segments give the drag, bias, ballast step and installation coefficients
// (seed 000 eqs. 7–12, 20) and, with the drag known, the integral method gives m (eqs. 16–19);
// the one-step integral least squares of every regressor-linear parameter (seeds 002/004)
// answers when there is no steady state, and supplies m when the integral method fails.
#include <algorithm>

#include "identify_stages.h"
#include "number_text.h"
#include "uuvplan/ident/regression.h"
#include "uuvplan/model/effects.h"

namespace uuvplan::ident::stages {
namespace {

// The steady points of every fit trial (detected, or in the user's windows); returns the
// number of constant-force legs long enough to settle, for the note when none did.
int CollectSteadyPoints(const DofContext& c, const IdentifyOptions& o, DofIdentification* r) {
  int long_pieces = 0;
  for (const TrialData* d : c.trials.fit) {
    const auto w = o.steady_windows.find(d->index);
    std::vector<std::pair<double, double>> windows;
    if (w != o.steady_windows.end()) {
      for (const auto& [a, b] : w->second) windows.push_back({a - d->time_offset, b - d->time_offset});
    }
    auto pts = SteadyPoints(*d, c.steady.detection, o.data.force_tolerance,
                            windows.empty() ? nullptr : &windows);
    r->steady_points.insert(r->steady_points.end(), pts.begin(), pts.end());
    for (const ForcePiece& p : ConstantForcePieces(*d, o.data.force_tolerance)) {
      if (p.t1 - p.t0 >= c.steady.detection.min_duration_s) ++long_pieces;
    }
  }
  return long_pieces;
}

// The integral method is meant for the dynamic (sine) trials (seed 000 §III-B): the filtered
// velocity follows smooth inputs well, while every command step distorts it. Steps are used
// only when there is no smooth dynamic trial.
std::vector<const TrialData*> InertiaTrials(const std::vector<const TrialData*>& fit) {
  std::vector<const TrialData*> dynamic;
  for (const TrialData* d : fit) {
    if (CommandRoughness(*d) > 0.0) dynamic.push_back(d);
  }
  return dynamic.empty() ? fit : dynamic;
}

// Seed 000 eqs. 7–12 and, with the drag known, the integral method (eqs. 16–19) for m. The
// notes are kept from the final pass only.
LeastSquaresAnswer SteadyAndInertia(const DofContext& c, const IdentifyOptions& o,
                                    bool final_pass, DofIdentification* r) {
  const int np = c.model.num_parameters();
  const int im = c.mass_index;
  LeastSquaresAnswer ls;
  ls.estimate = {c.prior, Eigen::MatrixXd::Zero(np, np),
                 std::vector<ParameterState>(np, ParameterState::kFixed)};
  r->inertia.reset();
  if (r->steady_points.empty()) return ls;
  r->steady = SteadyStateFit(c.model, r->steady_points, c.prior, c.steady);
  for (const auto& n : r->steady->not_excited) ls.not_excited_steady.insert(n);
  if (!r->steady->ok()) {
    // The other estimators still identify the DOF: a note, with what would fix it.
    if (final_pass) r->notes.push_back("steady state: " + r->steady->message);
    return ls;
  }
  if (final_pass) {
    for (const auto& n : r->steady->notes) r->notes.push_back("steady state: " + n);
  }
  ls.steady_ok = true;
  StageEstimate& e = ls.estimate;
  for (int j = 0; j < np; ++j) {
    if (r->steady->state[j] == ParameterState::kEstimated) e.state[j] = ParameterState::kEstimated;
    if (r->steady->state[j] == ParameterState::kDropped) e.state[j] = ParameterState::kDropped;
  }
  e.theta = r->steady->theta;
  e.covariance = r->steady->covariance;
  r->inertia = IntegralInertiaFit(c.model, InertiaTrials(c.trials.fit), e.theta, &e.covariance,
                                  o.inertia);
  if (r->inertia->ok() && r->inertia->m > 0) {
    e.theta[im] = r->inertia->m;
    e.covariance(im, im) = r->inertia->sigma * r->inertia->sigma;
    e.state[im] = ParameterState::kEstimated;
  }
  return ls;
}

// Seeds 002/004: one-step integral least squares on every regressor-linear parameter the
// steady state did not drop; its unexcited parameters (those the steady state did not excite
// either, when it answered).
void OneStep(const DofContext& c, const IdentifyOptions& o, LeastSquaresAnswer* ls,
             DofIdentification* r) {
  OneStepDofInput in;
  in.model = &c.model;
  in.trials = c.trials.fit;
  in.theta = ls->estimate.theta;
  for (int j : LinearParameters(c.model)) {
    if (ls->estimate.state[j] != ParameterState::kDropped) in.free.push_back(j);
  }
  auto res = OneStepLeastSquares({in}, o.one_step);
  r->one_step = std::move(res[0]);
  if (!r->one_step->ok()) r->notes.push_back(r->one_step->message);
  for (const auto& n : r->one_step->not_excited) {
    if (!ls->steady_ok || ls->not_excited_steady.count(n)) ls->not_excited.insert(n);
  }
}

// The least-squares answer: steady state + integral method (m from the one-step fit when the
// integral method failed), else the one-step fit.
void ChooseAnswer(const DofContext& c, LeastSquaresAnswer* ls, DofIdentification* r) {
  const int im = c.mass_index;
  StageEstimate& e = ls->estimate;
  const bool one_step_ok = r->one_step && r->one_step->ok();
  if (ls->steady_ok) {
    if (e.state[im] == ParameterState::kEstimated) {
      r->estimator = FinalEstimator::kSteadyStateIntegral;
    } else {
      if (r->inertia) {
        r->notes.push_back(r->inertia->message.empty() ? "integral method failed" : r->inertia->message);
      }
      if (one_step_ok && r->one_step->theta[im] > 0) {
        e.theta[im] = r->one_step->theta[im];
        e.covariance(im, im) = r->one_step->covariance(im, im);
        e.state[im] = ParameterState::kEstimated;
        r->estimator = FinalEstimator::kSteadyStateIntegral;
      }
    }
  } else if (one_step_ok) {
    e = {r->one_step->theta, r->one_step->covariance, r->one_step->state};
    r->estimator = FinalEstimator::kOneStep;
  }
  if (r->estimator == FinalEstimator::kNone) {
    r->warnings.push_back("least squares gave no answer (" +
                          (r->one_step ? r->one_step->message : std::string("no one-step rows")) +
                          "); the output-error fit starts from the a priori values");
  }
}

// Under feedback (closed_loop_iv.h): the instrumental-variable estimate of m and every
// regressor-linear parameter, the non-linear ones at the least-squares answer's values.
void ClosedLoop(const DofContext& c, const IdentifyOptions& o, const LeastSquaresAnswer& ls,
                DofIdentification* r) {
  if (!r->closed_loop_suspected) return;
  ClosedLoopIvOptions iv = o.closed_loop_iv;
  iv.prune_insignificant = o.prune_insignificant && iv.prune_insignificant;
  r->closed_loop_iv =
      ClosedLoopInstrumentalFit(c.model, c.trials.fit, ls.estimate.theta, o.one_step, iv);
  if (!r->closed_loop_iv->ok()) r->notes.push_back(r->closed_loop_iv->fit.message);
}

}  // namespace

LeastSquaresAnswer EstimateStage(const DofContext& c, const IdentifyOptions& o,
                                 DofIdentification* r) {
  const int long_pieces = CollectSteadyPoints(c, o, r);
  LeastSquaresAnswer ls = SteadyAndInertia(c, o, false, r);
  if (ls.steady_ok && ls.estimate.state[c.mass_index] == ParameterState::kEstimated) {
    // Second pass: settle the steady speeds with τ = m/k_L of the first pass.
    RefineSteadyPoints(c.model, ls.estimate.theta, c.trials.fit, &r->steady_points);
  }
  ls = SteadyAndInertia(c, o, true, r);
  if (r->steady_points.empty() && long_pieces > 0) {
    r->notes.push_back("steady state: no settled segment in " + std::to_string(long_pieces) +
                       " constant-force leg(s) of at least " +
                       Fmt(c.steady.detection.min_duration_s) +
                       " s (the speed did not settle within the noise; make the legs longer)");
  }
  OneStep(c, o, &ls, r);
  ChooseAnswer(c, &ls, r);
  ClosedLoop(c, o, ls, r);
  return ls;
}

}  // namespace uuvplan::ident::stages
