// Stage 4 of identifying a DOF, validate: the reported estimates with what makes them
// doubtful (not excited, closed loop) and what makes the fit a failure (docs/identification.md,
// "Failure statuses": non-physical, nothing or no dynamics significant, a free run that
// diverges or does no better than ν ≡ 0), and the free-run simulation of every trial with the
// identified model (velocity MAE, ref 002 eq. 37; position RMS; residual whiteness).
#include <algorithm>
#include <cmath>

#include "drag_parameter.h"
#include "identify_stages.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident::stages {
namespace {

// Dropped parameters carry the estimate they had before being dropped.
void KeepValuesBeforeDrop(const StageInputs& c, const std::vector<ParameterEstimate>& src,
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

// The DOF fails with `reason` (reasons add up, "; "-separated, in the message).
void Fail(const std::string& reason, DofIdentification* r, bool non_physical = false) {
  if (r->status == IdentifyStatus::kFailed && !r->message.empty()) {
    r->message += "; " + reason;
    r->failed_only_non_physical = r->failed_only_non_physical && non_physical;
  } else {
    r->status = IdentifyStatus::kFailed;
    r->message = reason;
    r->failed_only_non_physical = non_physical;
  }
}

// How far `value` lies outside the family's admissible range (0 inside it).
double DistanceOutside(const model::ParameterFamily& f, double value) {
  if (f.Admissible(value)) return 0.0;
  return value < f.lower || (f.lower_open && value == f.lower) ? f.lower - value : value - f.upper;
}

// Non-physical estimates (model/parameter.h, each family's admissible range: drag ≥ 0, m > 0,
// 0 < η ≤ 2, …): outside the range by more than 3σ is a failed fit; outside but within 3σ, a
// warning and the parameter unreliable. 3σ, not 1.96σ: a true value on the bound (kq = 0 on
// URIS, ref 004 Table 4) then fails 0.13% of fits, not 2.5% (one-sided normal tail).
void CheckAdmissible(DofIdentification* r) {
  constexpr double kMargin = 3.0;  // σ
  for (const auto& e : r->params) {
    const model::ParameterFamily* f = model::FamilyOf(e.name);
    if (e.state != ParameterState::kEstimated || !f) continue;
    const double outside = DistanceOutside(*f, e.value);
    if (!(outside > 0) && std::isfinite(e.value)) continue;
    const std::string what = e.name + " = " + model::Significant(e.value, 4) + " ± " +
                             model::Significant(e.sigma, 4) + " " + model::Unit(e.name, r->dof) +
                             " is outside its admissible range (" + f->Expected() + ")";
    const std::string why =
        IsDragParameter(e.name)
            ? " (drag only dissipates: the speed range may be too narrow to separate k and kq, "
              "or the model misses an effect — thrust map, lag, coupling; try `uuvplan diagnose`)"
            : "";
    r->unreliable.push_back(e.name);
    // The least-squares answer stands in for an output error that did not converge: outside
    // the range even within 3σ there is then no physical answer at all (bluerov yaw: the
    // output error drops kq = −0.56 ± 0.35 as insignificant and does not converge without it;
    // the least squares keep kq = −0.32 ± 0.33).
    const bool fallback = r->output_error &&
                          r->output_error->status != OutputErrorStatus::kConverged &&
                          r->estimator != FinalEstimator::kOutputError;
    if (!std::isfinite(e.value) || !(outside <= kMargin * e.sigma)) {
      Fail("non-physical fit: " + what + ", by more than 3σ" + why, r, /*non_physical=*/true);
    } else if (fallback) {
      Fail("non-physical fit: " + what +
               ", and the output-error refinement did not converge: "
               "no physical estimate" +
               why,
           r, /*non_physical=*/true);
    } else {
      r->warnings.push_back(what + ", within 3σ of it: not to be trusted" + why);
    }
  }
}

void WarnClosedLoop(DofIdentification* r) {
  if (r->closed_loop_suspected) {
    r->warnings.push_back(
        "closed-loop data suspected: the logged force of most fit trials changes at every row "
        "irregularly (a controller reacting to the measurements), so the force correlates with "
        "the velocity and open-loop estimates are biased (notes/pitfalls.md); m is not a "
        "confident estimate — identify from open-loop trials (steady legs and sines)");
    r->unreliable.push_back(model::param::kMass);
  }
}

bool Significant(const ParameterEstimate& e) {
  return e.state == ParameterState::kEstimated && e.significant;
}

void FailWithoutEstimate(DofIdentification* r) {
  const ParameterEstimate* m = r->Param(model::param::kMass);
  if (r->estimator == FinalEstimator::kNone) {
    Fail(
        "no estimate: no estimator could fit these trials (see the warnings); they do not "
        "excite the model (longer trials, steady runs at several levels, a sine)",
        r);
  } else if (std::none_of(r->params.begin(), r->params.end(), Significant)) {
    // Ref 000 §IV-D: every estimate has a percentile error above 51.02% — numbers, but no
    // usable estimate (e.g. a trial far too short for the model).
    Fail(
        "no parameter is identified: every estimate is insignificant (percentile error above "
        "51.02%); the trials do not excite the model (longer trials, steady runs at several "
        "levels, a sine)",
        r);
  } else if (m && m->state == ParameterState::kEstimated && !m->significant &&
             std::none_of(r->params.begin(), r->params.end(), [](const ParameterEstimate& e) {
               return IsDragParameter(e.name) && Significant(e);
             })) {
    // A constant force alone is no model of the dynamics: inertia and every drag insignificant.
    Fail(
        "no dynamics identified: m and every drag coefficient are insignificant (percentile "
        "error above 51.02%); only a constant force is — the trials do not excite the "
        "dynamics (steady runs at several levels, a sine, open-loop)",
        r);
  }
}

// The fit trials' thrust: whether any row commands a force, and whether one of known size — a
// non-zero command through a mapping and direction whose η is not a parameter of the model
// (open water, 1 by contract, or no mapping: the thrust term's η = 1).
struct ForceKinds {
  bool any = false, known = false;
};
ForceKinds FitForces(const StageInputs& c) {
  ForceKinds k;
  for (const TrialData* d : c.trials.fit) {
    for (std::size_t i = 0; i < d->force.size() && !k.known; ++i) {
      if (d->force[i] == 0) continue;
      k.any = true;
      if (d->mapping[i] < 0) {
        k.known = true;
        continue;
      }
      const auto dir = d->force[i] > 0 ? model::Direction::kPos : model::Direction::kNeg;
      const std::string& mapping = c.vehicle.mappings[d->mapping[i]].name;
      k.known = c.model.ParameterIndex(model::EtaName(mapping, dir)) < 0;
    }
  }
  return k;
}

// Without a force of known size the model is homogeneous in its parameters: (m, k, kq, bias,
// η) and c·(m, k, kq, bias, η) give the same motion, so no estimate is determined, whatever
// values are held (ref 000 §II-A: η must be known for at least one mapping and direction).
// (No thrust at all, or no estimate, fails for its own reason.)
void FailWithoutKnownForce(const StageInputs& c, DofIdentification* r) {
  const ForceKinds k = FitForces(c);
  if (k.known || !k.any || r->estimator == FinalEstimator::kNone) return;
  Fail(
      "no force of known size: every fit trial's force goes through a mapping and direction "
      "whose installation coefficient η is unknown (not open water), so the parameters are "
      "determined only up to a common scale (seed 000 §II-A) and the values printed rest on the "
      "η held at 1 — add fit legs in a mapping and direction declared open water",
      r);
}

// An inertia ten times below the vehicle's a priori range is no vehicle's: most often a unit
// mistake in the log, which scales every estimate — angles in degrees (m, k by 1/57.3), positions
// in cm or mm (1/100, 1/1000) — too slow a motion for the input check's rate-vs-angle test to
// see (ReadCampaignForIdentification); else a vehicle file that is wrong.
struct UnitSlip {
  double factor;
  const char* unit;
  bool rotation;
};
constexpr UnitSlip kUnitSlips[] = {
    {180 / M_PI, "degrees", true}, {100, "cm", false}, {1000, "mm", false}};

void FailBelowPriorInertia(const StageInputs& c, DofIdentification* r) {
  const ParameterEstimate* m = r->Param(model::param::kMass);
  if (!m || m->state != ParameterState::kEstimated || !m->significant || !(m->value > 0)) return;
  const auto [lo, hi] = c.vehicle.InertiaBounds(r->dof);
  if (!(m->value + 3 * m->sigma < lo / 10) || !FitForces(c).known) return;  // 3σ: clearly below
  const bool rotation = model::IsRotational(r->dof);
  const std::string unit = model::Unit(model::param::kMass, r->dof);
  // The slip that puts m nearest the range's geometric centre, if within a factor 2 of it.
  std::string likely;
  double best = std::log(2.0);
  for (const UnitSlip& s : kUnitSlips) {
    if (s.rotation != rotation) continue;
    const double miss = std::abs(std::log(m->value * s.factor / std::sqrt(lo * hi)));
    if (miss > best) continue;
    best = miss;
    likely = ": × " + model::Significant(s.factor, 3) + " gives " +
             model::Significant(m->value * s.factor, 3) + " " + unit +
             ", near the range, so the log's " + std::string(model::DofName(r->dof)) +
             " positions and velocities are most likely in " + s.unit + " — convert them to " +
             (rotation ? "rad" : "m");
  }
  Fail("m = " + model::Significant(m->value, 4) + " ± " + model::Significant(m->sigma, 4) + " " +
           unit + " is " + model::Significant(lo / m->value, 3) +
           "× below the vehicle's a priori range [" + model::Significant(lo, 4) + ", " +
           model::Significant(hi, 4) + "] " + unit +
           (likely.empty() ? ": check the log's units and the vehicle file's mass and inertia"
                           : likely),
       r);
}

// Output-error residuals whose lag-1 autocorrelation exceeds this are no sensor noise: the model
// misses a dynamics the data hold (a white residual has lag-1 within ±2/√n, ~0.02 for a 10^4-row
// campaign; CHOSEN 0.8, where the residual is mostly unmodelled signal: the BlueROV 2016
// campaign_all sits at 0.97, the cases' virtual campaigns within ±0.1).
constexpr double kModelErrorLag1 = 0.8;

// The vehicle file's inertia bounds are a statement about the vehicle; an estimate beyond them
// says the statement or the data is wrong, and the user is told which way and how far.
void FindOutsidePrior(const StageInputs& c, DofIdentification* r) {
  const ParameterEstimate* m = r->Param(model::param::kMass);
  if (!m || m->state != ParameterState::kEstimated || !std::isfinite(m->value)) return;
  const auto [lo, hi] = c.vehicle.InertiaBounds(r->dof);
  if (m->value < lo || m->value > hi) {
    r->outside_prior.push_back({model::param::kMass, m->value, m->sigma, lo, hi});
  }
}

// A usable model's free run beats ν ≡ 0 (the velocity MAE of ref 002 eq. 37) on its fit
// trials and on its validate trials; a free run that diverges is no model at all.
void CheckFreeRun(DofIdentification* r) {
  for (const auto& t : r->fit.trials) {
    if (!std::isfinite(t.velocity_mae)) {
      Fail("diverged: the free-run simulation of " + t.name +
               " with the identified model diverges — the model is not usable for simulation",
           r);
      return;
    }
  }
  const std::string unit(model::VelocityUnit(r->dof));
  auto check = [&](const char* trials, double model_mae, double zero_mae) {
    if (!(model_mae < zero_mae) && std::isfinite(zero_mae)) {
      Fail(std::string("no better than a zero-velocity model: free-run velocity MAE on the ") +
               trials + " trials " + model::Significant(model_mae, 4) + " " + unit + " against " +
               model::Significant(zero_mae, 4) + " " + unit + " for ν ≡ 0",
           r);
    }
  };
  check("fit", r->fit.velocity_mae_fit, r->fit.zero_velocity_mae_fit);
  check("validate", r->fit.velocity_mae_validate, r->fit.zero_velocity_mae_validate);
}

}  // namespace

void ReportEstimates(const StageInputs& c, const LeastSquaresAnswer& ls, const StageEstimate& e,
                     DofIdentification* r) {
  for (const auto& n : ls.not_excited) {
    r->warnings.push_back(n + " is not excited by the fit trials (kept at " +
                          model::Significant(e.theta[c.model.ParameterIndex(n)], 4) + ")");
  }
  r->theta = e.theta;
  r->covariance = e.covariance;
  r->params = MakeEstimates(r->parameter_names, e.theta, e.covariance, e.state);
  if (r->steady) KeepValuesBeforeDrop(c, r->steady->estimates, e.state, r);
  if (r->output_error) KeepValuesBeforeDrop(c, r->output_error->estimates, e.state, r);
  if (r->rls) KeepValuesBeforeDrop(c, r->rls->estimates, e.state, r);
  CheckAdmissible(r);
  WarnClosedLoop(r);
  FailWithoutEstimate(r);
  FailWithoutKnownForce(c, r);
  FailBelowPriorInertia(c, r);
}

void ValidateStage(const StageInputs& c, const ValidationOptions& o, DofIdentification* r) {
  bool model_error = false;
  if (r->estimator != FinalEstimator::kNone) {
    std::vector<TrialFit> fits;
    const bool oe = r->estimator == FinalEstimator::kOutputError && r->output_error;
    for (const TrialData* d : c.trials.fit) {
      const Eigen::VectorXd x0 =
          oe ? FittedMovingStart(*r->output_error, d->index) : Eigen::VectorXd();
      fits.push_back(ValidateTrial(c.model, r->theta, *d, o, x0.size() ? &x0 : nullptr));
    }
    for (const TrialData* d : c.trials.validate)
      fits.push_back(ValidateTrial(c.model, r->theta, *d, o));
    r->fit = Summarize(std::move(fits));
    CheckFreeRun(r);
    model_error = r->output_error && r->output_error->ok() &&
                  r->output_error->residual_lag1 > kModelErrorLag1;
    if (model_error) {
      r->warnings.push_back(
          "the identified model does not explain the measurements to their "
          "noise level (output-error residuals strongly correlated, lag-1 " +
          model::Significant(r->output_error->residual_lag1, 3) +
          "): model error; σ are autocorrelation-robust and describe the fit "
          "of this model, not the truth (try `uuvplan diagnose`)");
    }
  }
  r->outside_prior.clear();
  if (r->status != IdentifyStatus::kFailed) {
    FindOutsidePrior(c, r);  // a failed DOF's reason says more (a unit slip names its unit)
    r->status = model_error           ? IdentifyStatus::kModelError
                : r->warnings.empty() ? IdentifyStatus::kOk
                                      : IdentifyStatus::kWarnings;
    r->message = "estimated by " + std::string(FinalEstimatorName(r->estimator));
  }
}

}  // namespace uuvplan::ident::stages
