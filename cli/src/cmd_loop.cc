// `uuvplan loop --truth TRUTH.yaml --pool POOL [--target PCT] [--budget N] [--seed N]
// [--dof D]... [--diagnose] [--json F] [--write-vehicle OUT] [--verbose]`: the design–identify
// loop against the virtual vehicle of a truth file (planner/loop/design_loop.h, docs/loop.md):
// plan the most informative next trial, run it on the virtual vehicle, identify from every
// trial so far (with --diagnose, diagnose it and add the effects found to the model), and
// repeat until every parameter of interest (m; kq where significant, else k; every η) has a
// percentile error below the target, or the trial budget is spent. Prints each iteration
// (trial planned, estimates, σ, effects added, pool time) and the total pool time.
// Deterministic for a given seed.
// Exit status (docs/cli.md, docs/loop.md): 0 converged; 1 a DOF cannot be given the trial it
// needs in this pool; 2 bad input; 4 budget spent; 5 stuck (no trial the pool allows adds
// information); 6 convergence refused (estimates inconsistent, non-physical or invalid).
#include <cmath>
#include <iomanip>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

#include "uuvplan/cli/command.h"
#include "uuvplan/cli/exit_status.h"
#include "uuvplan/cli/model_vehicle_file.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/loop_json.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/thrust_reference.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/loop/design_loop.h"
#include "uuvplan/planner/pool/pool_verdict.h"
#include "uuvplan/text/loop_text.h"
#include "uuvplan/text/quantity_text.h"
#include "uuvplan/text/trial_text.h"
#include "uuvplan/text/verdict_text.h"

