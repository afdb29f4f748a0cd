// `uuvplan score VEHICLE CAMPAIGN [--json F] [--dof D]... [--sg-window N]`: the free-run error of each trial
// for the parameter set a vehicle file gives (dofs.<dof>.params and effects, as
// `diagnose --write-vehicle` writes it, or a truth file), without fitting: two models of one
// vehicle compared on the same data (ident/score.h, docs/cli.md). Exit 0; 1 when a DOF cannot
// be scored (a free run that cannot be simulated, nothing left to score); 2 on bad input.
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "uuvplan/cli/command.h"
#include "uuvplan/cli/filter_window_flag.h"
#include "uuvplan/ident/score.h"
#include "uuvplan/io/campaign_yaml.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/score_json.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::cli {
namespace {

struct ScoreCommandOptions {
  std::string vehicle;
  std::string campaign;
  std::string json;
  std::vector<std::string> dofs;
  ident::TrialDataOptions data;  ///< --sg-window
};

std::string Number(double x, const std::string& unit) {
  return std::isfinite(x) ? model::Significant(x, 4) + " " + unit : "-";
}

void PrintScores(const ident::ScoreResult& r, const ScoreCommandOptions& co, std::ostream& out) {
  out << "Free-run scores of the model in " << co.vehicle << " on " << co.campaign
      << " (no fit; velocity MAE: seed 002 eq. 37)\n";
  out << "  " << std::left << std::setw(32) << "trial" << std::setw(7) << "dof" << std::setw(10)
      << "use" << std::right << std::setw(18) << "velocity MAE" << std::setw(16) << "position RMS"
      << std::setw(10) << "samples" << "\n";
  for (const ident::TrialScore& s : r.trials) {
    // Angles in degrees, as identify and diagnose print them (docs/cli.md); the JSON keeps rad.
    const bool rotation = model::IsRotational(s.dof);
    const std::string unit(model::VelocityUnit(s.dof)), pos(rotation ? "°" : "m");
    out << "  " << std::left << std::setw(32) << s.fit.name << std::setw(7)
        << model::DofName(s.dof) << std::setw(10) << io::TrialUseName(s.fit.use) << std::right
        << std::setw(18) << Number(s.fit.velocity_mae, unit) << std::setw(16)
        << Number((rotation ? 180.0 / M_PI : 1.0) * s.fit.position_rms, pos) << std::setw(10)
        << s.fit.velocity_samples << "\n";
  }
  for (const ident::DofScore& d : r.dofs) {
    const std::string unit(model::VelocityUnit(d.dof));
    out << model::DofName(d.dof) << ": velocity MAE pooled over the samples: fit "
        << Number(d.velocity_mae_fit, unit) << " (" << d.samples_fit << "), validate "
        << Number(d.velocity_mae_validate, unit) << " (" << d.samples_validate << "), all "
        << Number(d.velocity_mae_all, unit)
        << (d.problem.empty() ? "" : "; cannot be scored: " + d.problem) << "\n";
  }
  for (const std::string& n : r.notes) out << "note: " << n << "\n";
}

int RunScore(const ScoreCommandOptions& co) {
  CheckFilterWindow(co.data);
  const model::Truth given = io::ReadTruth(co.vehicle);
  const model::Campaign campaign = io::ReadCampaign(co.campaign);
  ident::ScoreOptions o;
  o.data = co.data;
  o.dofs = ParseDofFlags(co.dofs);
  const ident::ScoreResult result = ident::ScoreCampaign(campaign, given, o);
  PrintScores(result, co, ReportStream(co.json));
  if (!co.json.empty()) WriteJson(co.json, io::ScoreJson(result, co.vehicle, co.campaign));
  bool scored = !result.dofs.empty();
  for (const ident::DofScore& d : result.dofs) scored = scored && d.problem.empty();
  return scored ? kExitOk : kExitActionNeeded;
}

void BindScore(CLI::App* sub, ScoreCommandOptions* o) {
  sub->add_option("VEHICLE", o->vehicle,
                  "vehicle file with a model (dofs.<dof>.params and effects: `diagnose "
                  "--write-vehicle`), or a truth file")
      ->required();
  sub->add_option("CAMPAIGN", o->campaign, "campaign.yaml or the directory that holds it")
      ->required();
  AddJsonOption(sub, &o->json, "also write the scores");
  sub->add_option("--dof", o->dofs, "score only this DOF (repeatable)");
  AddFilterWindowOption(sub, &o->data);
}

const CommandRegistration kRegistration(MakeCommand<ScoreCommandOptions>(
    "score", 85,
    "Free-run error of every trial of a campaign for the parameter set of a vehicle file, "
    "without fitting: two models compared on the same data.",
    BindScore, RunScore));

}  // namespace
}  // namespace uuvplan::cli
