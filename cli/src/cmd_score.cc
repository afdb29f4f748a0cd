// `uuvplan score VEHICLE CAMPAIGN [--json F] [--dof D]... [--sg-window N]`: the free-run error of
// each trial for the parameter set a vehicle file gives (dofs.<dof>.params and effects, as
// `diagnose --write-vehicle` writes it, or a truth file), without fitting: two models of one
// vehicle compared on the same data (ident/score.h, docs/cli.md). Exit 0; 1 when a DOF cannot
// be scored (a free run that cannot be simulated, nothing left to score); 2 on bad input.
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "uuvplan/cli/command.h"
#include "uuvplan/cli/filter_window_flag.h"
#include "uuvplan/ident/score.h"
#include "uuvplan/io/campaign_yaml.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/score_json.h"
#include "uuvplan/text/quantity_text.h"
#include "uuvplan/text/score_notes_text.h"
#include "uuvplan/text/text_table.h"

namespace uuvplan::cli {
namespace {

struct ScoreFlags {
  std::string vehicle;
  std::string campaign;
  std::string json;
  std::vector<std::string> dofs;
  ident::TrialDataOptions data;  ///< --sg-window
};

// trial, dof, use, velocity MAE, position RMS, samples: the score table's fixed columns.
const std::vector<text::FixedColumn> kScoreColumns{{32},       {7},        {10},
                                                   {18, true}, {16, true}, {10, true}};

void PrintScores(const ident::ScoreResult& r, const ScoreFlags& co, std::ostream& out) {
  out << "Free-run scores of the model in " << co.vehicle << " on " << co.campaign
      << " (no fit; velocity MAE: seed 002 eq. 37)\n";
  out << "  "
      << text::FixedRow(kScoreColumns,
                        {"trial", "dof", "use", "velocity MAE", "position RMS", "samples"})
      << "\n";
  for (const ident::TrialScore& s : r.trials) {
    // Angles in degrees, as identify and diagnose print them (docs/cli.md); the JSON keeps rad.
    const bool rotation = model::IsRotational(s.dof);
    const std::string unit(model::VelocityUnit(s.dof)), pos(rotation ? "°" : "m");
    const double position_rms = (rotation ? 180.0 / M_PI : 1.0) * s.fit.position_rms;
    out << "  "
        << text::FixedRow(kScoreColumns, {s.fit.name, std::string(model::DofName(s.dof)),
                                          std::string(model::TrialUseName(s.fit.use)),
                                          text::Quantity(s.fit.velocity_mae, unit, 4),
                                          text::Quantity(position_rms, pos, 4),
                                          std::to_string(s.fit.velocity_samples)})
        << "\n";
  }
  for (const ident::DofScore& d : r.dofs) {
    const std::string unit(model::VelocityUnit(d.dof));
    out << model::DofName(d.dof) << ": velocity MAE pooled over the samples: fit "
        << text::Quantity(d.velocity_mae_fit, unit, 4) << " (" << d.samples_fit << "), validate "
        << text::Quantity(d.velocity_mae_validate, unit, 4) << " (" << d.samples_validate
        << "), all " << text::Quantity(d.velocity_mae_all, unit, 4)
        << (d.problem.empty() ? "" : "; cannot be scored: " + d.problem) << "\n";
  }
  for (const ident::ScoreNote& n : r.notes) out << "note: " << text::NoteText(n) << "\n";
}

int RunScore(const ScoreFlags& co) {
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

void BindScore(CLI::App* sub, ScoreFlags* o) {
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

const CommandRegistration kScoreRegistration(MakeCommand<ScoreFlags>(
    "score", 85,
    "Free-run error of every trial of a campaign for the parameter set of a vehicle file, "
    "without fitting: two models compared on the same data.",
    BindScore, RunScore));

}  // namespace
}  // namespace uuvplan::cli