namespace uuvplan::cli {
namespace {

using model::InputError;

struct LoopFlags {
  std::string truth;
  std::string pool;
  std::vector<std::string> dofs;
  std::string json;
  std::string write_vehicle;
  bool verbose = false;
  bool diagnose = false;
  planner::LoopOptions loop;  ///< --target, --budget, --seed bound here
};

// "σ predicted → achieved: m 31.2 → 29.8 kg, kq 120 → 98.4 N·s²/m²".
std::string SigmaLine(const planner::LoopIteration& it) {
  std::ostringstream s;
  s << "σ predicted → achieved:";
  const char* sep = " ";
  for (const auto& [name, pa] : it.sigma) {
    s << sep << name << " " << model::Significant(pa[0], 3) << " → "
      << (std::isfinite(pa[1]) ? model::Significant(pa[1], 3) : std::string("—"))
      << text::UnitSuffix(model::Unit(name, it.dof));
    sep = ", ";
  }
  return s.str();
}

void PrintIteration(const planner::LoopIteration& it, double target, bool verbose,
                    std::ostream& out) {
  const auto& d = it.trial.design;
  out << "#" << std::left << std::setw(3) << it.index + 1 << std::setw(6) << model::DofName(d.dof)
      << std::setw(20) << d.id << text::TrialLine(d) << "\n     " << it.source << "; pool time "
      << model::DurationText(it.pool_time) << (it.new_information ? "" : "; no new information")
      << "\n";
  for (const auto& p : it.progress) {
    if (p.dof != it.dof) continue;
    out << "     ";
    for (const auto& q : p.interest) out << " " << text::InterestText(p.dof, q, target);
    out << "\n";
    for (const auto& q : p.interest) {
      if (!q.physical) out << "      ! " << q.flag << "\n";
    }
    if (p.consistency.tested) out << "      " << p.consistency.text << "\n";
  }
  if (!it.sigma.empty()) out << "      " << SigmaLine(it) << "\n";
  for (const auto& e : it.effects_entered) {
    out << "      + " << text::EffectEnteredText(it.dof, e) << "\n";
  }
  for (const auto& e : it.effects_left) {
    out << "      - " << text::EffectLeftText(it.dof, e) << "\n";
  }
  if (verbose) {
    for (const auto& n : it.notes) out << "     note: " << n << "\n";
  }
  out.flush();
}

// Before any file is read: a budget the loop can spend (--target is checked by its option).
void CheckLoopFlags(const planner::LoopOptions& lo) {
  if (lo.budget < 1) {
    throw InputError("--budget",
                     "expected a number of trials >= 1, got " + std::to_string(lo.budget));
  }
}

// The DOFs of --dof, each one the truth has the parameters to simulate.
std::vector<model::Dof> SimulableDofs(const LoopFlags& o, const model::Truth& truth) {
  const std::vector<model::Dof> dofs = ParseDofFlags(o.dofs);
  for (const model::Dof dof : dofs) {
    const std::string n(model::DofName(dof));
    if (!truth.dofs.count(dof)) {
      throw InputError(o.truth, "missing dofs." + n + ".params: --dof " + n + " needs the true " +
                                    n + " parameters to simulate");
    }
  }
  return dofs;
}

// The truth restated at the thrust_map reference of each DOF's final estimate (a thrust map's m,
// drag and bias depend on it: model/thrust_reference.h), with a line saying so.
model::Truth AtEstimatesThrustReference(model::Truth truth, const ident::IdentifyResult& estimates,
                                        std::ostream& out) {
  constexpr double kNone = std::numeric_limits<double>::quiet_NaN();
  for (auto& [dof, t] : truth.dofs) {
    const ident::DofIdentification* id = estimates.Find(dof);
    if (id == nullptr) continue;
    const double to = id->structure.Setting(model::param::kThrustReference, kNone);
    const auto own = t.settings.find(model::param::kThrustReference);
    const double from = own == t.settings.end() ? kNone : own->second;
    if (!std::isfinite(to) || !model::RestateThrustReference(to, &t)) continue;
    const std::string unit = model::Unit(model::param::kBias, dof);
    out << "  " << model::DofName(dof) << ": the truth restated at the estimate's thrust map "
        << "reference " << text::Quantity(to, unit) << " (it has " << text::Quantity(from, unit)
        << "): m, drag and bias scale with it\n";
  }
  return truth;
}

void PrintLoopSummary(const planner::LoopResult& r, const planner::LoopOptions& lo,
                      const model::Truth& truth, const std::string& message, std::ostream& out) {
  out << "\n"
      << (r.converged ? "Converged"
                      : "NOT converged (" + std::string(planner::LoopStatusName(r.status)) + ")")
      << " after " << r.iterations.size() << " trial(s): " << message << "\n"
      << "Pool time: " << model::DurationText(r.pool_time) << " ("
      << model::DurationText(lo.step.schedule.planner.pause_s)
      << " pauses between trials included)";
  for (const auto& [dof, t] : r.dof_pool_time) {
    out << "; " << model::DofName(dof) << " " << model::DurationText(t);
  }
  out << "\nassumption: " << planner::kPredictedSigmaAssumption;
  if (lo.diagnose) out << "\nassumption: " << text::DiagnosedModelAssumption();
  out << "\n\nFinal estimates against the truth:\n";
  const model::Truth compared = AtEstimatesThrustReference(truth, r.estimates, out);
  text::PrintProgress(r.progress, lo.step.target_percent, out, &compared);
}

int RunLoopCommand(const LoopFlags& o) {
  CheckLoopFlags(o.loop);
  const model::Truth truth = io::ReadTruth(o.truth);
  const model::Pool pool = io::ReadPool(o.pool);
  planner::LoopOptions lo = o.loop;
  lo.step.dofs = SimulableDofs(o, truth);
  if (o.diagnose) {
    lo.diagnose.emplace();
    lo.diagnose->threads = lo.step.identify.threads;
  }
  const double target = lo.step.target_percent;
  std::ostream& out = ReportStream(o.json);
  out << "Design–identify loop on the virtual '" << truth.vehicle.name << "' of " << o.truth
      << " in pool " << pool.name << " (target " << target << "%, budget " << lo.budget
      << " trials, seed " << lo.seed << ")\n"
      << "Parameters of interest: m; kq where significant, else k; every η "
         "(* = above the target)\n\n";
  // Before any trial: the pool verdict (planner/pool/pool_verdict.h) on the loop's DOFs; a pool
  // that hosts them for no vehicle of the a priori box is refused with schedule's sentence and exit
  // status; one that hosts them for part of the box is run, and the loop's end read against it.
  planner::ScheduleOptions so = lo.step.ScheduleAtTarget();
  so.dofs = lo.step.dofs;
  if (so.dofs.empty()) {
    for (const auto& [dof, params] : truth.dofs) so.dofs.push_back(dof);
  }
  const planner::PoolVerdict verdict = planner::JudgePool(truth.vehicle, pool, so);
  if (!verdict.hosted) text::PrintVerdict(verdict, pool, out);
  if (!planner::LoopMayRun(verdict)) {
    if (!o.json.empty()) {
      WriteJson(o.json, io::RefusedLoopJson(verdict, pool, VerdictExit(verdict)));
    }
    return VerdictExit(verdict);
  }
  if (!verdict.hosted) out << "\n";
  const auto progress = TerminalProgress("loop");
  planner::LoopResult r = planner::RunLoop(truth, pool, lo, [&](const planner::LoopIteration& it) {
    PrintIteration(it, target, o.verbose, out);
    progress("trial " + std::to_string(it.index + 1) + " " + it.trial.design.id + " done");
  });
  planner::ReadLoopEnd(verdict, &r);
  PrintLoopSummary(r, lo, truth, text::LoopEndMessage(r, verdict, pool), out);
  if (!o.json.empty()) {
    WriteJson(o.json, io::LoopResultJson(r, lo, verdict, pool, ExitStatus(r.status)));
  }
  if (!o.write_vehicle.empty() &&
      !WriteIdentifiedVehicle("loop", o.write_vehicle, "--truth " + o.truth + " --pool " + o.pool,
                              "", truth.vehicle, r.estimates,
                              "the model the loop identified last")) {
    return ExitStatus(r.status) == 0 ? 1 : ExitStatus(r.status);
  }
  return ExitStatus(r.status);
}

void BindLoop(CLI::App* sub, LoopFlags* o) {
  sub->add_option("--truth", o->truth, "truth file: a vehicle plus dofs.<dof>.params")->required();
  sub->add_option("--pool", o->pool, "pool.yaml")->required();
  AddTargetOption(sub, &o->loop.step.target_percent);
  sub->add_option("--budget", o->loop.budget, "most trials to run")->capture_default_str();
  sub->add_option("--seed", o->loop.seed,
                  "seed of the virtual pool (trial i draws from its own stream, as `simulate`)")
      ->capture_default_str();
  sub->add_option("--dof", o->dofs,
                  "DOF to identify (repeatable; default: every DOF the truth has parameters "
                  "for)");
  AddJsonOption(sub, &o->json, "also write the result");
  sub->add_flag("--diagnose", o->diagnose,
                "after each identification, diagnose the DOF's trials and add the effects found "
                "to the model later trials are identified in");
  sub->add_option("--write-vehicle", o->write_vehicle,
                  "write the truth's vehicle with the model identified last (estimates, σ and "
                  "the effects added), for schedule, next and identify");
  sub->add_flag("--verbose", o->verbose, "print each iteration's design and identification notes");
  AddThreadsOption(sub, {&o->loop.step.schedule.planner.threads, &o->loop.step.identify.threads},
                   "planning the DOFs' candidate trials and each iteration's identification");
}

const CommandRegistration kLoopRegistration(MakeCommand<LoopFlags>(
    "loop", 46,
    "Design → run (virtual) → identify → re-plan until every parameter of interest's "
    "percentile error is below the target, or the trial budget is spent.",
    BindLoop, RunLoopCommand));

}  // namespace
}  // namespace uuvplan::cli
