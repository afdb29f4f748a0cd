#include "uuvplan/ident/identify.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <set>
#include <sstream>

#include "uuvplan/ident/regression.h"
#include "uuvplan/ident/significance.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::ident {
namespace {

using model::Dof;

std::string Fmt(double v, int precision = 4) {
  std::ostringstream os;
  os.precision(precision);
  os << v;
  return os.str();
}

bool StartsWith(const std::string& s, const char* p) { return s.rfind(p, 0) == 0; }

std::string Join(const std::vector<std::string>& v) {
  std::string s;
  for (const auto& x : v) s += (s.empty() ? "" : ", ") + x;
  return s;
}

}  // namespace

bool IdentifyOptions::IsValid(std::string* error) const {
  if (!data.IsValid(error) || !steady.IsValid(error) || !inertia.IsValid(error) ||
      !one_step.IsValid(error) || !output_error.IsValid(error)) {
    return false;
  }
  if (!(validation.step_s > 0)) {
    if (error) *error = "ValidationOptions::step_s must be > 0";
    return false;
  }
  return true;
}

std::string_view IdentifyStatusName(IdentifyStatus s) {
  switch (s) {
    case IdentifyStatus::kOk: return "ok";
    case IdentifyStatus::kWarnings: return "warnings";
    case IdentifyStatus::kFailed: return "failed";
  }
  return "ok";
}

std::string_view FinalEstimatorName(FinalEstimator e) {
  switch (e) {
    case FinalEstimator::kOutputError: return "output_error";
    case FinalEstimator::kSteadyStateIntegral: return "steady_state+integral";
    case FinalEstimator::kOneStep: return "one_step_ls";
    case FinalEstimator::kNone: return "none";
  }
  return "none";
}

const ParameterEstimate* DofIdentification::Param(const std::string& name) const {
  for (const auto& p : params) {
    if (p.name == name) return &p;
  }
  return nullptr;
}

const DofIdentification* IdentifyResult::Find(Dof dof) const {
  for (const auto& d : dofs) {
    if (d.dof == dof) return &d;
  }
  return nullptr;
}

Eigen::VectorXd PriorTheta(const model::Vehicle& v, const model::DofModel& model,
                           const std::map<std::string, double>& guess) {
  const Dof dof = model.dof();
  const auto bounds = v.InertiaBounds(dof);
  const double m = 0.5 * (bounds[0] + bounds[1]) > 0 ? 0.5 * (bounds[0] + bounds[1]) : 1.0;
  double k = m / 5.0, kq = 0.0;  // a 5 s time constant when nothing is known
  if (auto it = v.priors.find(dof); it != v.priors.end() && it->second.drag) {
    k = it->second.drag->k;
    kq = it->second.drag->kq;
  }
  const auto& names = model.parameter_names();
  Eigen::VectorXd theta(model.num_parameters());
  for (int j = 0; j < model.num_parameters(); ++j) {
    const std::string& n = names[j];
    double value = 0.0;
    if (n == model::param::kMass) value = m;
    else if (n == model::param::kLinearDrag || n == model::param::kLinearDragNeg) value = k;
    else if (n == model::param::kQuadraticDrag || n == model::param::kQuadraticDragNeg) value = kq;
    else if (StartsWith(n, model::param::kEtaPrefix)) value = 1.0;
    else if (n == model::param::kLag) value = 0.1;
    if (auto g = guess.find(n); g != guess.end()) value = g->second;
    theta[j] = value;
  }
  return theta;
}

double CommandRoughness(const TrialData& d) {
  // The sequence of distinct consecutive command values (holds removed).
  std::vector<double> v;
  for (double f : d.force) {
    if (v.empty() || f != v.back()) v.push_back(f);
  }
  if (v.size() < 10) return 0.0;
  // A designed piecewise-constant input (steps, legs, telegraph, PRBS) revisits a few levels.
  std::vector<double> levels = v;
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  if (levels.size() <= std::max<std::size_t>(10, v.size() / 10)) return 0.0;
  // Many levels: smooth (a sampled sine) or irregular (a controller reacting to noise).
  std::vector<double> d1, d2;
  for (std::size_t i = 1; i < v.size(); ++i) {
    d1.push_back(std::abs(v[i] - v[i - 1]));
    if (i >= 2) d2.push_back(std::abs(v[i] - 2 * v[i - 1] + v[i - 2]));
  }
  auto median = [](std::vector<double> x) {
    std::nth_element(x.begin(), x.begin() + x.size() / 2, x.end());
    return x[x.size() / 2];
  };
  const double m1 = median(d1);
  return m1 > 0 ? median(d2) / m1 : 0.0;
}

