// `uuvplan log CAMPAIGN TRIAL.csv --trial ID [--plan PLAN.json [--planned ID]] [--dof D] [--mapping
// M]
// [--ballast-steps N] [--use fit|validate] [--start S]`: appends a trial logged at the pool to
// its campaign (io/campaign_log.h: the CSV copied to trials/<ID>.csv, campaign.yaml rewritten,
// each atomically; the input CSV is never modified), so that `next` can run between trials.
// With --plan (a schedule or a `next` result) the log is checked against the planned trial ID
// (planner/pool/log_check.h), which also gives the DOF and mapping; --planned names the plan's
// trial when the log is a retry logged under a new id.
// Exit status (docs/cli.md): 0 logged; 2 bad input (nothing changed), including a log that is
// not the planned trial.
#include <algorithm>
#include <iostream>
#include <optional>
#include <string>

#include "uuvplan/cli/command.h"
#include "uuvplan/ident/prepare/outliers.h"
#include "uuvplan/io/campaign_log.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/pool/log_check.h"

namespace uuvplan::cli {
namespace {

struct LogFlags {
  std::string campaign;
  std::string csv;
  std::string id;
  std::string plan;
  std::string planned;  ///< --planned: the plan's trial this log is (default: --trial)
  std::string dof;
  std::string mapping;
  int ballast_steps = 0;
  std::string use = "fit";
  std::optional<double> start;
};

// The trial `id` of the plan at `path`; InputError naming the plan when it has none.
model::TrialDesign PlannedDesign(const std::string& path, const std::string& id) {
  const planner::Schedule plan = io::ReadScheduleJson(path);
  for (const planner::PlannedTrial& t : plan.trials) {
    if (t.design.id == id) return t.design;
  }
  throw model::InputError(path + ": trials", "no trial '" + id + "' (--trial)");
}

io::LoggedTrial TrialOf(const LogFlags& o, const model::TrialDesign* design) {
  io::LoggedTrial t;
  t.id = o.id;
  t.csv = o.csv;
  t.ballast_steps = design && o.ballast_steps == 0 ? design->ballast_steps : o.ballast_steps;
  t.start = o.start;
  if (o.use != "fit" && o.use != "validate") {
    throw model::InputError("--use " + o.use, "expected fit or validate");
  }
  t.use = o.use == "fit" ? model::TrialUse::kFit : model::TrialUse::kValidate;
  if (!o.dof.empty()) {
    t.dof = ParseDofFlags({o.dof}).front();
  } else if (design) {
    t.dof = design->dof;
  } else {
    throw model::InputError("--dof", "required without --plan (the trial's DOF)");
  }
  const bool planned_dof = design && design->dof == t.dof;  // else refused in RunLog
  t.mapping = !o.mapping.empty() ? o.mapping : planned_dof ? design->mapping : "";
  return t;
}

// Drop-outs said when the trial is logged, not first by identify (ref 000 Fig. 14: a step
// longer than 3× the median step is a gap; filters and integrals never cross one).
void PrintGaps(const model::TrialEntry& e) {
  const std::vector<ident::Gap> gaps = ident::FindGaps(e.log.t);
  if (gaps.empty()) return;
  const auto longest = std::max_element(gaps.begin(), gaps.end(), [](const auto& a, const auto& b) {
    return a.t1 - a.t0 < b.t1 - b.t0;
  });
  std::cout << "note: " << gaps.size() << " gap(s) in the log (steps over 3× the median), the "
            << "longest " << model::DurationText(longest->t1 - longest->t0)
            << " from t = " << model::Significant(longest->t0, 6)
            << " s: identification neither filters nor "
            << "integrates across a gap, so the trial counts as shorter pieces\n";
}

int RunLog(const LogFlags& o) {
  if (!o.planned.empty() && o.plan.empty()) {
    throw model::InputError("--planned " + o.planned, "needs --plan (the plan that holds it)");
  }
  const std::string planned_id = o.planned.empty() ? o.id : o.planned;
  std::optional<model::TrialDesign> design;
  if (!o.plan.empty()) design = PlannedDesign(o.plan, planned_id);
  const io::LoggedTrial trial = TrialOf(o, design ? &*design : nullptr);
  io::LogCheck planned;
  if (design) {
    planned = [&](const model::TrialLog& log) {
      const auto problems = planner::CompareLogWithDesign(*design, trial.dof, trial.mapping, log);
      if (problems.empty()) return;
      throw model::InputError(o.csv, "not the planned trial " + planned_id + " of " + o.plan +
                                         ": " + model::Join(problems, "; ") +
                                         " (log it without --plan if it is meant to differ)");
    };
    // Another DOF than the plan's is refused before the campaign is read (CompareLogWithDesign
    // names only the DOF then, whatever the log holds).
    if (design->dof != trial.dof) planned(model::TrialLog{});
  }
  const model::Campaign c = io::AppendLoggedTrial(o.campaign, trial, planned);
  const model::TrialEntry& e = c.trials.back();
  const double span = e.log.t.empty() ? 0.0 : e.log.t.back() - e.log.t.front();
  std::cout << "Logged " << o.id << " (" << model::DofName(e.dof) << ", mapping "
            << (e.mapping.empty() ? "-" : e.mapping) << ", " << e.log.size() << " rows, "
            << model::DurationText(span)
            << (!design              ? ""
                : planned_id == o.id ? ", as planned"
                                     : ", as planned trial " + planned_id)
            << ") as " << e.file << " of " << c.path << ": " << c.trials.size() << " trial(s)\n";
  PrintGaps(e);
  return kExitOk;
}

void BindLog(CLI::App* sub, LogFlags* o) {
  sub->add_option("CAMPAIGN", o->campaign, "campaign.yaml or the directory that holds it")
      ->required();
  sub->add_option("TRIAL", o->csv, "the trial's log (CSV, contract §Trial log); only read")
      ->required();
  sub->add_option("--trial", o->id, "the trial's id (its file becomes trials/<id>.csv)")
      ->required();
  sub->add_option("--plan", o->plan,
                  "a schedule or `next` result: check the log against its trial --trial");
  sub->add_option("--planned", o->planned,
                  "with --plan: the plan's trial this log runs (a retry logged under a new "
                  "--trial id; default: the --trial id)");
  sub->add_option("--dof", o->dof, "the trial's DOF (default: the planned trial's)");
  sub->add_option("--mapping", o->mapping,
                  "the trial's mapping (default: the planned trial's, else the vehicle's only "
                  "mapping on the DOF)");
  sub->add_option("--ballast-steps", o->ballast_steps, "known ballast steps added (heave)")
      ->check(CLI::NonNegativeNumber);
  sub->add_option("--use", o->use, "fit (default) or validate");
  sub->add_option("--start", o->start, "start time on the campaign clock (s)");
}

const CommandRegistration kLogRegistration(MakeCommand<LogFlags>(
    "log", 44,
    "Append a trial logged at the pool to its campaign (checked against the plan with "
    "--plan), so that `next` can run between trials.",
    BindLog, RunLog));

}  // namespace
}  // namespace uuvplan::cli
