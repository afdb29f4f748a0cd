// Identification of a campaign: every trial prepared once, then each DOF through the stages
// of identify_stages.h (prepare → estimate → refine → validate), timed.
#include "uuvplan/ident/identify.h"

#include <algorithm>

#include "diagnosis/parallel.h"
#include "identify_stages.h"
#include "options_check.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::ident {
namespace {

using model::Dof;

constexpr model::EnumNames<IdentifyStatus, 4> kIdentifyStatusNames{{{
    {IdentifyStatus::kOk, "ok"},
    {IdentifyStatus::kWarnings, "warnings"},
    {IdentifyStatus::kModelError, "model_error"},
    {IdentifyStatus::kFailed, "failed"},
}}};

constexpr model::EnumNames<FinalEstimator, 7> kFinalEstimatorNames{{{
    {FinalEstimator::kOutputError, "output_error"},
    {FinalEstimator::kSteadyStateIntegral, "steady_state+integral"},
    {FinalEstimator::kOneStep, "one_step_ls"},
    {FinalEstimator::kClosedLoopIv, "closed_loop_iv"},
    {FinalEstimator::kSteadyState, "steady_state"},
    {FinalEstimator::kRls, "rls"},
    {FinalEstimator::kNone, "none"},
}}};

// The values of `identify --method`.
constexpr model::EnumNames<Method, 6> kMethodNames{{{
    {Method::kChain, "chain"},
    {Method::kLeastSquares, "ls"},
    {Method::kIntegral, "integral"},
    {Method::kOneStep, "one-step"},
    {Method::kRls, "rls"},
    {Method::kOutputError, "output-error"},
}}};

// A vehicle file that gives a DOF's parameters (a model written by `identify` or `diagnose
// --write-vehicle`): the standard parameters are estimated afresh, any effect it adds is
// refitted from its values (FitWrittenModel).
void NoteWrittenModel(const model::Vehicle& vehicle, Dof dof, DofIdentification* r) {
  if (!vehicle.models.count(dof)) return;
  const std::string name(model::DofName(dof));
  r->notes.push_back("the vehicle file gives " + name + " parameters (dofs." + name +
                     ".params and any effects): the standard ones are estimated afresh from the a "
                     "priori values, any effect is refitted from the file's values; `uuvplan "
                     "score` scores the file's model on this campaign as written");
}

// One DOF through the four stages; `prepare_s` is the time its trials took to prepare.
DofIdentification IdentifyDof(const model::Campaign& campaign, Dof dof,
                              const std::vector<TrialData>& all, double prepare_s,
                              const IdentifyOptions& o) {
  Stopwatch watch;
  DofIdentification r;
  r.dof = dof;
  const stages::DofTrials trials = stages::SelectTrials(dof, all, o.data.outliers, &r);
  if (trials.fit.empty()) {
    r.status = IdentifyStatus::kFailed;
    r.message = "no fit trial for " + std::string(model::DofName(dof)) +
                " (mark at least one trial `use: fit`)";
    return r;
  }
  r.structure = stages::ChooseStructure(campaign.vehicle, dof, trials, o);
  const model::DofModel model(campaign.vehicle, r.structure);
  r.parameter_names = model.parameter_names();
  stages::StageInputs c{campaign.vehicle,
                        trials,
                        model,
                        PriorTheta(campaign.vehicle, model, o.initial_guess),
                        o.steady,
                        o.output_error,
                        model.ParameterIndex(model::param::kMass)};
  c.steady.selection = c.output_error.selection = o.selection;
  r.closed_loop_suspected = stages::SuspectClosedLoop(trials.fit, o.closed_loop);
  NoteWrittenModel(campaign.vehicle, dof, &r);
  r.timing.push_back({"prepare", prepare_s + watch.Lap()});

  if (o.method != Method::kChain) {
    r.notes.push_back("method " + std::string(MethodName(o.method)) +
                      " (identify --method): its own estimate, no other stage");
  }
  const stages::LeastSquaresAnswer ls = stages::EstimateStage(c, o, &r);
  r.timing.push_back({"estimate", watch.Lap()});
  const stages::StageEstimate final_estimate = stages::RefineStage(c, ls, o, &r);
  r.timing.push_back({"refine", watch.Lap()});
  stages::ReportEstimates(c, ls, final_estimate, &r);
  const bool refit = o.written_model && o.method == Method::kChain && o.refine;
  if (const auto written = refit ? stages::FitWrittenModel(c, &r) : nullptr) {
    r.timing.push_back({"written model", watch.Lap()});
    const stages::StageInputs in_written{c.vehicle,
                                         c.trials,
                                         *written,
                                         r.theta,
                                         c.steady,
                                         c.output_error,
                                         written->ParameterIndex(model::param::kMass)};
    stages::ValidateStage(in_written, o.validation, &r);
  } else {
    stages::ValidateStage(c, o.validation, &r);
  }
  r.timing.push_back({"validate", watch.Lap()});
  return r;
}

TrialReport ReportOf(const TrialData& d) {
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
  return rep;
}

// The DOFs asked for, or every DOF with a fit trial.
std::vector<Dof> DofsToIdentify(const std::vector<TrialData>& trials, const IdentifyOptions& o) {
  std::vector<Dof> dofs = o.dofs;
  if (!dofs.empty()) return dofs;
  for (Dof d : model::kAllDofs) {
    for (const TrialData& t : trials) {
      if (t.dof == d && t.use == model::TrialUse::kFit) {
        dofs.push_back(d);
        break;
      }
    }
  }
  return dofs;
}

}  // namespace