namespace {

DofIdentification IdentifyDof(const model::Campaign& campaign, Dof dof,
                              const std::vector<TrialData>& all, const IdentifyOptions& o) {
  DofIdentification r;
  r.dof = dof;
  const model::Vehicle& vehicle = campaign.vehicle;
  std::vector<const TrialData*> fit, validate;
  std::vector<std::string> mappings;
  std::set<int> ballast_values;
  for (const TrialData& d : all) {
    if (d.dof != dof) continue;
    if (d.use == model::TrialUse::kFit) {
      fit.push_back(&d);
      r.fit_trials.push_back(d.index);
      for (const auto& m : d.mappings_used) {
        if (std::find(mappings.begin(), mappings.end(), m) == mappings.end()) mappings.push_back(m);
      }
      ballast_values.insert(d.ballast_steps);
    } else {
      validate.push_back(&d);
      r.validate_trials.push_back(d.index);
    }
  }
  for (const TrialData& d : all) {
    if (d.dof != dof) continue;
    for (const std::string& c : d.unusable_columns) {
      r.warnings.push_back(d.name + ": column " + c + " has no usable value (all NaN?): the " +
                           "trial is identified from its other measurement only");
    }
  }
  if (fit.empty()) {
    r.status = IdentifyStatus::kFailed;
    r.message = "no fit trial for " + std::string(model::DofName(dof)) +
                " (mark at least one trial `use: fit`)";
    return r;
  }
  // Model structure.
  if (auto it = o.structures.find(dof); it != o.structures.end()) {
    r.structure = it->second;
    r.structure.dof = dof;
  } else {
    r.structure = model::ModelStructure::Standard(vehicle, dof, mappings, ballast_values.size() > 1);
  }
  const model::DofModel model(vehicle, r.structure);
  const int np = model.num_parameters();
  r.parameter_names = model.parameter_names();
  const Eigen::VectorXd prior = PriorTheta(vehicle, model, o.initial_guess);

  SteadyStateOptions so = o.steady;
  OutputErrorOptions oo = o.output_error;
  so.prune_insignificant = o.prune_insignificant && so.prune_insignificant;
  oo.prune_insignificant = o.prune_insignificant && oo.prune_insignificant;

  // Closed loop.
  int rough = 0;
  for (const TrialData* d : fit) {
    if (CommandRoughness(*d) > 0.3) ++rough;
  }
  r.closed_loop_suspected = o.closed_loop == ClosedLoop::kYes ||
                            (o.closed_loop == ClosedLoop::kAuto && 2 * rough > static_cast<int>(fit.size()));

  using Clock = std::chrono::steady_clock;
  auto seconds_since = [](Clock::time_point a) {
    return std::chrono::duration<double>(Clock::now() - a).count();
  };
  auto stage = Clock::now();
  // 2. Steady state (seed 000 eqs. 7–12, 20).
  int long_pieces = 0;
  for (const TrialData* d : fit) {
    const auto w = o.steady_windows.find(d->index);
    std::vector<std::pair<double, double>> windows;
    if (w != o.steady_windows.end()) {
      for (const auto& [a, b] : w->second) windows.push_back({a - d->time_offset, b - d->time_offset});
    }
    auto pts = SteadyPoints(*d, so.detection, o.data.force_tolerance, windows.empty() ? nullptr : &windows);
    r.steady_points.insert(r.steady_points.end(), pts.begin(), pts.end());
    for (const ForcePiece& p : ConstantForcePieces(*d, o.data.force_tolerance)) {
      if (p.t1 - p.t0 >= so.detection.min_duration_s) ++long_pieces;
    }
  }
  Eigen::VectorXd theta_ls = prior;
  Eigen::MatrixXd cov_ls = Eigen::MatrixXd::Zero(np, np);
  std::vector<ParameterState> state_ls(np, ParameterState::kFixed);
  std::set<std::string> not_excited_steady;
  bool steady_ok = false;
  const int im = model.ParameterIndex(model::param::kMass);
  // The integral method is meant for the dynamic (sine) trials (seed 000 §III-B): the filtered
  // velocity follows smooth inputs well, while every command step distorts it. Steps are used
  // only when there is no smooth dynamic trial.
  std::vector<const TrialData*> dynamic;
  for (const TrialData* d : fit) {
    if (CommandRoughness(*d) > 0.0) dynamic.push_back(d);
  }
  // Seed 000 eqs. 7–12 and, with the drag known, the integral method (eqs. 16–19) for m.
  auto steady_and_inertia = [&](bool final_pass) {
    theta_ls = prior;
    cov_ls.setZero();
    state_ls.assign(np, ParameterState::kFixed);
    not_excited_steady.clear();
    steady_ok = false;
    r.inertia.reset();
    if (r.steady_points.empty()) return;
    r.steady = SteadyStateFit(model, r.steady_points, prior, so);
    for (const auto& n : r.steady->not_excited) not_excited_steady.insert(n);
    if (!r.steady->ok()) {
      // The other estimators still identify the DOF: a note, with what would fix it.
      if (final_pass) r.notes.push_back("steady state: " + r.steady->message);
      return;
    }
    if (final_pass) {
      for (const auto& n : r.steady->notes) r.notes.push_back("steady state: " + n);
    }
    steady_ok = true;
    for (int j = 0; j < np; ++j) {
      if (r.steady->state[j] == ParameterState::kEstimated) state_ls[j] = ParameterState::kEstimated;
      if (r.steady->state[j] == ParameterState::kDropped) state_ls[j] = ParameterState::kDropped;
    }
    theta_ls = r.steady->theta;
    cov_ls = r.steady->covariance;
    r.inertia = IntegralInertiaFit(model, dynamic.empty() ? fit : dynamic, theta_ls, &cov_ls, o.inertia);
    if (r.inertia->ok() && r.inertia->m > 0) {
      theta_ls[im] = r.inertia->m;
      cov_ls(im, im) = r.inertia->sigma * r.inertia->sigma;
      state_ls[im] = ParameterState::kEstimated;
    }
  };
  steady_and_inertia(false);
  if (steady_ok && state_ls[im] == ParameterState::kEstimated) {
    // Second pass: settle the steady speeds with τ = m/k_L of the first pass.
    RefineSteadyPoints(model, theta_ls, fit, &r.steady_points);
  }
  steady_and_inertia(true);
  if (r.steady_points.empty() && long_pieces > 0) {
    r.notes.push_back("steady state: no settled segment in " + std::to_string(long_pieces) +
                      " constant-force leg(s) of at least " + Fmt(so.detection.min_duration_s) +
                      " s (the speed did not settle within the noise; make the legs longer)");
  }

  r.timing["steady_state+integral"] = seconds_since(stage);
  stage = Clock::now();
  // 3a. One-step integral LS (seeds 002/004) on every regressor-linear parameter not dropped.
  std::vector<int> free_ls;
  for (int j : LinearParameters(model)) {
    if (state_ls[j] != ParameterState::kDropped) free_ls.push_back(j);
  }
  {
    OneStepDofInput in;
    in.model = &model;
    in.trials = fit;
    in.theta = theta_ls;
    in.free = free_ls;
    auto res = OneStepLeastSquares({in}, o.one_step);
    r.one_step = std::move(res[0]);
    if (!r.one_step->ok()) r.notes.push_back(r.one_step->message);
  }
  std::set<std::string> not_excited;
  if (r.one_step) {
    for (const auto& n : r.one_step->not_excited) {
      if (!steady_ok || not_excited_steady.count(n)) not_excited.insert(n);
    }
  }
  // 3b. The least-squares answer: steady state + integral method, else one-step LS.
  if (steady_ok) {
    if (state_ls[im] == ParameterState::kEstimated) {
      r.estimator = FinalEstimator::kSteadyStateIntegral;
    } else {
      if (r.inertia) r.notes.push_back(r.inertia->message.empty() ? "integral method failed" : r.inertia->message);
      if (r.one_step && r.one_step->ok() && r.one_step->theta[im] > 0) {
        theta_ls[im] = r.one_step->theta[im];
        cov_ls(im, im) = r.one_step->covariance(im, im);
        state_ls[im] = ParameterState::kEstimated;
        r.estimator = FinalEstimator::kSteadyStateIntegral;
      }
    }
  } else if (r.one_step && r.one_step->ok()) {
    theta_ls = r.one_step->theta;
    cov_ls = r.one_step->covariance;
    state_ls = r.one_step->state;
    r.estimator = FinalEstimator::kOneStep;
  }
  if (r.estimator == FinalEstimator::kNone) {
    r.warnings.push_back("least squares gave no answer (" +
                         (r.one_step ? r.one_step->message : std::string("no one-step rows")) +
                         "); the output-error fit starts from the a priori values");
  }

  r.timing["one_step_ls"] = seconds_since(stage);
  stage = Clock::now();
  // 4. Output error, from the least-squares answer.
  Eigen::VectorXd theta = theta_ls;
  Eigen::MatrixXd cov = cov_ls;
  std::vector<ParameterState> state = state_ls;
  if (o.refine) {
    // Parameters the least squares dropped as insignificant are free again here: significance
    // is a property of an estimator's own covariance, and the output error's is much smaller
    // (integrated positions make a small bias, invisible to the steady speeds, highly
    // significant). The output error re-tests them with its own σ (51.02%, seed 000 §IV-D)
    // and drops them again only if they are still insignificant.
    std::vector<ParameterState> s0(np, ParameterState::kEstimated);
    std::vector<std::string> reinstated;
    for (int j = 0; j < np; ++j) {
      if (state_ls[j] == ParameterState::kDropped) reinstated.push_back(r.parameter_names[j]);
      if (not_excited.count(r.parameter_names[j])) s0[j] = ParameterState::kFixed;
    }
    Eigen::VectorXd start = theta_ls;
    if (!(start[im] > 0)) start[im] = prior[im];
    // A negative drag makes the free run unstable: start the refinement with it at zero.
    for (int j = 0; j < np; ++j) {
      const std::string& n = r.parameter_names[j];
      if ((n == model::param::kLinearDrag || n == model::param::kQuadraticDrag ||
           n == model::param::kLinearDragNeg || n == model::param::kQuadraticDragNeg) &&
          start[j] < 0) {
        start[j] = 0.0;
      }
    }
    OutputErrorResult oe = OutputErrorFit(model, fit, start, s0, oo);
    // A least-squares start far from the answer can lead Levenberg–Marquardt to a poor local
    // minimum (residuals above the noise: s² more than 4 standard errors √(2/dof) above 1, or
    // a negative drag) or nowhere: restart from the a priori values and keep the better fit.
    auto suspicious = [&](const OutputErrorResult& f) {
      if (!f.ok()) return true;
      const int dof = std::max(1, f.num_residuals - np);
      if (f.sigma2 > 1.0 + 4.0 * std::sqrt(2.0 / dof)) return true;
      for (int j = 0; j < np; ++j) {
        const std::string& n = r.parameter_names[j];
        if ((n == model::param::kLinearDrag || n == model::param::kQuadraticDrag) && f.theta[j] < 0) return true;
      }
      return false;
    };
    if (suspicious(oe)) {
      Eigen::VectorXd alt = prior;
      for (int j = 0; j < np; ++j) {
        if (state_ls[j] == ParameterState::kDropped) alt[j] = 0.0;
      }
      OutputErrorResult retry = OutputErrorFit(model, fit, alt, s0, oo);
      if (retry.ok() && (!oe.ok() || retry.cost < oe.cost)) {
        r.notes.push_back("output error restarted from the a priori values (from the "
                          "least-squares answer: " + oe.message + ")");
        oe = std::move(retry);
      }
    }
    if (oe.status == OutputErrorStatus::kIllConditioned && !oe.not_identifiable.empty()) {
      // Fix what the data cannot determine and refit once; say so.
      std::vector<std::string> fixed;
      for (const auto& n : oe.not_identifiable) {
        const int j = model.ParameterIndex(n);
        if (j >= 0 && j != im) {
          s0[j] = ParameterState::kFixed;
          fixed.push_back(n);
        }
      }
      if (!fixed.empty()) {
        oe = OutputErrorFit(model, fit, start, s0, oo);
        // The other estimates are conditional on the held values: were those wrong (a priori
        // guesses), the rest absorb the difference with a σ that does not show it (ROMEO heave
        // with W and η held at 0 and 1: kq twice its true value at "±4%"). They are reported
        // but marked unreliable.
        std::vector<std::string> conditional;
        for (int j = 0; j < np; ++j) {
          if (oe.state[j] == ParameterState::kEstimated) {
            conditional.push_back(r.parameter_names[j]);
            r.unreliable.push_back(r.parameter_names[j]);
          }
        }
        r.warnings.push_back("output error: not identifiable from these trials (held at their "
                             "least-squares/a priori values): " + Join(fixed) +
                             " (condition number " + Fmt(oe.condition_number, 3) +
                             "; excite them, e.g. with forces of both signs on every mapping); "
                             "the other estimates (" + Join(conditional) +
                             ") are conditional on the held values and their σ does not include "
                             "that: NOT reliable");
      }
    }
    for (const auto& n : oe.notes) r.notes.push_back("output error: " + n);
    // The refinement is reported only when Levenberg–Marquardt converged to an admissible
    // minimum. Otherwise (iteration limit, failed simulation, singular information) its
    // numbers are not an estimate: the least-squares answer is reported instead, with a
    // warning — or, when there is no least-squares answer, the output error's with a warning.
    const bool have_ls = r.estimator != FinalEstimator::kNone;
    const bool converged = oe.status == OutputErrorStatus::kConverged;
    if (converged || (!have_ls && oe.ok())) {
      theta = oe.theta;
      cov = oe.covariance;
      state = oe.state;
      r.estimator = FinalEstimator::kOutputError;
      if (!converged) {
        r.warnings.push_back("output error stopped at the iteration limit (" +
                             std::to_string(oe.iterations) +
                             ") without converging and there is no least-squares answer to "
                             "fall back to: its estimates are reported but may not be a minimum");
      }
      for (const std::string& n : reinstated) {
        const int j = model.ParameterIndex(n);
        if (state[j] == ParameterState::kEstimated) {
          r.notes.push_back(n + " (dropped as insignificant by the least squares) is significant "
                            "for the output error: " + Fmt(theta[j]) + " ± " +
                            Fmt(std::sqrt(cov(j, j))) + " (its own covariance)");
        }
      }
    } else {
      r.warnings.push_back(oe.message + " — the output-error refinement did not converge; the "
                           "least-squares estimates (" +
                           std::string(FinalEstimatorName(r.estimator)) + ") are reported");
    }
    r.output_error = std::move(oe);
  }
  for (const auto& n : not_excited) {
    r.warnings.push_back(n + " is not excited by the fit trials (kept at " +
                         Fmt(theta[model.ParameterIndex(n)]) + ")");
  }
  r.theta = theta;
  r.covariance = cov;
  r.params = MakeEstimates(r.parameter_names, theta, cov, state);
  // Dropped parameters carry the estimate they had before being dropped.
  auto before = [&](const std::vector<ParameterEstimate>& src) {
    for (const auto& e : src) {
      const int j = model.ParameterIndex(e.name);
      if (j >= 0 && state[j] == ParameterState::kDropped && e.state == ParameterState::kDropped) {
        r.params[j].value_before_drop = e.value_before_drop;
        r.params[j].sigma_before_drop = e.sigma_before_drop;
        r.params[j].significant = false;
      }
    }
  };
  if (r.steady) before(r.steady->estimates);
  if (r.output_error) before(r.output_error->estimates);

  for (const auto& e : r.params) {
    if ((e.name == model::param::kLinearDrag || e.name == model::param::kQuadraticDrag ||
         e.name == model::param::kLinearDragNeg || e.name == model::param::kQuadraticDragNeg) &&
        e.state == ParameterState::kEstimated && e.value < 0 && e.significant) {
      r.warnings.push_back(e.name + " = " + Fmt(e.value) + " ± " + Fmt(e.sigma) +
                           " is negative: physically implausible (drag only dissipates). The "
                           "speed range may be too narrow to separate k and kq, or the model "
                           "misses an effect (thrust map, lag, coupling; try `uuvplan diagnose`)");
      r.unreliable.push_back(e.name);
    }
  }
  if (r.closed_loop_suspected) {
    r.warnings.push_back(
        "closed-loop data suspected: the logged force of most fit trials changes at every row "
        "irregularly (a controller reacting to the measurements), so the force correlates with "
        "the velocity and open-loop estimates are biased (notes/pitfalls.md); m is not a "
        "confident estimate — identify from open-loop trials (steady legs and sines)");
    r.unreliable.push_back(model::param::kMass);
  }
  if (r.estimator == FinalEstimator::kNone) {
    r.status = IdentifyStatus::kFailed;
    r.message = "no estimate: no estimator could fit these trials (see the warnings); they do "
                "not excite the model (longer trials, steady runs at several levels, a sine)";
  } else if (std::none_of(r.params.begin(), r.params.end(), [](const ParameterEstimate& e) {
               return e.state == ParameterState::kEstimated && e.significant;
             })) {
    // Seed 000 §IV-D: every estimate has a percentile error above 51.02% — numbers, but no
    // usable estimate (e.g. a trial far too short for the model).
    r.status = IdentifyStatus::kFailed;
    r.message = "no parameter is identified: every estimate is insignificant (percentile error "
                "above 51.02%); the trials do not excite the model (longer trials, steady runs "
                "at several levels, a sine)";
    r.warnings.push_back(r.message);
  }

  r.timing["output_error"] = seconds_since(stage);
  stage = Clock::now();
  // 5. Validation on every trial of the DOF.
  if (r.estimator != FinalEstimator::kNone) {
    std::vector<TrialFit> fits;
    for (const TrialData* d : fit) fits.push_back(ValidateTrial(model, theta, *d, o.validation));
    for (const TrialData* d : validate) fits.push_back(ValidateTrial(model, theta, *d, o.validation));
    r.fit = Summarize(std::move(fits));
    for (const auto& t : r.fit.trials) {
      if (!std::isfinite(t.velocity_mae)) {
        r.warnings.push_back("the free-run simulation of " + t.name +
                             " with the identified model diverges: the model is not usable for "
                             "simulation as identified");
        break;
      }
    }
    if (r.output_error && r.output_error->ok() && r.output_error->residual_lag1 > 0.8) {
      r.warnings.push_back("the identified model does not explain the measurements to their noise "
                           "level (output-error residuals strongly correlated, lag-1 " +
                           Fmt(r.output_error->residual_lag1, 3) +
                           "): model error; σ are autocorrelation-robust and describe the fit "
                           "of this model, not the truth (try `uuvplan diagnose`)");
    }
  }
  r.timing["validation"] = seconds_since(stage);
  if (r.status != IdentifyStatus::kFailed) {
    r.status = r.warnings.empty() ? IdentifyStatus::kOk : IdentifyStatus::kWarnings;
    r.message = "estimated by " + std::string(FinalEstimatorName(r.estimator));
  }
  return r;
}

}  // namespace

