// The design–identify loop (design_loop.h): `next` and `loop` as steps of the next-trial
// policy (next_trial_policy.h) on a campaign; the loop's trials run in the virtual pool through
// model::VirtualCampaignBuilder, and only the DOF that got a trial is re-identified.
#include "uuvplan/planner/loop/design_loop.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <sstream>

#include "loop/loop_diagnosis.h"
#include "loop/next_trial_policy.h"
#include "options_check.h"
#include "uuvplan/model/campaign_builder.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::planner {
namespace {
using model::Dof;

constexpr model::EnumNames<NextStatus, 5> kNextStatusNames{
    {{{NextStatus::kTrial, "trial"},
      {NextStatus::kConverged, "converged"},
      {NextStatus::kInfeasible, "infeasible"},
      {NextStatus::kStuck, "stuck"},
      {NextStatus::kRefused, "refused"}}}};
constexpr model::EnumNames<LoopStatus, 5> kLoopStatusNames{
    {{{LoopStatus::kConverged, "converged"},
      {LoopStatus::kBudgetSpent, "budget_spent"},
      {LoopStatus::kInfeasible, "infeasible"},
      {LoopStatus::kStuck, "stuck"},
      {LoopStatus::kRefused, "refused"}}}};

std::vector<Dof> CampaignDofs(const model::Campaign& c) {
  std::vector<Dof> out;
  for (Dof dof : model::kAllDofs) {
    for (const auto& e : c.trials) {
      if (e.dof == dof && e.use == model::TrialUse::kFit) {
        out.push_back(dof);
        break;
      }
    }
  }
  return out;
}

// Identification of one DOF from its own trials (what Identify does per DOF) in `vehicle`'s
// model, so that the loop re-identifies only the DOF that got a new trial. Input errors become
// a failed DOF.
ident::DofIdentification IdentifyDof(const model::Campaign& campaign, const model::Vehicle& vehicle,
                                     Dof dof, const ident::IdentifyOptions& options) {
  const model::Campaign sub = internal::DofCampaign(campaign, vehicle, dof);
  ident::IdentifyOptions o = options;
  o.dofs = {dof};
  try {
    ident::IdentifyResult r = ident::Identify(sub, o);
    if (!r.dofs.empty()) return std::move(r.dofs.front());
    ident::DofIdentification f;
    f.dof = dof;
    f.status = ident::IdentifyStatus::kFailed;
    f.message = r.message;
    return f;
  } catch (const model::InputError& e) {
    ident::DofIdentification f;
    f.dof = dof;
    f.status = ident::IdentifyStatus::kFailed;
    f.message = std::string("identification refused the trials: ") + e.what();
    return f;
  }
}

// The DOFs the loop drives: the options' or every DOF the truth has parameters for; each must
// be runnable on the virtual vehicle and plannable.
std::vector<Dof> LoopDofs(const model::Truth& truth, const std::vector<Dof>& asked) {
  const std::vector<Dof> dofs = internal::DofsOrTruths(truth, asked);
  if (dofs.empty()) {
    throw model::InputError("truth", "no dofs.<dof>.params: the truth has nothing to identify");
  }
  for (Dof dof : dofs) {
    if (!truth.dofs.count(dof)) {
      throw model::InputError("truth", "missing dofs." + std::string(model::DofName(dof)) +
                                           ".params: the virtual vehicle cannot run " +
                                           std::string(model::DofName(dof)) + " trials");
    }
    internal::RequirePlannable(truth.vehicle, dof, "truth");
  }
  return dofs;
}

// Puts a DOF's new identification in place of its old one (DOFs in order) and restates the
// campaign's status: its worst DOF's (ident::WorseStatus).
void UpdateEstimates(ident::DofIdentification id, std::size_t trials,
                     ident::IdentifyResult* estimates) {
  auto same = std::find_if(estimates->dofs.begin(), estimates->dofs.end(),
                           [&](const auto& x) { return x.dof == id.dof; });
  if (same != estimates->dofs.end()) {
    *same = std::move(id);
  } else {
    estimates->dofs.push_back(std::move(id));
  }
  std::stable_sort(estimates->dofs.begin(), estimates->dofs.end(),
                   [](const auto& a, const auto& b) { return a.dof < b.dof; });
  estimates->status = ident::IdentifyStatus::kOk;
  for (const auto& x : estimates->dofs) {
    estimates->status = ident::WorseStatus(estimates->status, x.status);
  }
  estimates->message = std::to_string(estimates->dofs.size()) + " DOF(s) identified from " +
                       std::to_string(trials) + " trial(s)";
}

// Each DOF's identification without its newest fit trial (the consistency test's reference
// for `next`, which has no memory of earlier steps); DOFs with one fit trial have none.
std::map<Dof, ident::DofIdentification> PreviousEstimates(const model::Campaign& campaign,
                                                          const std::vector<Dof>& dofs,
                                                          const ident::IdentifyOptions& options) {
  std::map<Dof, ident::DofIdentification> out;
  for (Dof dof : dofs) {
    if (internal::FitTrials(campaign, dof) < 2) continue;
    model::Campaign earlier = campaign;
    for (auto e = earlier.trials.end(); e != earlier.trials.begin();) {
      --e;
      if (e->dof == dof && e->use == model::TrialUse::kFit) {
        earlier.trials.erase(e);
        break;
      }
    }
    out.emplace(dof, IdentifyDof(earlier, earlier.vehicle, dof, options));
  }
  return out;
}

std::string BudgetSpentMessage(const LoopOptions& options,
                               const std::vector<DofProgress>& progress) {
  std::ostringstream m;
  m << "trial budget of " << options.budget << " spent before the target of "
    << model::Significant(options.step.target_percent, 3) << "%:";
  for (const auto& p : progress) {
    if (p.converged) continue;
    m << " " << model::DofName(p.dof) << " " << p.worst << " at "
      << (std::isfinite(p.worst_percent) ? model::Significant(p.worst_percent, 3) + "%"
                                         : "not estimated");
    if (p.precise && !p.doubts.empty()) m << " but not trusted (" << p.doubts.front() << ")";
    m << ";";
  }
  m << " raise --budget or the target";
  return m.str();
}

// Whether the loop stops before running the decided trial; if so, sets the result's status.
bool LoopEnds(const internal::Decision& d, const LoopOptions& options, LoopResult* result) {
  if (d.status != NextStatus::kTrial) {
    result->status = d.status == NextStatus::kConverged    ? LoopStatus::kConverged
                     : d.status == NextStatus::kInfeasible ? LoopStatus::kInfeasible
                     : d.status == NextStatus::kStuck      ? LoopStatus::kStuck
                                                           : LoopStatus::kRefused;
    result->message = d.message;
    return true;
  }
  if (static_cast<int>(result->iterations.size()) >= options.budget) {
    result->status = LoopStatus::kBudgetSpent;
    result->message = BudgetSpentMessage(options, d.progress);
    return true;
  }
  return false;
}

const DofProgress* ProgressOf(const std::vector<DofProgress>& progress, Dof dof) {
  for (const auto& p : progress) {
    if (p.dof == dof) return &p;
  }
  return nullptr;
}

// Predicted against achieved σ of the trial's DOF, and whether the trial brought new
// information: a parameter of interest estimated for the first time, or gaining at least
// min_information_ratio of its information, or the DOF converging (the trial confirmed it).
void MeasureGain(const DofProgress* before, const LoopOptions& options, LoopIteration* it) {
  for (const auto& [name, predicted] : it->at_estimates.sigma) {
    double achieved = std::numeric_limits<double>::quiet_NaN();
    for (const auto& e : it->params[it->dof]) {
      if (e.name == name && e.state == ident::ParameterState::kEstimated) achieved = e.sigma;
    }
    it->sigma[name] = {predicted, achieved};
  }
  const DofProgress* after = ProgressOf(it->progress, it->dof);
  if (before == nullptr || after == nullptr) return;
  it->new_information = after->converged;
  for (std::size_t i = 0; i < after->interest.size() && i < before->interest.size(); ++i) {
    const InterestParameter& a = after->interest[i];
    const InterestParameter& b = before->interest[i];
    if (a.name != b.name || !a.estimated) continue;
    const double ratio = b.estimated ? std::pow(b.sigma / a.sigma, 2) - 1.0
                                     : std::numeric_limits<double>::infinity();
    if (ratio >= options.step.min_information_ratio) it->new_information = true;
  }
}

// Under LoopOptions::diagnose, diagnoses the trial's DOF first (its model may change), then
// identifies it in the working model. Keeps the estimate before it for the consistency test,
// unless the model changed (the two are then not comparable).
ident::DofIdentification IdentifyTrialDof(const LoopOptions& options,
                                          const model::Campaign& campaign,
                                          const ident::IdentifyResult& estimates,
                                          internal::WorkingModel* working,
                                          internal::LoopMemory* memory, LoopIteration* it) {
  memory->previous.erase(it->dof);
  bool changed = false;
  if (options.diagnose) {
    internal::ModelChange change = internal::AdoptFindings(campaign, it->dof, *options.diagnose,
                                                           options.settled_aic_gap, working);
    const std::string dof(model::DofName(it->dof));
    if (!change.note.empty()) it->notes.push_back(dof + ": diagnose: " + change.note);
    memory->model_doubts[it->dof] = working->doubts[it->dof];
    changed = change.changed();
    it->effects_entered = std::move(change.entered);
    it->effects_left = std::move(change.left);
  }
  const ident::DofIdentification* old = estimates.Find(it->dof);
  if (old != nullptr && !changed) memory->previous.emplace(it->dof, *old);
  return IdentifyDof(campaign, working->vehicle, it->dof, options.step.identify);
}

// Runs the decided trial in the virtual pool, re-identifies its DOF (keeping the identification
// before it for the consistency test) and measures progress.
LoopIteration RunIteration(internal::Decision d, const LoopOptions& options,
                           const std::vector<Dof>& dofs, model::VirtualCampaignBuilder* builder,
                           ident::IdentifyResult* estimates, internal::WorkingModel* working,
                           internal::LoopMemory* memory) {
  LoopIteration it;
  it.index = static_cast<int>(builder->campaign().trials.size());
  it.dof = d.dof;
  it.source = d.source;
  // Ids are unique in a campaign (they name the log files): an a priori trial keeps its id.
  it.trial = d.trial;
  it.predicted = d.predicted;
  it.candidates = d.candidates;
  it.at_estimates = d.at_estimates;
  it.notes = d.notes;
  it.start = builder->clock();
  builder->Append(d.trial.design);
  it.pool_time = builder->clock() - options.step.schedule.planner.pause_s;
  const model::Campaign& campaign = builder->campaign();
  ident::DofIdentification id =
      IdentifyTrialDof(options, campaign, *estimates, working, memory, &it);
  for (const auto& w : id.warnings) {
    it.notes.push_back(std::string(model::DofName(d.dof)) + ": identify: " + w);
  }
  UpdateEstimates(std::move(id), campaign.trials.size(), estimates);
  for (const auto& x : estimates->dofs) it.params[x.dof] = x.params;
  for (Dof dof : dofs) {
    const auto prev = memory->previous.find(dof);
    it.progress.push_back(EvaluateProgress(
        campaign.vehicle, dof, estimates->Find(dof), internal::FitTrials(campaign, dof),
        options.step, prev == memory->previous.end() ? nullptr : &prev->second));
    internal::AddModelDoubts(*memory, &it.progress.back());
  }
  MeasureGain(ProgressOf(d.progress, d.dof), options, &it);
  return it;
}

// A design never runs again after `max_repeats` runs without new information; its
// DOF is stuck (with the limit that keeps the planner on that design). True when it stopped.
bool StopRepeat(internal::Planner& planner, const internal::Decision& d, const LoopResult& result,
                const model::Campaign& campaign, const LoopOptions& options,
                internal::LoopMemory* memory) {
  int idle = 0;
  for (const auto& it : result.iterations) {
    if (!it.new_information && SameDesign(it.trial.design, d.trial.design)) ++idle;
  }
  if (idle < options.max_repeats) return false;
  const DofProgress* p = ProgressOf(d.progress, d.dof);
  CandidateGain gain = d.candidates.empty() ? CandidateGain{} : d.candidates.back();
  std::string reason =
      "this design ran " + std::to_string(idle) + " times without new information; " +
      internal::StuckReason(planner, campaign, *p, result.estimates.Find(d.dof), d.trial, gain);
  memory->stopped[d.dof] = {d.dof, NextStatus::kStuck, reason};
  return true;
}

// Counts consecutive failed consistency tests of the trial's DOF; refuses the DOF after
// LoopOptions::max_inconsistent of them.
void TrackConsistency(const LoopIteration& it, const LoopOptions& options,
                      std::map<Dof, int>* streak, internal::LoopMemory* memory) {
  const DofProgress* p = ProgressOf(it.progress, it.dof);
  if (p == nullptr || !p->consistency.tested) return;
  int& n = (*streak)[it.dof];
  n = p->consistency.consistent ? 0 : n + 1;
  if (n >= options.max_inconsistent) {
    memory->stopped[it.dof] = {it.dof, NextStatus::kRefused,
                               "estimates inconsistent across " + std::to_string(n) +
                                   " consecutive trials (last: " + p->consistency.text +
                                   "): the model does not explain every trial, or its σ are "
                                   "overconfident (try `uuvplan diagnose`)"};
  }
}

}  // namespace

