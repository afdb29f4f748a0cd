// `uuvplan next CAMPAIGN --pool POOL [--dof D]... [--target PCT] [--json F] [--commands DIR]`:
// identify from every trial logged so far, turn the estimates and their covariance into the a
// priori knowledge of the design (box = estimates ± 2σ, prior information = covariance⁻¹) and
// plan the single most informative next trial (planner/loop/design_loop.h, docs/loop.md) — what
// a pool team runs between two trials. The result can be run with `simulate --plan` (its
// "trial"); --commands writes its command file and run-sheet line as `schedule --commands`.
// The pool verdict is judged over what is known now: for each DOF identified, the box about its
// estimates that `schedule` plans over for the file `identify --write-vehicle` writes.
// Exit status (docs/cli.md): 0 a trial is planned and the pool hosts the identification of the
// DOFs driven for all or part of the a priori box (the pool verdict, planner/pool/pool_verdict.h,
// printed as `schedule` prints it), or the DOFs have converged (then "trial" is null); 1 no
// trial that is still needed fits the pool, or the pool verdict says it hosts them for no vehicle
// of the box (the best next trial is still printed), or a DOF of a pool not hosted over the
// whole box is stuck (outside the hostable part); 2 bad input;
// 5 stuck (no trial the pool allows adds information); 6 convergence refused (precise but
// non-physical or invalid).
#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "uuvplan/cli/command.h"
#include "uuvplan/cli/exit_status.h"
#include "uuvplan/ident/score.h"
#include "uuvplan/io/command_files.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/next_json.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/loop/design_loop.h"
#include "uuvplan/planner/pool/pool_verdict.h"
#include "uuvplan/text/identify_table.h"
#include "uuvplan/text/loop_text.h"
#include "uuvplan/text/quantity_text.h"
#include "uuvplan/text/trial_text.h"
#include "uuvplan/text/verdict_text.h"

