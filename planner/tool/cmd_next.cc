// `uuvplan next CAMPAIGN --pool POOL [--dof D]... [--target PCT] [--json F]`: identify from
// every trial logged so far, turn the estimates and their covariance into the a priori
// knowledge of the design (box = estimates ± 2σ, prior information = covariance⁻¹) and plan the
// single most informative next trial (planner/design_loop.h, docs/loop.md) — what a pool team
// runs between two trials. The result can be run with `simulate --plan` (its "trial").
// Exit status: 0 a trial is planned, or every parameter of interest is already below the
// target (then "trial" is null); 1 no trial that is still needed fits the pool; 2 bad input.
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

#include "command.h"
#include "identify_table.h"
#include "uuvplan/io/identify_json.h"
#include "loop_report.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/planner/design_loop.h"

namespace uuvplan::tool {
namespace {

struct NextCliOptions {
  std::string campaign;
  std::string pool;
  std::vector<std::string> dofs;
  std::string json;
  bool accept_units = false;
  planner::DesignLoopOptions design;  ///< --target bound here
};

// The planned trial: its design, the travel and thrust it needs, and the σ predicted after it.
void PrintNextTrial(const planner::NextStepResult& r, std::ostream& out) {
  const auto& d = r.trial.design;
  std::ostringstream travel;
  travel << std::fixed << std::setprecision(2) << "[" << r.trial.travel[0] << ", "
         << r.trial.travel[1] << "] " << model::PositionUnit(d.dof) << ", smallest thrust "
         << r.trial.thrust_min << " N";
  out << "Next: " << d.id << " (" << model::DofName(d.dof) << ", " << r.source << ")\n  "
      << TrialLine(d) << "\n  travel " << travel.str() << "\n  " << r.message << "\n";
  if (!r.predicted.sigma.empty()) {
    out << "  predicted σ after it:";
    for (const auto& [name, s] : r.predicted.sigma) {
      out << "  " << name << " " << std::setprecision(3) << s;
    }
    out << "\n";
  }
}

void PrintNextStep(const planner::NextStepResult& r, const model::Campaign& campaign,
                   const model::Pool& pool, const NextCliOptions& o, std::ostream& out) {
  const double target = o.design.target_percent;
  out << "Next trial for " << campaign.vehicle.name << " in pool " << pool.name << " after "
      << campaign.trials.size() << " trial(s) of " << o.campaign << "\n\n";
  if (!r.estimates.dofs.empty()) {
    PrintIdentifyTable(r.estimates, out);
    out << "\n";
  }
  out << "Parameters of interest (m; kq where significant, else k; every η):\n";
  PrintProgress(r.progress, target, out);
  out << "\n";
  switch (r.status) {
    case planner::NextStatus::kTrial:
      PrintNextTrial(r, out);
      break;
    case planner::NextStatus::kConverged:
      out << "No trial needed: " << r.message << "\n";
      break;
    case planner::NextStatus::kInfeasible:
      out << "No trial can be planned: " << r.message << "\n";
      break;
  }
  if (!r.notes.empty()) {
    out << "\nNotes:\n";
    for (const auto& n : r.notes) out << "  - " << n << "\n";
  }
}

// {"estimates", "trial" (null unless planned), "predicted", "status", "message", "source",
//  "target", "progress", "notes"}.
nlohmann::json NextStepJson(const planner::NextStepResult& r, double target) {
  const bool planned = r.status == planner::NextStatus::kTrial;
  nlohmann::json j;
  j["estimates"] = io::IdentifyJson(r.estimates);
  j["trial"] = planned ? io::TrialToJson(r.trial) : nlohmann::json(nullptr);
  j["predicted"] = planned ? PredictedJson(r.dof, r.predicted) : nlohmann::json::object();
  j["status"] = std::string(planner::NextStatusName(r.status));
  j["message"] = r.message;
  j["source"] = r.source;
  j["target"] = target;
  j["progress"] = ProgressJson(r.progress);
  j["notes"] = r.notes;
  return j;
}

int RunNext(const NextCliOptions& o) {
  if (!(o.design.target_percent > 0)) {
    throw model::InputError("--target", "expected a percentile error > 0 (%), got " +
                                            model::ShortestNumber(o.design.target_percent));
  }
  const model::Campaign campaign = ReadCampaignForIdentification(o.campaign, o.accept_units);
  const model::Pool pool = io::ReadPool(o.pool);
  planner::DesignLoopOptions options = o.design;
  options.dofs = ParseDofFlags(o.dofs);
  const planner::NextStepResult r = planner::NextStep(campaign, pool, options);
  PrintNextStep(r, campaign, pool, o, ReportStream(o.json));
  if (!o.json.empty()) WriteJson(o.json, NextStepJson(r, o.design.target_percent));
  return r.status == planner::NextStatus::kInfeasible ? kExitActionNeeded : kExitOk;
}

void BindNext(CLI::App* sub, NextCliOptions* o) {
  sub->add_option("CAMPAIGN", o->campaign, "campaign.yaml of the trials run so far, or its directory")->required();
  sub->add_option("--pool", o->pool, "pool.yaml of the pool of the next trial")->required();
  sub->add_option("--dof", o->dofs,
                  "DOF to drive to the target (repeatable; default: the DOFs the campaign "
                  "has trials of, or every DOF the vehicle can plan)");
  sub->add_option("--target", o->design.target_percent,
                  "percentile error 100·σ/|θ| (%) every parameter of interest must reach")
      ->capture_default_str();
  AddJsonOption(sub, &o->json, "also write the result");
  AddAcceptUnitsFlag(sub, &o->accept_units);
}

const CommandRegistration kRegistration(MakeCommand<NextCliOptions>(
    "next", 45,
    "Identify from the trials so far, then plan the single most informative next trial "
    "(sequential design: box = estimates ± 2σ, prior information = covariance⁻¹).",
    BindNext, RunNext));

}  // namespace
}  // namespace uuvplan::tool