bool DesignLoopOptions::IsValid(std::string* error) const {
  internal::OptionsCheck check("DesignLoopOptions", error);
  check
      .Require(target_percent > 0 && std::isfinite(target_percent), "target_percent",
               model::Significant(target_percent, 3), "0 < target_percent < inf")
      .Require(usable_percent > 0, "usable_percent", model::Significant(usable_percent, 3),
               "usable_percent > 0")
      .Require(consistency_level > 0 && consistency_level < 1, "consistency_level",
               model::Significant(consistency_level, 3), "0 < consistency_level < 1")
      .Require(max_trials_to_target > 0, "max_trials_to_target",
               model::Significant(max_trials_to_target, 3), "> 0")
      .Require(min_information_ratio > 0, "min_information_ratio",
               model::Significant(min_information_ratio, 3), "> 0");
  return check.ok() && schedule.IsValid(error) && identify.IsValid(error);
}

bool LoopOptions::IsValid(std::string* error) const {
  internal::OptionsCheck check("LoopOptions", error);
  check.Require(budget >= 1, "budget", budget, "budget >= 1")
      .Require(command_rate_hz > 0, "command_rate_hz", model::Significant(command_rate_hz, 3),
               "> 0")
      .Require(max_repeats >= 0, "max_repeats", max_repeats, "max_repeats >= 0")
      .Require(max_inconsistent >= 1, "max_inconsistent", max_inconsistent, "max_inconsistent >= 1")
      .Require(settled_aic_gap >= 0, "settled_aic_gap", model::Significant(settled_aic_gap, 3),
               ">= 0");
  return check.ok() && step.IsValid(error) && (!diagnose || diagnose->IsValid(error));
}