namespace uuvplan::cli {
namespace {

struct NextFlags {
  std::string campaign;
  std::string pool;
  std::vector<std::string> dofs;
  std::string json;
  std::string commands;  ///< --commands DIR: the next trial's command file and run sheet
  bool accept_units = false;
  planner::DesignLoopOptions design;  ///< --target bound here
};

// The planned trial: its design, the travel and thrust it needs, and the σ predicted after it.
void PrintNextTrial(const planner::NextStepResult& r, std::ostream& out) {
  const auto& d = r.trial.design;
  out << "Next: " << d.id << " (" << model::DofName(d.dof) << ", " << r.source << ")\n  "
      << text::TrialLine(d) << "\n  travel "
      << text::TravelText(d.dof, r.trial.travel[0], r.trial.travel[1]) << ", smallest thrust "
      << model::Significant(r.trial.thrust_min, 3) << " N\n  " << r.message << "\n";
  if (!r.predicted.sigma.empty()) {
    out << "  predicted σ after it:";
    for (const auto& [name, s] : r.predicted.sigma) {
      out << "  " << name << " " << text::Quantity(s, model::Unit(name, d.dof));
    }
    out << "\n  assumption: " << planner::kPredictedSigmaAssumption << "\n";
  }
}

// What `next` says before its message when it plans no trial.
constexpr model::EnumNames<planner::NextStatus, 4> kNoTrialLeads{{{
    {planner::NextStatus::kConverged, "No trial needed"},
    {planner::NextStatus::kInfeasible, "No trial can be planned"},
    {planner::NextStatus::kStuck, "No trial adds enough information"},
    {planner::NextStatus::kRefused, "Convergence refused"},
}}};

// Why a candidate has no bottleneck parameter (CandidateGain::parameter empty).
std::string NoBottleneck(const std::vector<planner::DofProgress>& progress, model::Dof dof) {
  for (const auto& p : progress) {
    if (p.dof != dof) continue;
    if (p.precise) {
      return "every parameter of interest is below the target; this trial tests the estimate "
             "(trusted once a second estimate agrees)";
    }
    if (!std::isfinite(p.worst_percent)) {
      return "nothing is estimated yet; this trial starts the estimate";
    }
  }
  return "no parameter of interest above the target is reached by this trial";
}

void PrintNextStep(const planner::NextStepResult& r, const model::Campaign& campaign,
                   const model::Pool& pool, const NextFlags& o, std::ostream& out) {
  const double target = o.design.target_percent;
  out << "Next trial for " << campaign.vehicle.name << " in pool " << pool.name << " after "
      << campaign.trials.size() << " trial(s) of " << o.campaign << "\n\n";
  if (!r.estimates.dofs.empty()) {
    text::PrintIdentifyTable(r.estimates, out);
    out << "\n";
  }
  out << "Parameters of interest (m; kq where significant, else k; every η):\n";
  text::PrintProgress(r.progress, target, out);
  out << "\n";
  if (r.status == planner::NextStatus::kTrial) {
    PrintNextTrial(r, out);
  } else {
    out << kNoTrialLeads.Name(r.status) << ": " << r.message << "\n";
  }
  for (const auto& c : r.candidates) {
    if (c.parameter.empty()) {
      out << "Candidate " << c.trial << " (" << model::DofName(c.dof)
          << "): no σ to predict: " << NoBottleneck(r.progress, c.dof) << "\n";
      continue;
    }
    const std::string unit = model::Unit(c.parameter, c.dof);
    out << "Candidate " << c.trial << " (" << model::DofName(c.dof) << "): σ(" << c.parameter
        << ") "
        << (std::isinf(c.sigma_now) ? "not determined yet" : text::Quantity(c.sigma_now, unit))
        << " → " << text::Quantity(c.sigma_after, unit)
        << (c.first_estimate ? ": this trial determines it (the next is planned from its estimate)"
                             : ", about " + model::Significant(c.trials_to_target, 3) +
                                   " such trials to the target")
        << (c.negligible ? " — negligible" : "") << "\n";
  }
  if (!r.notes.empty()) {
    out << "\nNotes:\n";
    for (const auto& n : r.notes) out << "  - " << n << "\n";
  }
}

// --commands DIR: the planned trial's thruster commands and its run-sheet line, over the box
// the verdict is judged on (`known`: the vehicle with the current estimates).
void WriteNextCommands(const NextFlags& o, const planner::NextStepResult& r,
                       const model::Vehicle& known, const model::Pool& pool,
                       const planner::ScheduleOptions& so, std::ostream& out) {
  if (o.commands.empty()) return;
  if (r.status != planner::NextStatus::kTrial) {
    out << "\nNo trial planned: " << o.commands << " not written.\n";
    return;
  }
  planner::Schedule next;
  next.trials.push_back(r.trial);
  io::WriteScheduleCommands(o.commands, known, pool, next, so);
  out << "\nCommands of " << r.trial.design.id << " and its run-sheet line: " << o.commands << "\n";
}

int RunNext(const NextFlags& o) {
  const model::Campaign campaign = ReadCampaignForIdentification(o.campaign, o.accept_units);
  const model::Pool pool = io::ReadPool(o.pool);
  planner::DesignLoopOptions options = o.design;
  options.dofs = ParseDofFlags(o.dofs);
  const planner::NextStepResult r = planner::NextStep(campaign, pool, options);
  // The pool verdict of the DOFs driven (schedule's and check-pool's answer for them).
  planner::ScheduleOptions so = options.ScheduleAtTarget();
  for (const auto& p : r.progress) so.dofs.push_back(p.dof);
  const model::Vehicle known = ident::WithIdentifiedModels(campaign.vehicle, r.estimates);
  const planner::PoolVerdict verdict = planner::JudgePool(known, pool, so);
  // A DOF that ran trials here and gets no further one is stuck (5) in a pool the verdict
  // hosts; in one it hosts for part of the box or none, the pool's answer is 1 (as `loop`'s,
  // planner::ReadLoopEnd). A trial is planned (0) where the loop may run: all or part.
  int exit_status = ExitStatus(r.status);
  const bool pool_refuses =
      (r.status == planner::NextStatus::kTrial && !planner::LoopMayRun(verdict)) ||
      (r.status == planner::NextStatus::kStuck && !verdict.hosted);
  if (pool_refuses) exit_status = VerdictExit(verdict);
  std::ostream& out = ReportStream(o.json);
  PrintNextStep(r, campaign, pool, o, out);
  text::PrintVerdict(verdict, pool, out);
  WriteNextCommands(o, r, known, pool, so, out);
  if (!o.json.empty()) {
    // The pool's answer is the status a script reads (as `loop`'s).
    WriteJson(o.json, io::NextStepJson(r, o.design.target_percent, verdict, pool, exit_status,
                                       pool_refuses && exit_status != 0));
  }
  return exit_status;
}

void BindNext(CLI::App* sub, NextFlags* o) {
  sub->add_option("CAMPAIGN", o->campaign,
                  "campaign.yaml of the trials run so far, or its directory")
      ->required();
  sub->add_option("--pool", o->pool, "pool.yaml of the pool of the next trial")->required();
  sub->add_option("--dof", o->dofs,
                  "DOF to drive to the target (repeatable; default: the DOFs the campaign "
                  "has trials of, or every DOF the vehicle can plan)");
  AddTargetOption(sub, &o->design.target_percent);
  AddJsonOption(sub, &o->json, "also write the result");
  sub->add_option("--commands", o->commands,
                  "write the next trial's thruster commands (CSV) and its run-sheet line "
                  "(Markdown) into this new directory");
  AddAcceptUnitsFlag(sub, &o->accept_units);
  AddThreadsOption(sub, {&o->design.schedule.planner.threads, &o->design.identify.threads},
                   "identifying (trials and DOFs) and planning the DOFs' candidate trials");
}

const CommandRegistration kNextRegistration(MakeCommand<NextFlags>(
    "next", 45,
    "Identify from the trials so far, then plan the single most informative next trial "
    "(sequential design: box = estimates ± 2σ, prior information = covariance⁻¹).",
    BindNext, RunNext));

}  // namespace
}  // namespace uuvplan::cli
