// `uuvplan check-pool VEHICLE --pool POOL [--plan PLAN.json] [--json F]`: can this pool host the
// trials of a plan (or the planner's own schedule for this pool), which constraint fails and by
// how much, the smallest pool that hosts them, and the best schedule that fits the given pool
// with the information it loses (docs/planning.md). The answer and exit status are the pool
// verdict (planner/pool/pool_verdict.h), the same as `schedule`'s for the same vehicle, pool and
// DOFs: 1 when the pool cannot host the identification of every DOF asked for (a plan that
// leaves out a DOF the planner cannot plan here does not make it hostable), 2 bad input.
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "uuvplan/cli/command.h"
#include "uuvplan/cli/exit_status.h"
#include "uuvplan/cli/planning_progress.h"
#include "uuvplan/io/check_pool_json.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/pool/pool_check.h"
#include "uuvplan/planner/pool/pool_verdict.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/planner/schedule_planner.h"
#include "uuvplan/text/text_table.h"
#include "uuvplan/text/trial_text.h"
#include "uuvplan/text/verdict_text.h"

namespace uuvplan::cli {
namespace {

struct CheckPoolFlags {
  std::string vehicle;
  std::string pool;
  std::string plan;
  std::string json;
  std::vector<std::string> dofs;
  planner::PoolCheckOptions check;  ///< --max-duration bound here
};

// The trials to check: the plan file's, or the planner's own schedule for this pool; `own` is
// the planner's schedule of the DOFs asked for either way (the verdict judges it).
struct TrialsToCheck {
  planner::Schedule plan;
  planner::ScheduleResult own;
  bool plan_given = false;
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

TrialsToCheck ChooseTrials(const CheckPoolFlags& o, const model::Vehicle& vehicle,
                           const model::Pool& pool, const planner::ScheduleOptions& so,
                           const PlanningProgress& progress) {
  TrialsToCheck t;
  t.plan_given = !o.plan.empty();
  if (t.plan_given) {  // read and checked before planning: a bad file fails at once
    t.plan = io::ReadScheduleJson(o.plan);
    CheckPlanMappings(t.plan, vehicle, o.plan);
  }
  t.own = planner::PlanSchedule(vehicle, pool, so, progress.dof_planned);
  if (!t.plan_given) t.plan = t.own.schedule;
  return t;
}

void PrintTrialChecks(const planner::PoolCheckResult& r, std::ostream& out) {
  text::TextTable table({"DOF", "trial", "fits", "travel", "|τ|min (N)"});
  for (const auto& t : r.trials) {
    table.AddRow({std::string(model::DofName(t.dof)), t.id, t.check.feasible ? "yes" : "NO",
                  text::TravelText(t.dof, t.check.travel[0], t.check.travel[1]),
                  model::Significant(t.check.thrust_min, 3)});
  }
  table.Print(out);
  for (const auto& t : r.trials) {
    for (const auto& reason : t.check.reasons) out << "    - " << t.id << ": " << reason << "\n";
  }
}

void PrintAlternative(const planner::PoolCheckResult& r, std::ostream& out) {
  out << "\nBest schedule that fits this pool: " << planner::PlanStatusName(r.alternative.status)
      << ", " << r.alternative.schedule.trials.size() << " trials, pool time "
      << model::DurationText(r.alternative.schedule.pool_time) << "\n";
  text::TextTable table({"DOF", "trial", "kind", "mapping", "duration"});
  for (const auto& t : r.alternative.schedule.trials) {
    table.AddRow({std::string(model::DofName(t.design.dof)), t.design.id,
                  std::string(model::TrialKindName(t.design.kind)), t.design.mapping,
                  model::DurationText(t.design.duration)});
  }
  table.Print(out);
  for (const auto& d : r.alternative.dofs) {
    if (!d.complete && !d.message.empty()) out << "  " << d.message << "\n";
  }
  for (const auto& [dof, loss] : r.information_loss) {
    out << "  information lost on " << model::DofName(dof) << ": "
        << model::Significant(100.0 * loss, 3) << "% (1 - D-efficiency against the plan)\n";
  }
}

int RunCheckPool(const CheckPoolFlags& o) {
  const model::Vehicle vehicle = io::ReadVehicle(o.vehicle);
  const model::Pool pool = io::ReadPool(o.pool);
  planner::PoolCheckOptions check = o.check;
  check.schedule.dofs = ParseDofFlags(o.dofs);
  CheckDofsPlannable(check.schedule.dofs, vehicle, o.vehicle);
  const PlanningProgress progress = ShowPlanningProgress("check-pool");
  const TrialsToCheck checked = ChooseTrials(o, vehicle, pool, check.schedule, progress);
  progress.line("checking the trials over the box; judging the pool, searching for the smallest");
  const planner::PoolCheckResult r = planner::CheckPool(vehicle, pool, checked.plan, check);
  // The plan's trials are checked once (CheckPool, same options) and judged on those checks.
  // The command that answers "and if not, what would": it searches for the smallest pool.
  planner::VerdictOptions search;
  search.need_bisections = planner::kSmallestPoolBisections;
  const planner::PoolVerdict verdict = planner::JudgePoolOnChecks(
      vehicle, pool, check.schedule, checked.own, checked.plan_given ? &r.trials : nullptr, search);
  std::ostream& out = ReportStream(o.json);
  out << "Pool " << pool.name << " for " << vehicle.name << ", "
      << (o.plan.empty() ? "the planner's own schedule" : "plan " + o.plan) << ": "
      << text::VerdictAnswer(verdict.hostability, verdict.identified_box, verdict.derived_box)
      << "\n\n";
  PrintTrialChecks(r, out);
  text::PrintVerdict(verdict, pool, out);
  if (r.has_alternative) PrintAlternative(r, out);
  if (!o.json.empty()) WriteJson(o.json, io::CheckPoolJson(r, verdict, pool));
  return VerdictExit(verdict);
}

void BindCheckPool(CLI::App* sub, CheckPoolFlags* o) {
  sub->add_option("VEHICLE", o->vehicle, "vehicle file (YAML)")->required();
  sub->add_option("--pool", o->pool, "pool file (YAML)")->required();
  sub->add_option("--plan", o->plan, "schedule JSON (`uuvplan schedule --json`)");
  sub->add_option("--dof", o->dofs,
                  "DOF whose identification the pool must host (repeatable; default every DOF "
                  "with a mapping and a sensor, as `schedule`)");
  AddJsonOption(sub, &o->json, "write the result");
  AddTargetOption(sub, &o->check.schedule.precision.target_percent);
  sub->add_option("--max-duration", o->check.schedule.planner.max_trial_duration_s,
                  "longest trial (s)")
      ->capture_default_str()
      ->check(TrialDuration());
}

const CommandRegistration kCheckPoolRegistration(MakeCommand<CheckPoolFlags>(
    "check-pool", 20,
    "Can this pool host the trials (a plan, or the planner's own schedule), and if not "
    "what would: the smallest pool and the best schedule that fits (exit 1 if not).",
    BindCheckPool, RunCheckPool));

}  // namespace
}  // namespace uuvplan::cli
