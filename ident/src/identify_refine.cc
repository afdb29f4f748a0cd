// Stage 3 of identifying a DOF, refine: the output-error (maximum-likelihood) fit started from
// the least-squares answer; restarted from the a priori values when that start leads nowhere,
// refitted with the unidentifiable parameters held, and reported only when it converged.
#include <algorithm>
#include <cmath>

#include "drag_parameter.h"
#include "identify_stages.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident::stages {
namespace {

// Where the refinement starts and what it may move.
struct RefineStart {
  Eigen::VectorXd theta;
  std::vector<ParameterState> state;  ///< kEstimated, or kFixed when not excited
  std::vector<std::string> reinstated;
};

// Parameters the least squares dropped as insignificant are free again here: significance is
// a property of an estimator's own covariance, and the output error's is much smaller
// (integrated positions make a small bias, invisible to the steady speeds, highly
// significant). The output error re-tests them with its own σ (51.02%, ref 000 §IV-D) and
// drops them again only if they are still insignificant.
RefineStart StartFrom(const StageInputs& c, const LeastSquaresAnswer& ls) {
  const int np = c.model.num_parameters();
  const auto& names = c.model.parameter_names();
  RefineStart s{ls.estimate.theta, std::vector<ParameterState>(np, ParameterState::kEstimated), {}};
  for (int j = 0; j < np; ++j) {
    if (ls.estimate.state[j] == ParameterState::kDropped) s.reinstated.push_back(names[j]);
    if (ls.not_excited.count(names[j])) s.state[j] = ParameterState::kFixed;
  }
  if (!(s.theta[c.mass_index] > 0)) s.theta[c.mass_index] = c.prior[c.mass_index];
  // A negative drag makes the free run unstable: start the refinement with it at zero.
  for (int j = 0; j < np; ++j) {
    if (IsDragParameter(names[j]) && s.theta[j] < 0) s.theta[j] = 0.0;
  }
  return s;
}

// A fit in a poor local minimum (residuals above the noise: s² more than 4 standard errors
// √(2/dof) above 1, or a negative drag) or nowhere.
bool Suspicious(const StageInputs& c, const OutputErrorResult& f) {
  if (!f.ok()) return true;
  const int np = c.model.num_parameters();
  const int dof = std::max(1, f.num_residuals - np);
  if (f.sigma2 > 1.0 + 4.0 * std::sqrt(2.0 / dof)) return true;
  const auto& names = c.model.parameter_names();
  for (int j = 0; j < np; ++j) {
    if ((names[j] == model::param::kLinearDrag || names[j] == model::param::kQuadraticDrag) &&
        f.theta[j] < 0) {
      return true;
    }
  }
  return false;
}

// A least-squares start far from the answer can lead Levenberg–Marquardt to a poor local
// minimum or nowhere: restart from the a priori values and keep the better fit.
OutputErrorResult FitWithRestart(const StageInputs& c, const LeastSquaresAnswer& ls,
                                 const RefineStart& s, bool from_prior, DofIdentification* r) {
  OutputErrorResult oe = OutputErrorFit(c.model, c.trials.fit, s.theta, s.state, c.output_error);
  if (from_prior || !Suspicious(c, oe)) return oe;
  Eigen::VectorXd alt = c.prior;
  for (int j = 0; j < c.model.num_parameters(); ++j) {
    if (ls.estimate.state[j] == ParameterState::kDropped) alt[j] = 0.0;
  }
  OutputErrorResult retry = OutputErrorFit(c.model, c.trials.fit, alt, s.state, c.output_error);
  if (retry.ok() && (!oe.ok() || retry.cost < oe.cost)) {
    r->notes.push_back(
        "output error restarted from the a priori values (from the "
        "least-squares answer: " +
        oe.message + ")");
    oe = std::move(retry);
  }
  return oe;
}

// Fix what the data cannot determine and refit once; say so. The other estimates are
// conditional on the held values: were those wrong (a priori guesses), the rest absorb the
// difference with a σ that does not show it (ROMEO heave with W and η held at 0 and 1: kq twice
// its true value at "±4%"). They are reported but marked unreliable.
void RefitHoldingUnidentifiable(const StageInputs& c, RefineStart* s, OutputErrorResult* oe,
                                DofIdentification* r) {
  std::vector<std::string> fixed;
  for (const auto& n : oe->not_identifiable) {
    const int j = c.model.ParameterIndex(n);
    if (j >= 0 && j != c.mass_index) {
      s->state[j] = ParameterState::kFixed;
      fixed.push_back(n);
    }
  }
  if (fixed.empty()) return;
  *oe = OutputErrorFit(c.model, c.trials.fit, s->theta, s->state, c.output_error);
  std::vector<std::string> conditional;
  for (int j = 0; j < c.model.num_parameters(); ++j) {
    if (oe->state[j] == ParameterState::kEstimated) {
      conditional.push_back(r->parameter_names[j]);
      r->unreliable.push_back(r->parameter_names[j]);
    }
  }
  r->warnings.push_back(
      "output error: not identifiable from these trials (held at their "
      "least-squares/a priori values): " +
      model::Join(fixed) + " (condition number " + model::Significant(oe->condition_number, 3) +
      "; excite them, e.g. with forces of both signs on every mapping); "
      "the other estimates (" +
      model::Join(conditional) +
      ") are conditional on the held values and their σ does not include "
      "that: NOT reliable");
}

// The refinement is reported only when Levenberg–Marquardt converged to an admissible
// minimum. Otherwise (iteration limit, failed simulation, singular information) its numbers
// are not an estimate: the least-squares answer is reported instead, with a warning — or,
// when there is no least-squares answer, the output error's with a warning.
StageEstimate Adopt(const StageInputs& c, const LeastSquaresAnswer& ls, const RefineStart& s,
                    const OutputErrorResult& oe, DofIdentification* r) {
  const bool have_ls = r->estimator != FinalEstimator::kNone;
  const bool converged = oe.status == OutputErrorStatus::kConverged;
  if (!converged && !(!have_ls && oe.ok())) {
    r->warnings.push_back(oe.message +
                          " — the output-error refinement did not converge; the "
                          "least-squares estimates (" +
                          std::string(FinalEstimatorName(r->estimator)) + ") are reported");
    return ls.estimate;
  }
  StageEstimate e{oe.theta, oe.covariance, oe.state};
  r->estimator = FinalEstimator::kOutputError;
  if (!converged) {
    r->warnings.push_back("output error stopped at the iteration limit (" +
                          std::to_string(oe.iterations) +
                          ") without converging and there is no least-squares answer to "
                          "fall back to: its estimates are reported but may not be a minimum");
  }
  for (const std::string& n : s.reinstated) {
    const int j = c.model.ParameterIndex(n);
    if (e.state[j] == ParameterState::kEstimated) {
      r->notes.push_back(n +
                         " (dropped as insignificant by the least squares) is significant "
                         "for the output error: " +
                         model::Significant(e.theta[j], 4) + " ± " +
                         model::Significant(std::sqrt(e.covariance(j, j)), 4) +
                         " (its own covariance)");
    }
  }
  return e;
}

// Under feedback the command carries the measurement noise the controller saw, so the output
// error (which simulates from that command) and the least squares are biased: the
// instrumental-variable estimate is reported instead, and no output error is run.
bool AdoptClosedLoop(DofIdentification* r, StageEstimate* e) {
  if (!r->closed_loop_iv || !r->closed_loop_iv->ok()) return false;
  const OneStepDofResult& f = r->closed_loop_iv->fit;
  *e = {f.theta, f.covariance, f.state};
  r->estimator = FinalEstimator::kClosedLoopIv;
  r->notes.push_back("closed loop: " + f.message +
                     "; the output error is not run (under "
                     "feedback the command correlates with the measurement noise)");
  return true;
}

}  // namespace

StageEstimate RefineStage(const StageInputs& c, const LeastSquaresAnswer& ls,
                          const IdentifyOptions& o, DofIdentification* r) {
  StageEstimate closed_loop;
  if (AdoptClosedLoop(r, &closed_loop)) return closed_loop;
  // --method output-error starts from the a priori values (EstimateStage answered nothing);
  // every other single method is its own answer.
  const bool from_prior = o.method == Method::kOutputError;
  if (!o.refine || !(o.method == Method::kChain || from_prior)) return ls.estimate;
  RefineStart s = StartFrom(c, ls);
  OutputErrorResult oe = FitWithRestart(c, ls, s, from_prior, r);
  if (oe.status == OutputErrorStatus::kIllConditioned && !oe.not_identifiable.empty()) {
    RefitHoldingUnidentifiable(c, &s, &oe, r);
  }
  for (const auto& n : oe.notes) r->notes.push_back("output error: " + n);
  StageEstimate e = Adopt(c, ls, s, oe, r);
  r->output_error = std::move(oe);
  return e;
}

}  // namespace uuvplan::ident::stages
