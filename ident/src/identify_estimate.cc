// Stage 2 of identifying a DOF, estimate: the least-squares answer that starts the refinement.
// Steady-state segments give the drag, bias, ballast step and installation coefficients
// (ref 000 eqs. 7–12, 20) and, with the drag known, the integral method gives m (eqs. 16–19);
// the one-step integral least squares of every regressor-linear parameter (refs 002/004)
// answers when there is no steady state, and supplies m when the integral method fails.
#include <algorithm>
#include <cmath>

#include "identify_stages.h"
#include "stats/model_selection.h"
#include "uuvplan/ident/estimators/regression.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident::stages {
namespace {

// No least-squares answer yet: the a priori values, every parameter held.
LeastSquaresAnswer PriorAnswer(const StageInputs& c) {
  const int np = c.model.num_parameters();
  LeastSquaresAnswer ls;
  ls.estimate = {c.prior, Eigen::MatrixXd::Zero(np, np),
                 std::vector<ParameterState>(np, ParameterState::kFixed)};
  return ls;
}

// The steady points of every fit trial (detected, or in the user's windows); returns the
// number of constant-force legs long enough to settle, for the note when none did.
int CollectSteadyPoints(const StageInputs& c, const IdentifyOptions& o, DofIdentification* r) {
  int long_pieces = 0;
  for (const TrialData* d : c.trials.fit) {
    const auto w = o.steady_windows.find(d->index);
    std::vector<std::pair<double, double>> windows;
    if (w != o.steady_windows.end()) {
      for (const auto& [a, b] : w->second)
        windows.push_back({a - d->time_offset, b - d->time_offset});
    }
    auto pts = SteadyPoints(*d, c.steady.detection, o.data.force_tolerance,
                            windows.empty() ? nullptr : &windows);
    r->steady_points.insert(r->steady_points.end(), pts.begin(), pts.end());
    long_pieces += static_cast<int>(
        ConstantForcePieces(*d, o.data.force_tolerance, c.steady.detection.min_duration_s).size());
  }
  return long_pieces;
}

// The integral method is meant for the dynamic (sine) trials (ref 000 §III-B): the filtered
// velocity follows smooth inputs well, while every command step distorts it. Steps are used
// only when there is no smooth dynamic trial.
std::vector<const TrialData*> InertiaTrials(const std::vector<const TrialData*>& fit) {
  std::vector<const TrialData*> dynamic;
  for (const TrialData* d : fit) {
    if (CommandRoughness(*d) > 0.0) dynamic.push_back(d);
  }
  return dynamic.empty() ? fit : dynamic;
}

// Ref 000 eqs. 7–12 and, with the drag known, the integral method (eqs. 16–19) for m. The
// notes are kept from the final pass only.
LeastSquaresAnswer SteadyAndInertia(const StageInputs& c, const IdentifyOptions& o, bool final_pass,
                                    DofIdentification* r) {
  const int np = c.model.num_parameters();
  const int im = c.mass_index;
  LeastSquaresAnswer ls = PriorAnswer(c);
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
  if (o.method == Method::kLeastSquares) return ls;  // m stays a priori
  r->inertia =
      IntegralInertiaFit(c.model, InertiaTrials(c.trials.fit), e.theta, &e.covariance, o.inertia);
  if (r->inertia->ok() && r->inertia->m > 0) {
    e.theta[im] = r->inertia->m;
    e.covariance(im, im) = r->inertia->sigma * r->inertia->sigma;
    e.state[im] = ParameterState::kEstimated;
  }
  return ls;
}

// Refs 002/004: one-step integral least squares on every regressor-linear parameter the
// steady state did not drop; its unexcited parameters (those the steady state did not excite
// either, when it answered).
void OneStep(const StageInputs& c, const IdentifyOptions& o, LeastSquaresAnswer* ls,
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

// The least-squares answer of the chain: steady state + integral method (m from the one-step
// fit when the integral method failed), else the one-step fit. A single method (--method)
// answers with its own estimate or not at all.
void ChooseAnswer(const StageInputs& c, Method method, LeastSquaresAnswer* ls,
                  DofIdentification* r) {
  const int im = c.mass_index;
  StageEstimate& e = ls->estimate;
  const bool one_step_ok = r->one_step && r->one_step->ok();
  const bool m_estimated = e.state[im] == ParameterState::kEstimated;
  if (ls->steady_ok && method == Method::kLeastSquares) {
    r->estimator = FinalEstimator::kSteadyState;
    r->notes.push_back(
        "ls: m is not estimated by the steady-state least squares (held at its a "
        "priori " +
        model::Significant(e.theta[im], 4) + " " + model::Unit(model::param::kMass, c.model.dof()) +
        "; the free runs use it)");
  } else if (ls->steady_ok && (m_estimated || method == Method::kIntegral)) {
    if (m_estimated)
      r->estimator = FinalEstimator::kSteadyStateIntegral;
    else if (r->inertia)
      r->notes.push_back(r->inertia->message.empty() ? "integral method failed"
                                                     : r->inertia->message);
  } else if (ls->steady_ok) {
    if (r->inertia) {
      r->notes.push_back(r->inertia->message.empty() ? "integral method failed"
                                                     : r->inertia->message);
    }
    if (one_step_ok && r->one_step->theta[im] > 0) {
      e.theta[im] = r->one_step->theta[im];
      e.covariance(im, im) = r->one_step->covariance(im, im);
      e.state[im] = ParameterState::kEstimated;
      r->estimator = FinalEstimator::kSteadyStateIntegral;
    }
  } else if (one_step_ok) {
    e = {r->one_step->theta, r->one_step->covariance, r->one_step->state};
    r->estimator = FinalEstimator::kOneStep;
  }
  if (r->estimator == FinalEstimator::kNone && method == Method::kChain) {
    r->warnings.push_back("least squares gave no answer (" +
                          (r->one_step ? r->one_step->message : std::string("no one-step rows")) +
                          "); the output-error fit starts from the a priori values");
  } else if (r->estimator == FinalEstimator::kNone) {
    r->warnings.push_back("method " + std::string(MethodName(method)) +
                          " gave no estimate (its reason in the notes)");
  }
}

// Ref 004 eq. 15 on the one-step rows of every fit trial, in campaign time: the estimate
// after the last row, with its covariance (rls.h). Model selection as the other estimators
// (ref 000 §IV-D; ref 004 §5.2 set β = 0 for "no significant improvement"): while a
// prunable parameter's percentile error exceeds 51.02%, the worst is dropped (held at 0) and
// the recursion rerun.
LeastSquaresAnswer RlsAnswer(const StageInputs& c, const IdentifyOptions& o, DofIdentification* r) {
  LeastSquaresAnswer ls = PriorAnswer(c);
  std::vector<int> free = LinearParameters(c.model);
  Eigen::VectorXd given = c.prior;
  std::vector<ParameterEstimate> dropped;
  std::vector<std::string> kept;  // insignificant parameters kept for their correlation
  while (true) {
    r->rls = RecursiveOneStep(c.model, c.trials.fit, given, free, o.one_step, o.rls);
    if (!r->rls->ok()) {
      r->warnings.push_back(r->rls->message);
      return ls;
    }
    const RlsDofResult& f = *r->rls;
    const std::vector<PruneCandidate> candidates =
        CandidatesOf(f.names, f.final_theta, f.covariance, f.free);
    double pe = 0.0;
    kept.clear();
    const int worst = o.selection.prune_insignificant
                          ? WorstInsignificant(candidates, o.selection, &pe, &kept)
                          : -1;
    if (worst < 0) break;
    const int j = f.free[worst];
    ParameterEstimate e{f.names[j],
                        0.0,
                        std::nan(""),
                        ParameterState::kDropped,
                        false,
                        candidates[worst].value,
                        candidates[worst].sigma};
    dropped.push_back(e);
    r->notes.push_back("rls: " + e.name + " = " + model::Significant(e.value_before_drop, 4) +
                       " ± " + model::Significant(e.sigma_before_drop, 4) +
                       " has a percentile error of " + model::Significant(pe, 3) +
                       "% > 51.02%: insignificant at 95%, dropped and the recursion rerun "
                       "(seed 000 §IV-D)");
    given[j] = 0.0;
    free.erase(std::find(free.begin(), free.end(), j));
  }
  for (const std::string& n : kept) r->notes.push_back("rls: " + n);
  RlsDofResult& f = *r->rls;
  f.estimates = MakeEstimates(f.names, f.final_theta, f.covariance, f.state);
  for (const ParameterEstimate& e : dropped) {
    const int j = c.model.ParameterIndex(e.name);
    f.state[j] = ParameterState::kDropped;
    f.estimates[j] = e;
  }
  for (const auto& n : f.not_excited) ls.not_excited.insert(n);
  ls.estimate = {f.final_theta, f.covariance, f.state};
  r->estimator = FinalEstimator::kRls;
  r->notes.push_back(f.message);
  return ls;
}

// Under feedback (closed_loop_iv.h): the instrumental-variable estimate of m and every
// regressor-linear parameter, the non-linear ones at the least-squares answer's values.
void EstimateUnderFeedback(const StageInputs& c, const IdentifyOptions& o,
                           const LeastSquaresAnswer& ls, DofIdentification* r) {
  if (!r->closed_loop_suspected) return;
  ClosedLoopIvOptions iv = o.closed_loop_iv;
  iv.selection = o.selection;
  r->closed_loop_iv =
      ClosedLoopInstrumentalFit(c.model, c.trials.fit, ls.estimate.theta, o.one_step, iv);
  if (!r->closed_loop_iv->ok()) r->notes.push_back(r->closed_loop_iv->fit.message);
  for (const std::string& n : r->closed_loop_iv->notes) r->notes.push_back("closed loop: " + n);
}

}  // namespace

LeastSquaresAnswer EstimateStage(const StageInputs& c, const IdentifyOptions& o,
                                 DofIdentification* r) {
  if (o.method == Method::kRls) return RlsAnswer(c, o, r);
  if (o.method == Method::kOutputError) return PriorAnswer(c);
  LeastSquaresAnswer ls = PriorAnswer(c);
  if (UsesSteadyState(o.method)) {
    const int long_pieces = CollectSteadyPoints(c, o, r);
    ls = SteadyAndInertia(c, o, false, r);
    if (ls.steady_ok && ls.estimate.state[c.mass_index] == ParameterState::kEstimated) {
      // Second pass: settle the steady speeds with τ = m/k_L of the first pass.
      RefineSteadyPoints(c.model, ls.estimate.theta, c.trials.fit, &r->steady_points);
    }
    ls = SteadyAndInertia(c, o, true, r);
    if (r->steady_points.empty() && long_pieces > 0) {
      r->notes.push_back("steady state: no settled segment in " + std::to_string(long_pieces) +
                         " constant-force leg(s) of at least " +
                         model::Significant(c.steady.detection.min_duration_s, 4) +
                         " s (the speed did not settle within the noise; make the legs longer)");
    }
  }
  if (o.method == Method::kChain || o.method == Method::kOneStep) OneStep(c, o, &ls, r);
  ChooseAnswer(c, o.method, &ls, r);
  if (o.method == Method::kChain) EstimateUnderFeedback(c, o, ls, r);
  return ls;
}

void CheckMethodFits(model::Dof dof, const std::vector<TrialData>& trials,
                     const IdentifyOptions& o) {
  if (o.method != Method::kLeastSquares && o.method != Method::kIntegral) return;
  std::string files;
  for (const TrialData& d : trials) {
    if (d.dof != dof || d.use != model::TrialUse::kFit) continue;
    if (o.steady_windows.count(d.index)) return;
    if (!ConstantForcePieces(d, o.data.force_tolerance, o.steady.detection.min_duration_s)
             .empty()) {
      return;
    }
    files += (files.empty() ? "" : ", ") + d.name;
  }
  if (files.empty()) return;  // no fit trial: the DOF's own failure says so
  throw model::InputError(
      "--method " + std::string(MethodName(o.method)),
      "the steady-state least squares (seed 000 eqs. 7–12) needs constant-force legs of at "
      "least " +
          model::Significant(o.steady.detection.min_duration_s, 4) + " s, and the " +
          std::string(model::DofName(dof)) + " fit trials (" + files +
          ") have none; use --method one-step, rls or output-error, or mark windows with --steady");
}

}  // namespace uuvplan::ident::stages
