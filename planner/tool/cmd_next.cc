// `uuvplan next CAMPAIGN --pool POOL [--dof D]... [--target PCT] [--json F]`: identify from
// every trial logged so far, turn the estimates and their covariance into the a priori
// knowledge of the design (box = estimates ± 2σ, prior information = covariance⁻¹) and plan the
// single most informative next trial (planner/design_loop.h, docs/loop.md) — what a pool team
// runs between two trials. The result can be run with `simulate --plan` (its "trial").
// Exit status: 0 a trial is planned, or every parameter of interest is already below the
// target (then "trial" is null); 1 no trial that is still needed fits the pool; 2 bad input.
#include <CLI/CLI.hpp>
#include <iomanip>
#include <iostream>
#include <memory>
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
#include "uuvplan/planner/design_loop.h"

namespace uuvplan::tool {
namespace {

using model::InputError;

std::string Str(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}

struct NextCliOptions {
  std::string campaign;
  std::string pool;
  std::vector<std::string> dofs;
  double target = 5.0;
  std::string json;
};

std::vector<model::Dof> ParseDofs(const std::vector<std::string>& names) {
  std::vector<model::Dof> out;
  for (const auto& n : names) {
    const auto d = model::ParseDof(n);
    if (!d) throw InputError("--dof " + n, "expected surge, sway, heave, roll, pitch or yaw");
    out.push_back(*d);
  }
  return out;
}

int RunNext(const NextCliOptions& o) {
  if (!(o.target > 0)) {
    throw InputError("--target", "expected a percentile error > 0 (%), got " + Str(o.target));
  }
  const model::Campaign campaign = io::ReadCampaign(o.campaign);
  const model::Pool pool = io::ReadPool(o.pool);
  planner::DesignLoopOptions options;
  options.dofs = ParseDofs(o.dofs);
  options.target_percent = o.target;
  const planner::NextStepResult r = planner::NextStep(campaign, pool, options);

  std::ostream& out = o.json == "-" ? std::cerr : std::cout;
  out << "Next trial for " << campaign.vehicle.name << " in pool " << pool.name << " after "
      << campaign.trials.size() << " trial(s) of " << o.campaign << "\n\n";
  if (!r.estimates.dofs.empty()) {
    PrintIdentifyTable(r.estimates, out);
    out << "\n";
  }
  out << "Parameters of interest (m; kq where significant, else k; every η):\n";
  PrintProgress(r.progress, o.target, out);
  out << "\n";
  switch (r.status) {
    case planner::NextStatus::kTrial: {
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
      break;
    }
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
  if (!o.json.empty()) {
    nlohmann::json j;
    j["estimates"] = io::IdentifyJson(r.estimates);
    j["trial"] = r.status == planner::NextStatus::kTrial ? io::TrialToJson(r.trial)
                                                         : nlohmann::json(nullptr);
    j["predicted"] = r.status == planner::NextStatus::kTrial ? PredictedJson(r.dof, r.predicted)
                                                             : nlohmann::json::object();
    j["status"] = std::string(planner::NextStatusName(r.status));
    j["message"] = r.message;
    j["source"] = r.source;
    j["target"] = o.target;
    j["progress"] = ProgressJson(r.progress);
    j["notes"] = r.notes;
    WriteJson(o.json, j);
  }
  return r.status == planner::NextStatus::kInfeasible ? kExitActionNeeded : kExitOk;
}

const CommandRegistration kRegistration(
    {"next", 45, [](CLI::App& app, std::function<int()>* run) {
       auto o = std::make_shared<NextCliOptions>();
       CLI::App* sub = app.add_subcommand(
           "next",
           "Identify from the trials so far, then plan the single most informative next trial "
           "(sequential design: box = estimates ± 2σ, prior information = covariance⁻¹).");
       sub->add_option("CAMPAIGN", o->campaign, "campaign.yaml of the trials run so far")
           ->required();
       sub->add_option("--pool", o->pool, "pool.yaml of the pool of the next trial")->required();
       sub->add_option("--dof", o->dofs,
                       "DOF to drive to the target (repeatable; default: the DOFs the campaign "
                       "has trials of, or every DOF the vehicle can plan)");
       sub->add_option("--target", o->target,
                       "percentile error 100·σ/|θ| (%) every parameter of interest must reach")
           ->capture_default_str();
       sub->add_option("--json", o->json,
                       "also write the result as JSON to this file ('-' = stdout)");
       sub->callback([o, run] { *run = [o] { return RunNext(*o); }; });
     }});

}  // namespace
}  // namespace uuvplan::tool
