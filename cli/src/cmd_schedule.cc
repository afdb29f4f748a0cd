// `uuvplan schedule VEHICLE --pool POOL [--dof D]... [--json F]`: the test schedule of a vehicle
// (a new payload) in a pool — steady runs and legs for drag and installation coefficients, a
// sine trial for the inertia, per DOF, robust over the a priori box (docs/planning.md).
// Exit status (the pool verdict, planner/pool/pool_verdict.h): 0 the pool hosts the identification
// of every requested DOF; 1 it does not (the partial schedule is still printed and written, with
// the verdict: per DOF the limit and its need, and the smallest pool); 2 bad input.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "uuvplan/cli/command.h"
#include "uuvplan/cli/coupled_schedule.h"
#include "uuvplan/cli/exit_status.h"
#include "uuvplan/cli/planning_progress.h"
#include "uuvplan/io/command_files.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/pool_verdict_json.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design/coupled_design.h"
#include "uuvplan/planner/design/information_table.h"
#include "uuvplan/planner/pool/pool_verdict.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/planner/schedule_planner.h"
#include "uuvplan/text/quantity_text.h"
#include "uuvplan/text/text_table.h"
#include "uuvplan/text/trial_text.h"
#include "uuvplan/text/verdict_text.h"

namespace uuvplan::cli {
namespace {

struct ScheduleFlags {
  std::string vehicle;
  std::string pool;
  std::vector<std::string> dofs;
  std::string json;
  std::string commands;  ///< --commands DIR: per-thruster command files and the run sheet
  std::string robust{planner::RobustnessName(planner::ScheduleOptions{}.planner.robustness)};
  planner::ScheduleOptions schedule;  ///< --max-duration, --no-steady, --no-sine bound here
  std::string model_kind = "dof";     ///< --model: dof (per DOF) or coupled (ref 003)
  std::string mode;                   ///< --mode: a combined mode (coupled only)
  bool duration_given = false;        ///< --max-duration on the command line
};

planner::Robustness ParseRobustness(const std::string& s) {
  for (const auto r : {planner::Robustness::kMaximin, planner::Robustness::kAverage,
                       planner::Robustness::kNominal}) {
    if (planner::RobustnessName(r) == s) return r;
  }
  throw model::InputError("--robust", "expected maximin, average or nominal, got '" + s + "'");
}

// `--model coupled` plans one combined trial of ref 003's model (coupled_design.h): the
// per-DOF planner's options do not apply, and one given would be ignored.
void RefusePerDofOptionsWithCoupled(const ScheduleFlags& o) {
  const planner::ScheduleOptions per_dof;
  std::vector<std::string> given;
  if (!o.dofs.empty()) given.push_back("--dof");
  if (!o.commands.empty()) given.push_back("--commands");
  if (o.schedule.precision.target_percent != per_dof.precision.target_percent)
    given.push_back("--target");
  if (o.schedule.steady_runs != per_dof.steady_runs) given.push_back("--no-steady");
  if (o.schedule.sine_trial != per_dof.sine_trial) given.push_back("--no-sine");
  if (!given.empty()) {
    throw model::InputError("--model coupled",
                            "no " + model::Join(given) +
                                ": the coupled model gets one combined-mode trial (--mode); "
                                "drop them, or use --model dof");
  }
}

int RunCoupled(const ScheduleFlags& o, const model::Vehicle& vehicle, const model::Pool& pool) {
  planner::CombinedDesignOptions co =
      o.mode.empty()
          ? planner::CoupledDesignOptions()
          : planner::CoupledDesignOptions(*model::ParseDofList(o.mode));  // checked by CLI11
  co.solver.robustness = ParseRobustness(o.robust);
  if (o.duration_given) co.duration_s = o.schedule.planner.max_trial_duration_s;
  return RunCoupledSchedule(vehicle, pool, co, o.json);
}

void PrintSchedule(const planner::ScheduleResult& r, const model::Vehicle& v,
                   const model::Pool& pool, std::ostream& out) {
  out << "Schedule for " << v.name << " in pool " << pool.name << " (free, walls less 2·"
      << model::Significant(pool.margin, 4)
      << " m margin: " << model::Significant(pool.FreeTravel(model::Dof::kSurge), 4)
      << " m length, " << model::Significant(pool.FreeTravel(model::Dof::kSway), 4) << " m width, "
      << model::Significant(pool.FreeTravel(model::Dof::kHeave), 4) << " m depth; tether "
      << model::Significant(pool.max_turns, 4) << " turns): " << planner::PlanStatusName(r.status)
      << "\n\n";
  text::TextTable trials(
      {"DOF", "trial", "kind", "mapping", "duration", "travel", "|τ|min (N)", "force"});
  for (const auto& t : r.schedule.trials) {
    const auto& d = t.design;
    trials.AddRow(
        {std::string(model::DofName(d.dof)), d.id, std::string(model::TrialKindName(d.kind)),
         d.mapping, model::DurationText(d.duration),
         text::TravelText(d.dof, t.travel[0], t.travel[1]), model::Significant(t.thrust_min, 3),
         text::ForceText(d, text::kScheduleForceStyle)});
  }
  trials.Print(out);
  out << "\nPredicted 1σ (worst over the a priori box) and robust D criterion (log det of the "
         "relative information):\n";
  text::TextTable predicted({"DOF", "D (no unit)", "parameter", "σ"});
  for (const auto& [dof, p] : r.schedule.predicted) {
    std::string criterion = model::Significant(p.criterion_value, 4);
    for (const auto& [name, s] : p.sigma) {
      predicted.AddRow({std::string(model::DofName(dof)), criterion, name,
                        text::Quantity(s, model::Unit(name, dof))});
      criterion = "";
    }
  }
  predicted.Print(out);
  out << "assumption: " << planner::kPredictedSigmaAssumption << "\n";
  out << "\nPool time: " << model::DurationText(r.schedule.pool_time) << " (pauses included), "
      << r.schedule.trials.size() << " trials\n";
  for (const auto& d : r.dofs) {
    if (!d.complete && !d.message.empty()) out << "\n" << d.message << "\n";
  }
  bool header = false;
  for (const auto& d : r.dofs) {
    for (const auto& n : d.notes) {
      if (!header) out << "\nNotes:\n";
      header = true;
      out << "  - " << n << "\n";
    }
  }
}

int RunSchedule(const ScheduleFlags& o) {
  if (o.model_kind == "coupled") RefusePerDofOptionsWithCoupled(o);
  if (o.model_kind != "coupled" && !o.mode.empty()) {
    throw model::InputError("--mode " + o.mode, "a combined mode is planned with --model coupled");
  }
  const model::Vehicle vehicle = io::ReadVehicle(o.vehicle);
  const model::Pool pool = io::ReadPool(o.pool);
  if (o.model_kind == "coupled") return RunCoupled(o, vehicle, pool);
  planner::ScheduleOptions so = o.schedule;
  so.planner.robustness = ParseRobustness(o.robust);
  so.dofs = ParseDofFlags(o.dofs);
  CheckDofsPlannable(so.dofs, vehicle, o.vehicle);
  std::string error;
  if (!so.IsValid(&error)) throw model::InputError("options", error);
  const PlanningProgress progress = ShowPlanningProgress("schedule");
  const planner::ScheduleResult r = planner::PlanSchedule(vehicle, pool, so, progress.dof_planned);
  progress.line("judging the pool verdict at the box's centre and corners");
  const planner::PoolVerdict verdict = planner::JudgePool(vehicle, pool, so, r, nullptr);
  std::ostream& out = ReportStream(o.json);
  PrintSchedule(r, vehicle, pool, out);
  text::PrintVerdict(verdict, pool, out);
  if (!o.json.empty()) {
    WriteJson(o.json, io::ScheduleResultJson(
                          r, planner::InformationOf(vehicle, pool, r.schedule, so), verdict, pool));
  }
  if (!o.commands.empty()) io::WriteScheduleCommands(o.commands, vehicle, pool, r.schedule, so);
  return VerdictExit(verdict);
}

void BindSchedule(CLI::App* sub, ScheduleFlags* o) {
  sub->add_option("VEHICLE", o->vehicle, "vehicle file (YAML)")->required();
  sub->add_option("--pool", o->pool, "pool file (YAML)")->required();
  sub->add_option("--dof", o->dofs,
                  "DOF to plan (repeatable; default every DOF with a mapping and a sensor)");
  AddJsonOption(sub, &o->json, "write the schedule");
  sub->add_option("--commands", o->commands,
                  "write each trial's thruster commands (CSV) and the run sheet (Markdown) into "
                  "this new directory");
  sub->add_option("--robust", o->robust, "maximin (default), average or nominal")
      ->capture_default_str();
  AddTargetOption(sub, &o->schedule.precision.target_percent);
  sub->add_option("--max-duration", o->schedule.planner.max_trial_duration_s,
                  "longest trial (s); with --model coupled the combined trial's duration "
                  "(then 120 s when not given)")
      ->capture_default_str()
      ->check(TrialDuration())
      ->each([o](const std::string&) { o->duration_given = true; });
  sub->add_option("--model", o->model_kind,
                  "dof (a schedule per DOF) or coupled (one combined surge+sway+yaw sine trial "
                  "for seed 003's coupled model)")
      ->capture_default_str()
      ->check(CLI::IsMember({"dof", "coupled"}));
  sub->add_option("--mode", o->mode,
                  "with --model coupled: the combined mode, surge+yaw, sway+yaw or "
                  "surge+sway+yaw (default)")
      ->check(CLI::IsMember({"surge+yaw", "sway+yaw", "surge+sway+yaw"}));
  sub->add_flag_callback(
      "--no-steady", [o] { o->schedule.steady_runs = false; }, "plan no steady runs");
  sub->add_flag_callback(
      "--no-sine", [o] { o->schedule.sine_trial = false; }, "plan no sine trial");
}

const CommandRegistration kScheduleRegistration(MakeCommand<ScheduleFlags>(
    "schedule", 10,
    "The test schedule of a vehicle in a pool: steady runs and legs for drag and "
    "installation coefficients, a sine trial for the inertia, robust over the a priori "
    "box (exit 1 if the pool cannot host every trial).",
    BindSchedule, RunSchedule));

}  // namespace
}  // namespace uuvplan::cli