std::string_view NextStatusName(NextStatus s) { return kNextStatusNames.Name(s); }

std::string_view LoopStatusName(LoopStatus s) { return kLoopStatusNames.Name(s); }

NextStepResult NextStep(const model::Campaign& campaign, const model::Pool& pool,
                        const DesignLoopOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) throw model::InputError("next options", error);
  std::vector<Dof> dofs = options.dofs;
  if (dofs.empty()) dofs = CampaignDofs(campaign);
  if (dofs.empty()) {
    for (Dof dof : model::kAllDofs) {
      if (internal::Plannable(campaign.vehicle, dof)) dofs.push_back(dof);
    }
  }
  const std::string where = campaign.vehicle_file.empty() ? campaign.path : campaign.vehicle_file;
  for (Dof dof : dofs) internal::RequirePlannable(campaign.vehicle, dof, where);

  NextStepResult r;
  if (!CampaignDofs(campaign).empty()) {
    ident::IdentifyOptions io = options.identify;
    io.dofs.clear();
    r.estimates = ident::Identify(campaign, io);
  } else {
    r.estimates.status = ident::IdentifyStatus::kFailed;
    r.estimates.message = "no fit trial yet: nothing to identify";
  }
  internal::Planner planner{campaign.vehicle, pool, options, {}, {}};
  const internal::LoopMemory memory{PreviousEstimates(campaign, dofs, options.identify), {}, {}};
  internal::Decision d = internal::Decide(planner, campaign, dofs, r.estimates, memory);
  r.status = d.status;
  r.candidates = std::move(d.candidates);
  r.message = std::move(d.message);
  r.progress = std::move(d.progress);
  r.dof = d.dof;
  r.source = std::move(d.source);
  r.trial = std::move(d.trial);
  r.predicted = std::move(d.predicted);
  r.notes = std::move(d.notes);
  for (const auto& n : r.estimates.notes) r.notes.push_back("identify: " + n);
  return r;
}

