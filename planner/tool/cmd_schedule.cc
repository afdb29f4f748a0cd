// `uuvplan schedule VEHICLE --pool POOL [--dof D]... [--json F]`: the test schedule of a vehicle
// (a new payload) in a pool — steady runs and legs for drag and installation coefficients, a
// sine trial for the inertia, per DOF, robust over the a priori box (docs/planning.md).
// Exit status (the pool verdict, planner/pool_verdict.h): 0 the pool hosts the identification
// of every requested DOF; 1 it does not (the partial schedule is still printed and written, with
// the verdict: per DOF the limit and its need, and the smallest pool); 2 bad input.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <sstream>
#include <string>
#include <vector>

#include "command.h"
#include "trial_text.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/planner/pool_verdict.h"
#include "uuvplan/planner/schedule_planner.h"
#include "uuvplan/io/pool_verdict_json.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"
#include "verdict_text.h"

namespace uuvplan::tool {
namespace {

struct ScheduleCliOptions {
  std::string vehicle;
  std::string pool;
  std::vector<std::string> dofs;
  std::string json;
  std::string robust{planner::RobustnessName(planner::ScheduleOptions{}.planner.robustness)};
  planner::ScheduleOptions schedule;  ///< --max-duration, --no-steady, --no-sine bound here
};

planner::Robustness ParseRobustness(const std::string& s) {
  for (const auto r : {planner::Robustness::kMaximin, planner::Robustness::kAverage,
                       planner::Robustness::kNominal}) {
    if (planner::RobustnessName(r) == s) return r;
  }
  throw model::InputError("--robust", "expected maximin, average or nominal, got '" + s + "'");
}

std::string TravelText(const planner::PlannedTrial& t) {
  std::ostringstream travel;
  travel << std::fixed << std::setprecision(2) << "[" << t.travel[0] << ", " << t.travel[1]
         << "] " << model::PositionUnit(t.design.dof);
  return travel.str();
}

void PrintSchedule(const planner::ScheduleResult& r, const model::Vehicle& v,
                   const model::Pool& pool, std::ostream& out) {
  out << "Schedule for " << v.name << " in pool " << pool.name
      << " (free, walls less 2·" << model::Significant(pool.margin, 4) << " m margin: "
      << model::Significant(pool.FreeTravel(model::Dof::kSurge), 4) << " m length, "
      << model::Significant(pool.FreeTravel(model::Dof::kSway), 4) << " m width, "
      << model::Significant(pool.FreeTravel(model::Dof::kHeave), 4) << " m depth; tether "
      << model::Significant(pool.max_turns, 4) << " turns): " << planner::PlanStatusName(r.status)
      << "\n\n";
  out << std::left << std::setw(17) << "id" << std::setw(9) << "kind" << std::setw(22) << "mapping"
      << std::right << std::setw(8) << "T (s)"
      << "  " << std::left << std::setw(21) << "travel (m or rad)" << std::right << std::setw(11)
      << "|tau|min N"
      << "  force (N or N·m)\n";
  for (const auto& t : r.schedule.trials) {
    const auto& d = t.design;
    out << std::left << std::setw(17) << d.id << std::setw(9) << model::TrialKindName(d.kind)
        << std::setw(22) << d.mapping << std::right << std::fixed << std::setprecision(1)
        << std::setw(8) << d.duration << "  " << std::left << std::setw(21) << TravelText(t)
        << std::right << std::setw(11) << std::setprecision(2) << t.thrust_min << "  "
        << ForceText(d, kScheduleForceStyle) << "\n";
  }
  out << "\nPredicted 1σ (worst over the a priori box) and robust D criterion (log det of the "
         "relative information):\n";
  for (const auto& [dof, p] : r.schedule.predicted) {
    out << "  " << std::left << std::setw(6) << model::DofName(dof) << std::right << " D "
        << model::Significant(p.criterion_value, 4) << ":";
    for (const auto& [name, s] : p.sigma) {
      out << "  " << name << " " << model::Significant(s, 3) << " " << model::Unit(name, dof);
    }
    out << "\n";
  }
  out << std::fixed << std::setprecision(0) << "\nPool time: " << r.schedule.pool_time << " s ("
      << std::setprecision(1) << r.schedule.pool_time / 60.0 << " min, pauses included), "
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

// {schedule..., "status", "notes": [...], "not_planned": {<dof>: {"message"}}, "verdict": {...}}
// (docs/cli.md; the needs and the required pool, with units, are the verdict's).
nlohmann::json ScheduleResultJson(const planner::ScheduleResult& r,
                                  const planner::PoolVerdict& verdict, const model::Pool& pool) {
  nlohmann::json j = io::ScheduleToJson(r.schedule);
  j["status"] = std::string(planner::PlanStatusName(r.status));
  nlohmann::json notes = nlohmann::json::array();
  nlohmann::json missing = nlohmann::json::object();
  for (const auto& d : r.dofs) {
    for (const auto& n : d.notes) notes.push_back(n);
    if (!d.complete) missing[std::string(model::DofName(d.dof))] = {{"message", d.message}};
  }
  j["notes"] = notes;
  if (!missing.empty()) j["not_planned"] = missing;
  j["verdict"] = io::PoolVerdictJson(verdict, pool);
  return j;
}

int RunSchedule(const ScheduleCliOptions& o) {
  const model::Vehicle vehicle = io::ReadVehicle(o.vehicle);
  const model::Pool pool = io::ReadPool(o.pool);
  planner::ScheduleOptions so = o.schedule;
  so.planner.robustness = ParseRobustness(o.robust);
  so.dofs = ParseDofFlags(o.dofs);
  CheckDofsPlannable(so.dofs, vehicle, o.vehicle);
  std::string error;
  if (!so.IsValid(&error)) throw model::InputError("options", error);
  const planner::ScheduleResult r = planner::PlanSchedule(vehicle, pool, so);
  const planner::PoolVerdict verdict = planner::JudgePool(vehicle, pool, so, r, nullptr);
  std::ostream& out = ReportStream(o.json);
  PrintSchedule(r, vehicle, pool, out);
  PrintVerdict(verdict, pool, out);
  if (!o.json.empty()) WriteJson(o.json, ScheduleResultJson(r, verdict, pool));
  return VerdictExit(verdict);
}

void BindSchedule(CLI::App* sub, ScheduleCliOptions* o) {
  sub->add_option("VEHICLE", o->vehicle, "vehicle file (YAML)")->required();
  sub->add_option("--pool", o->pool, "pool file (YAML)")->required();
  sub->add_option("--dof", o->dofs,
                  "DOF to plan (repeatable; default every DOF with a mapping and a sensor)");
  AddJsonOption(sub, &o->json, "write the schedule");
  sub->add_option("--robust", o->robust, "maximin (default), average or nominal")
      ->capture_default_str();
  AddTargetOption(sub, &o->schedule.precision.target_percent);
  sub->add_option("--max-duration", o->schedule.planner.max_trial_duration_s, "longest trial (s)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
  sub->add_flag_callback(
      "--no-steady", [o] { o->schedule.steady_runs = false; }, "plan no steady runs");
  sub->add_flag_callback(
      "--no-sine", [o] { o->schedule.sine_trial = false; }, "plan no sine trial");
}

const CommandRegistration kRegistration(MakeCommand<ScheduleCliOptions>(
    "schedule", 10,
    "The test schedule of a vehicle in a pool: steady runs and legs for drag and "
    "installation coefficients, a sine trial for the inertia, robust over the a priori "
    "box (exit 1 if the pool cannot host every trial).",
    BindSchedule, RunSchedule));

}  // namespace
}  // namespace uuvplan::tool