IdentifyResult Identify(const model::Campaign& campaign, const IdentifyOptions& o) {
  std::string error;
  if (!o.IsValid(&error)) throw model::InputError("identify options", error);
  IdentifyResult result;
  std::vector<TrialData> trials;
  trials.reserve(campaign.trials.size());
  for (std::size_t i = 0; i < campaign.trials.size(); ++i) {
    trials.push_back(PrepareTrial(campaign.trials[i], static_cast<int>(i), campaign.vehicle, o.data));
    const TrialData& d = trials.back();
    TrialReport rep;
    rep.index = d.index;
    rep.file = d.name;
    rep.dof = d.dof;
    rep.use = d.use;
    rep.time_offset = d.time_offset;
    rep.position_outliers = d.position_outliers;
    rep.velocity_outliers = d.velocity_outliers;
    rep.gaps = d.gaps;
    rep.notes = d.notes;
    result.trials.push_back(std::move(rep));
  }
  std::vector<Dof> dofs = o.dofs;
  if (dofs.empty()) {
    for (Dof d : model::kAllDofs) {
      for (const TrialData& t : trials) {
        if (t.dof == d && t.use == model::TrialUse::kFit) {
          dofs.push_back(d);
          break;
        }
      }
    }
  }
  if (dofs.empty()) {
    result.status = IdentifyStatus::kFailed;
    result.message = "no trial has `use: fit`: nothing to identify";
    return result;
  }
  for (Dof d : dofs) result.dofs.push_back(IdentifyDof(campaign, d, trials, o));
  result.status = IdentifyStatus::kOk;
  for (const auto& d : result.dofs) {
    if (d.status == IdentifyStatus::kFailed) result.status = IdentifyStatus::kFailed;
    else if (d.status == IdentifyStatus::kWarnings && result.status == IdentifyStatus::kOk)
      result.status = IdentifyStatus::kWarnings;
  }
  result.message = std::to_string(result.dofs.size()) + " DOF(s) identified from " +
                   std::to_string(trials.size()) + " trial(s)";
  return result;
}

}  // namespace uuvplan::ident