bool IdentifyOptions::IsValid(std::string* error) const {
  return data.IsValid(error) && steady.IsValid(error) && inertia.IsValid(error) &&
         one_step.IsValid(error) && closed_loop_iv.IsValid(error) && output_error.IsValid(error) &&
         rls.IsValid(error) &&
         Require(refine || method == Method::kChain,
                 "--no-refine (refine = false) applies to the default chain only; method " +
                     std::string(MethodName(method)) + " runs its own estimator alone",
                 error) &&
         Require(steady_windows.empty() || UsesSteadyState(method),
                 "--steady (steady_windows) marks steady-state segments, which method " +
                     std::string(MethodName(method)) + " does not use (only chain, ls, integral)",
                 error) &&
         Require(closed_loop != ClosedLoop::kYes || method == Method::kChain,
                 "method " + std::string(MethodName(method)) +
                     " is biased on closed-loop data (--closed-loop yes): the command correlates "
                     "with the measurement noise; use the default chain (closed-loop "
                     "instrumental variables)",
                 error) &&
         Require(validation.step_s > 0, "ValidationOptions::step_s must be > 0", error) &&
         Require(threads >= 0, "IdentifyOptions::threads must be >= 0 (0: one per core)", error);
}

std::string_view IdentifyStatusName(IdentifyStatus s) { return kIdentifyStatusNames.Name(s); }

std::string_view FinalEstimatorName(FinalEstimator e) { return kFinalEstimatorNames.Name(e); }

std::string_view MethodName(Method m) { return kMethodNames.Name(m); }

std::optional<Method> ParseMethod(std::string_view name) { return kMethodNames.Parse(name); }

std::string MethodNames() { return kMethodNames.List(); }

bool UsesSteadyState(Method m) {
  return m == Method::kChain || m == Method::kLeastSquares || m == Method::kIntegral;
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

namespace {

IdentifyResult IdentifyCampaign(const model::Campaign& campaign, model::Campaign* release,
                                const IdentifyOptions& o) {
  std::string error;
  if (!o.IsValid(&error)) throw model::InputError("identify options", error);
  IdentifyResult result;
  result.method = o.method;
  // Trials, then DOFs, in parallel: each job fills its own slot (diagnosis/parallel.h).
  std::vector<TrialData> trials(campaign.trials.size());
  std::vector<double> prepare_s(trials.size());  // per trial
  diagnosis::ParallelFor(trials.size(), o.threads, [&](std::size_t i) {
    Stopwatch watch;
    trials[i] = PrepareTrial(campaign.trials[i], static_cast<int>(i), campaign.vehicle, o.data,
                             release ? &release->trials[i].log : nullptr);
    prepare_s[i] = watch.Lap();
  });
  for (const TrialData& t : trials) result.trials.push_back(ReportOf(t));
  const std::vector<Dof> dofs = DofsToIdentify(trials, o);
  if (dofs.empty()) {
    result.status = IdentifyStatus::kFailed;
    result.message = "no trial has `use: fit`: nothing to identify";
    return result;
  }
  for (Dof d : dofs) stages::CheckMethodFits(d, trials, o);
  result.dofs.resize(dofs.size());
  diagnosis::ParallelFor(dofs.size(), o.threads, [&](std::size_t k) {
    double share = 0.0;
    for (const TrialData& t : trials) share += t.dof == dofs[k] ? prepare_s[t.index] : 0.0;
    result.dofs[k] = IdentifyDof(campaign, dofs[k], trials, share, o);
  });
  result.status = IdentifyStatus::kOk;
  std::string failed;
  for (const auto& d : result.dofs) {
    result.status = WorseStatus(result.status, d.status);
    if (d.status == IdentifyStatus::kFailed) {
      failed += (failed.empty() ? "" : ", ") + std::string(model::DofName(d.dof));
    }
  }
  result.message =
      std::to_string(result.dofs.size()) + " DOF(s) identified from " +
      std::to_string(trials.size()) + " trial(s)" +
      (failed.empty() ? "" : "; failed: " + failed + " (the reason on each DOF's FAILED line)");
  return result;
}

}  // namespace

IdentifyResult Identify(const model::Campaign& campaign, const IdentifyOptions& o) {
  return IdentifyCampaign(campaign, nullptr, o);
}

IdentifyResult IdentifyReleasingLogs(model::Campaign* campaign, const IdentifyOptions& o) {
  return IdentifyCampaign(*campaign, campaign, o);
}

}  // namespace uuvplan::ident