bool SameDesign(const model::TrialDesign& a, const model::TrialDesign& b) {
  auto near = [](double x, double y, double rel) {
    return std::abs(x - y) <= rel * std::max(std::abs(x), std::abs(y)) + 1e-9;
  };
  if (a.dof != b.dof || a.kind != b.kind || a.mapping != b.mapping ||
      a.segments.size() != b.segments.size() || !near(a.duration, b.duration, 0.1)) {
    return false;
  }
  for (std::size_t i = 0; i < a.segments.size(); ++i) {
    if (a.segments[i].mapping != b.segments[i].mapping ||
        !near(a.segments[i].force, b.segments[i].force, 0.05)) {
      return false;
    }
  }
  return near(a.force, b.force, 0.05) && near(a.offset, b.offset, 0.05) &&
         near(a.amplitude, b.amplitude, 0.05) && near(a.omega, b.omega, 0.05);
}

int MostUninformativeRepeats(const std::vector<LoopIteration>& iterations) {
  int most = 0;
  for (const auto& it : iterations) {
    if (it.new_information) continue;
    int runs = 0;
    for (const auto& other : iterations) {
      if (!other.new_information && SameDesign(other.trial.design, it.trial.design)) ++runs;
    }
    most = std::max(most, runs);
  }
  return most;
}

