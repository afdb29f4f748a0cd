// `uuvplan schedule VEHICLE --pool POOL [--dof D]... [--json F]`: the test schedule of a vehicle
// (a new payload) in a pool — steady runs and legs for drag and installation coefficients, a
// sine trial for the inertia, per DOF, robust over the a priori box (docs/planning.md).
// Exit status: 0 every requested DOF fully planned; 1 some trials cannot be hosted by the pool
// (the partial schedule is still printed and written, with what is missing and why);
// 2 bad input.
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
#include "uuvplan/planner/schedule_planner.h"

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

// Every DOF asked for must have a thrust mapping to drive it and a sensor to observe it.
void CheckDofsPlannable(const std::vector<model::Dof>& dofs, const model::Vehicle& vehicle,
                        const std::string& vehicle_path) {
  for (const model::Dof dof : dofs) {
    const std::string name(model::DofName(dof));
    if (vehicle.MappingsOf(dof).empty()) {
      throw model::InputError(vehicle_path + ": mappings",
                              "--dof " + name + ": no thrust mapping acts on " + name);
    }
    auto s = vehicle.sensors.find(dof);
    if (s == vehicle.sensors.end() || (!s->second.position && !s->second.velocity)) {
      throw model::InputError(vehicle_path + ": sensors." + name,
                              "--dof " + name + ": no position or velocity sensor on " + name);
    }
  }
}

void PrintSchedule(const planner::ScheduleResult& r, const model::Vehicle& v,
                   const model::Pool& pool, std::ostream& out) {
  out << "Schedule for " << v.name << " in pool " << pool.name
      << " (free: " << pool.FreeTravel(model::Dof::kSurge) << " m length, "
      << pool.FreeTravel(model::Dof::kSway) << " m width, " << pool.FreeTravel(model::Dof::kHeave)
      << " m depth): " << planner::PlanStatusName(r.status) << "\n\n";
  out << std::left << std::setw(17) << "id" << std::setw(9) << "kind" << std::setw(22) << "mapping"
      << std::right << std::setw(8) << "T (s)"
      << "  " << std::left << std::setw(17) << "travel" << std::right << std::setw(9) << "|tau|min"
      << "  force\n";
  for (const auto& t : r.schedule.trials) {
    const auto& d = t.design;
    std::ostringstream travel;
    travel << std::fixed << std::setprecision(2) << "[" << t.travel[0] << ", " << t.travel[1]
           << "]";
    out << std::left << std::setw(17) << d.id << std::setw(9) << model::TrialKindName(d.kind)
        << std::setw(22) << d.mapping << std::right << std::fixed << std::setprecision(1)
        << std::setw(8) << d.duration << "  " << std::left << std::setw(17) << travel.str()
        << std::right << std::setw(9) << std::setprecision(2) << t.thrust_min << "  "
        << ForceText(d, kScheduleForceStyle)
        << "\n";
  }
  out << "\nPredicted 1σ (worst over the a priori box) and robust D criterion:\n";
  for (const auto& [dof, p] : r.schedule.predicted) {
    out << "  " << std::left << std::setw(6) << model::DofName(dof) << std::right << " D "
        << std::setprecision(2) << p.criterion_value << ":";
    for (const auto& [name, s] : p.sigma)
      out << "  " << name << " " << std::setprecision(3) << std::defaultfloat << s;
    out << std::fixed << "\n";
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

// {schedule..., "status", "notes": [...], "not_planned": {<dof>: {"message", "required_travel",
// "required_pool"}}} (docs/cli.md, the schedule JSON).
nlohmann::json ScheduleResultJson(const planner::ScheduleResult& r, const model::Pool& pool) {
  nlohmann::json j = io::ScheduleToJson(r.schedule);
  j["status"] = std::string(planner::PlanStatusName(r.status));
  nlohmann::json notes = nlohmann::json::array();
  nlohmann::json missing = nlohmann::json::object();
  for (const auto& d : r.dofs) {
    for (const auto& n : d.notes) notes.push_back(n);
    if (!d.complete) {
      nlohmann::json m = {{"message", d.message}};
      if (d.required_travel > 0) {
        m["required_travel"] = d.required_travel;
        m["required_pool"] = pool.WallToWallFor(d.required_travel);
      }
      missing[std::string(model::DofName(d.dof))] = m;
    }
  }
  j["notes"] = notes;
  if (!missing.empty()) j["not_planned"] = missing;
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
  PrintSchedule(r, vehicle, pool, ReportStream(o.json));
  if (!o.json.empty()) WriteJson(o.json, ScheduleResultJson(r, pool));
  return r.status == planner::PlanStatus::kOk ? kExitOk : kExitActionNeeded;
}

void BindSchedule(CLI::App* sub, ScheduleCliOptions* o) {
  sub->add_option("VEHICLE", o->vehicle, "vehicle file (YAML)")->required();
  sub->add_option("--pool", o->pool, "pool file (YAML)")->required();
  sub->add_option("--dof", o->dofs,
                  "DOF to plan (repeatable; default every DOF with a mapping and a sensor)");
  AddJsonOption(sub, &o->json, "write the schedule");
  sub->add_option("--robust", o->robust, "maximin (default), average or nominal")
      ->capture_default_str();
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
