// `uuvplan check-pool VEHICLE --pool POOL [--plan PLAN.json] [--json F]`: can this pool host the
// trials of a plan (or the planner's own schedule for this pool), which constraint fails and by
// how much, the smallest pool that hosts them, and the best schedule that fits the given pool
// with the information it loses (docs/planning.md). Exit status 1 when the pool cannot host it.
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "command.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/planner/pool_check.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::tool {
namespace {

struct CheckPoolCliOptions {
  std::string vehicle;
  std::string pool;
  std::string plan;
  std::string json;
  planner::PoolCheckOptions check;  ///< --max-duration bound here
};

// The trials to check: the plan file's, or the planner's own schedule for this pool (then
// `own` holds it and `own_partial` says whether some DOF could not be planned).
struct TrialsToCheck {
  planner::Schedule plan;
  planner::ScheduleResult own;
  bool own_partial = false;
};

// Every trial of a plan file must use a mapping of the vehicle that acts on the trial's DOF.
void CheckPlanMappings(const planner::Schedule& plan, const model::Vehicle& vehicle,
                       const std::string& plan_path) {
  for (std::size_t i = 0; i < plan.trials.size(); ++i) {
    const auto& d = plan.trials[i].design;
    const std::string where = plan_path + ": trials[" + std::to_string(i) + "]";
    const int mi = vehicle.MappingIndex(d.mapping);
    if (mi < 0 || vehicle.mappings[mi].dof != d.dof) {
      throw model::InputError(where + ".mapping", "expected a " +
                                                      std::string(model::DofName(d.dof)) +
                                                      " mapping of vehicle '" + vehicle.name +
                                                      "', got '" + d.mapping + "'");
    }
  }
}

TrialsToCheck ChooseTrials(const CheckPoolCliOptions& o, const model::Vehicle& vehicle,
                           const model::Pool& pool) {
  TrialsToCheck t;
  if (!o.plan.empty()) {
    t.plan = io::ReadScheduleJson(o.plan);
    CheckPlanMappings(t.plan, vehicle, o.plan);
  } else {
    t.own = planner::PlanSchedule(vehicle, pool, o.check.schedule);
    t.plan = t.own.schedule;
    t.own_partial = t.own.status != planner::PlanStatus::kOk;
  }
  return t;
}

void PrintTrialChecks(const planner::PoolCheckResult& r, std::ostream& out) {
  for (const auto& t : r.trials) {
    out << "  " << std::left << std::setw(18) << t.id
        << (t.check.feasible ? "fits" : "DOES NOT FIT") << std::right << std::fixed
        << std::setprecision(2) << "   travel [" << t.check.travel[0] << ", " << t.check.travel[1]
        << "], |tau|min " << t.check.thrust_min << " N\n";
    for (const auto& reason : t.check.reasons) out << "      - " << reason << "\n";
  }
}

// The extent asked of the pool along each axis that some trial moves on.
void PrintRequiredPool(const planner::PoolCheckResult& r, std::ostream& out) {
  bool axis[3] = {false, false, false};
  for (const auto& t : r.trials) {
    if (t.dof == model::Dof::kSurge) axis[0] = true;
    if (t.dof == model::Dof::kSway) axis[1] = true;
    if (t.dof == model::Dof::kHeave) axis[2] = true;
  }
  out << std::defaultfloat << "\nSmallest pool that hosts these trials (margins included):";
  if (axis[0]) out << " length " << r.required_length << " m";
  if (axis[1]) out << " width " << r.required_width << " m";
  if (axis[2]) out << " depth " << r.required_depth << " m";
  if (!axis[0] && !axis[1] && !axis[2]) out << " any (rotations only)";
  out << "\n";
}

// Why the planner's own schedule leaves some DOF out, and the travel it would need.
void PrintNotPlanned(const planner::ScheduleResult& own, const model::Pool& pool,
                     std::ostream& out) {
  for (const auto& d : own.dofs) {
    if (d.complete) continue;
    out << "\n" << d.message << "\n";
    if (d.required_travel > 0) {
      out << "  (the smallest useful " << model::DofName(d.dof) << " trial needs "
          << d.required_travel << " of free travel, i.e. "
          << pool.WallToWallFor(d.required_travel) << " with the margins)\n";
    }
  }
}

void PrintAlternative(const planner::PoolCheckResult& r, std::ostream& out) {
  out << "\nBest schedule that fits this pool: " << planner::PlanStatusName(r.alternative.status)
      << ", " << r.alternative.schedule.trials.size() << " trials, pool time "
      << r.alternative.schedule.pool_time << " s\n";
  for (const auto& t : r.alternative.schedule.trials) {
    out << "  " << std::left << std::setw(18) << t.design.id << std::right
        << model::TrialKindName(t.design.kind) << " " << t.design.mapping << ", "
        << t.design.duration << " s\n";
  }
  for (const auto& d : r.alternative.dofs) {
    if (!d.complete && !d.message.empty()) out << "  " << d.message << "\n";
  }
  for (const auto& [dof, loss] : r.information_loss) {
    out << "  information lost on " << model::DofName(dof) << ": " << std::setprecision(3)
        << 100.0 * loss << "% (1 - D-efficiency against the plan)\n";
  }
}

// {"feasible", "trials": [...], "required": {...}, "not_planned"?: {...}, "fits"?: {...}}.
nlohmann::json CheckPoolJson(const planner::PoolCheckResult& r, const TrialsToCheck& checked,
                             bool feasible, const model::Pool& pool) {
  nlohmann::json trials = nlohmann::json::array();
  for (const auto& t : r.trials) {
    trials.push_back({{"id", t.id},
                      {"dof", std::string(model::DofName(t.dof))},
                      {"feasible", t.check.feasible},
                      {"reasons", t.check.reasons},
                      {"travel", {t.check.travel[0], t.check.travel[1]}},
                      {"thrust_min", t.check.thrust_min}});
  }
  nlohmann::json j = {
      {"feasible", feasible},
      {"trials", trials},
      {"required",
       {{"length", r.required_length}, {"width", r.required_width}, {"depth", r.required_depth}}}};
  if (checked.own_partial) {
    nlohmann::json missing = nlohmann::json::object();
    for (const auto& d : checked.own.dofs) {
      if (d.complete) continue;
      nlohmann::json m = {{"message", d.message}};
      if (d.required_travel > 0) m["required_pool"] = pool.WallToWallFor(d.required_travel);
      missing[std::string(model::DofName(d.dof))] = m;
    }
    j["not_planned"] = missing;
  }
  if (r.has_alternative) {
    nlohmann::json alt = io::ScheduleToJson(r.alternative.schedule);
    alt["status"] = std::string(planner::PlanStatusName(r.alternative.status));
    nlohmann::json loss = nlohmann::json::object();
    for (const auto& [dof, l] : r.information_loss) loss[std::string(model::DofName(dof))] = l;
    j["fits"] = {{"schedule", alt}, {"information_loss", loss}};
  }
  return j;
}

int RunCheckPool(const CheckPoolCliOptions& o) {
  const model::Vehicle vehicle = io::ReadVehicle(o.vehicle);
  const model::Pool pool = io::ReadPool(o.pool);
  const TrialsToCheck checked = ChooseTrials(o, vehicle, pool);
  const planner::PoolCheckResult r = planner::CheckPool(vehicle, pool, checked.plan, o.check);
  const bool feasible = r.feasible && !checked.own_partial;
  std::ostream& out = ReportStream(o.json);
  out << "Pool " << pool.name << " (" << pool.length << " x " << pool.width << " x " << pool.depth
      << " m, margin " << pool.margin << " m) for " << vehicle.name << ", "
      << (o.plan.empty() ? "the planner's own schedule" : "plan " + o.plan) << ": "
      << (feasible ? "CAN host it" : "CANNOT host it") << "\n\n";
  PrintTrialChecks(r, out);
  PrintRequiredPool(r, out);
  if (checked.own_partial) PrintNotPlanned(checked.own, pool, out);
  if (r.has_alternative) PrintAlternative(r, out);
  if (!o.json.empty()) WriteJson(o.json, CheckPoolJson(r, checked, feasible, pool));
  return feasible ? kExitOk : kExitActionNeeded;
}

void BindCheckPool(CLI::App* sub, CheckPoolCliOptions* o) {
  sub->add_option("VEHICLE", o->vehicle, "vehicle file (YAML)")->required();
  sub->add_option("--pool", o->pool, "pool file (YAML)")->required();
  sub->add_option("--plan", o->plan, "schedule JSON (`uuvplan schedule --json`)");
  AddJsonOption(sub, &o->json, "write the result");
  sub->add_option("--max-duration", o->check.schedule.planner.max_trial_duration_s,
                  "longest trial (s)")
      ->capture_default_str()
      ->check(CLI::PositiveNumber);
}

const CommandRegistration kRegistration(MakeCommand<CheckPoolCliOptions>(
    "check-pool", 20,
    "Can this pool host the trials (a plan, or the planner's own schedule), and if not "
    "what would: the smallest pool and the best schedule that fits (exit 1 if not).",
    BindCheckPool, RunCheckPool));

}  // namespace
}  // namespace uuvplan::tool