double PoolTime(const std::vector<model::TrialDesign>& designs, double pause_s) {
  double t = 0.0;
  for (const auto& d : designs) t += d.duration;
  if (designs.size() > 1) t += pause_s * static_cast<double>(designs.size() - 1);
  return t;
}

LoopResult RunLoop(const model::Truth& truth, const model::Pool& pool, const LoopOptions& options,
                   const std::function<void(const LoopIteration&)>& on_iteration) {
  std::string error;
  if (!options.IsValid(&error)) throw model::InputError("loop options", error);
  const std::vector<Dof> dofs = LoopDofs(truth, options.step.dofs);
  LoopResult result;
  result.estimates.status = ident::IdentifyStatus::kFailed;
  result.estimates.message = "no trial yet";
  model::VirtualCampaignOptions virtual_pool;
  virtual_pool.seed = options.seed;
  virtual_pool.command_rate_hz = options.command_rate_hz;
  virtual_pool.pause_s = options.step.schedule.planner.pause_s;
  virtual_pool.unwrap_headings = true;  // as `uuvplan next` reads the logs
  virtual_pool.pool = pool;
  model::VirtualCampaignBuilder builder(truth, virtual_pool);
  internal::Planner planner{truth.vehicle, pool, options.step, {}, {}};
  planner.Prepare(dofs);  // every DOF starts with its a priori schedule: plan them at once
  internal::LoopMemory memory;
  internal::WorkingModel working{truth.vehicle, {}, {}};
  std::map<Dof, int> inconsistent;
  std::map<Dof, std::vector<model::TrialDesign>> per_dof;
  for (;;) {
    const auto t0 = std::chrono::steady_clock::now();
    internal::Decision d =
        internal::Decide(planner, builder.campaign(), dofs, result.estimates, memory);
    result.progress = d.progress;
    if (LoopEnds(d, options, &result)) break;
    if (StopRepeat(planner, d, result, builder.campaign(), options, &memory)) continue;
    LoopIteration it =
        RunIteration(std::move(d), options, dofs, &builder, &result.estimates, &working, &memory);
    TrackConsistency(it, options, &inconsistent, &memory);
    per_dof[it.dof].push_back(it.trial.design);
    planner.run[it.dof].push_back(it.trial);
    result.pool_time = it.pool_time;
    it.wall_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (on_iteration) on_iteration(it);
    result.iterations.push_back(std::move(it));
  }
  result.campaign = builder.Take();
  result.converged = result.status == LoopStatus::kConverged;
  const double pause = options.step.schedule.planner.pause_s;
  for (const auto& [dof, designs] : per_dof) result.dof_pool_time[dof] = PoolTime(designs, pause);
  return result;
}

}  // namespace uuvplan::planner
