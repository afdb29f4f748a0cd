// Stage 4 of identifying a DOF, validate: the reported estimates with what makes them
// doubtful (not excited, negative drag, closed loop, nothing significant), and the free-run
// simulation of every trial with the identified model (velocity MAE, seed 002 eq. 37;
// position RMS; residual whiteness).
#include <algorithm>
#include <cmath>

#include "drag_parameter.h"
#include "identify_stages.h"
#include "number_text.h"
#include "uuvplan/model/effects.h"

namespace uuvplan::ident::stages {
namespace {

// Dropped parameters carry the estimate they had before being dropped.
void KeepValuesBeforeDrop(const DofContext& c, const std::vector<ParameterEstimate>& src,
                          const std::vector<ParameterState>& state, DofIdentification* r) {
  for (const auto& e : src) {
    const int j = c.model.ParameterIndex(e.name);
    if (j >= 0 && state[j] == ParameterState::kDropped && e.state == ParameterState::kDropped) {
      r->params[j].value_before_drop = e.value_before_drop;
      r->params[j].sigma_before_drop = e.sigma_before_drop;
      r->params[j].significant = false;
    }
  }
}

void WarnImplausible(DofIdentification* r) {
  for (const auto& e : r->params) {
    if (IsDragParameter(e.name) && e.state == ParameterState::kEstimated && e.value < 0 &&
        e.significant) {
      r->warnings.push_back(e.name + " = " + Fmt(e.value) + " ± " + Fmt(e.sigma) +
                            " is negative: physically implausible (drag only dissipates). The "
                            "speed range may be too narrow to separate k and kq, or the model "
                            "misses an effect (thrust map, lag, coupling; try `uuvplan diagnose`)");
      r->unreliable.push_back(e.name);
    }
  }
  if (r->closed_loop_suspected) {
    r->warnings.push_back(
        "closed-loop data suspected: the logged force of most fit trials changes at every row "
        "irregularly (a controller reacting to the measurements), so the force correlates with "
        "the velocity and open-loop estimates are biased (notes/pitfalls.md); m is not a "
        "confident estimate — identify from open-loop trials (steady legs and sines)");
    r->unreliable.push_back(model::param::kMass);
  }
}

void FailWithoutEstimate(DofIdentification* r) {
  if (r->estimator == FinalEstimator::kNone) {
    r->status = IdentifyStatus::kFailed;
    r->message = "no estimate: no estimator could fit these trials (see the warnings); they do "
                 "not excite the model (longer trials, steady runs at several levels, a sine)";
  } else if (std::none_of(r->params.begin(), r->params.end(), [](const ParameterEstimate& e) {
               return e.state == ParameterState::kEstimated && e.significant;
             })) {
    // Seed 000 §IV-D: every estimate has a percentile error above 51.02% — numbers, but no
    // usable estimate (e.g. a trial far too short for the model).
    r->status = IdentifyStatus::kFailed;
    r->message = "no parameter is identified: every estimate is insignificant (percentile error "
                 "above 51.02%); the trials do not excite the model (longer trials, steady runs "
                 "at several levels, a sine)";
    r->warnings.push_back(r->message);
  }
}

}  // namespace

void ReportEstimates(const DofContext& c, const LeastSquaresAnswer& ls,
                     const StageEstimate& e, DofIdentification* r) {
  for (const auto& n : ls.not_excited) {
    r->warnings.push_back(n + " is not excited by the fit trials (kept at " +
                          Fmt(e.theta[c.model.ParameterIndex(n)]) + ")");
  }
  r->theta = e.theta;
  r->covariance = e.covariance;
  r->params = MakeEstimates(r->parameter_names, e.theta, e.covariance, e.state);
  if (r->steady) KeepValuesBeforeDrop(c, r->steady->estimates, e.state, r);
  if (r->output_error) KeepValuesBeforeDrop(c, r->output_error->estimates, e.state, r);
  WarnImplausible(r);
  FailWithoutEstimate(r);
}

void ValidateStage(const DofContext& c, const ValidationOptions& o, DofIdentification* r) {
  if (r->estimator != FinalEstimator::kNone) {
    std::vector<TrialFit> fits;
    for (const TrialData* d : c.trials.fit) fits.push_back(ValidateTrial(c.model, r->theta, *d, o));
    for (const TrialData* d : c.trials.validate) fits.push_back(ValidateTrial(c.model, r->theta, *d, o));
    r->fit = Summarize(std::move(fits));
    for (const auto& t : r->fit.trials) {
      if (!std::isfinite(t.velocity_mae)) {
        r->warnings.push_back("the free-run simulation of " + t.name +
                              " with the identified model diverges: the model is not usable "
                              "for simulation as identified");
        break;
      }
    }
    if (r->output_error && r->output_error->ok() && r->output_error->residual_lag1 > 0.8) {
      r->warnings.push_back("the identified model does not explain the measurements to their "
                            "noise level (output-error residuals strongly correlated, lag-1 " +
                            Fmt(r->output_error->residual_lag1, 3) +
                            "): model error; σ are autocorrelation-robust and describe the fit "
                            "of this model, not the truth (try `uuvplan diagnose`)");
    }
  }
  if (r->status != IdentifyStatus::kFailed) {
    r->status = r->warnings.empty() ? IdentifyStatus::kOk : IdentifyStatus::kWarnings;
    r->message = "estimated by " + std::string(FinalEstimatorName(r->estimator));
  }
}

}  // namespace uuvplan::ident::stages
