// `uuvplan diagnose CAMPAIGN [--json F] [--dof D]... [--write-vehicle OUT.yaml] [--sg-window N]`:
// what the standard model's simulation gets wrong, the physical effect that causes it, the extended
// model and its gain (ident/diagnosis/diagnosis.h, docs/diagnosis.md). Exit 0 (findings are
// results, not errors), 1 when a DOF could not be diagnosed (its standard model's identification or
// fit failed: the report says why), 2 on bad input. Progress lines on stderr once a run has taken 2
// s. On a terminal, the summary's Brief() line follows on stderr.
#include <chrono>
#include <functional>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "uuvplan/cli/command.h"
#include "uuvplan/cli/filter_window_flag.h"
#include "uuvplan/cli/model_vehicle_file.h"
#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/ident/score.h"
#include "uuvplan/io/diagnosis_json.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/text/diagnosis_report.h"

namespace uuvplan::cli {
namespace {

struct DiagnoseFlags {
  std::string campaign;
  std::string json;
  std::string write_vehicle;
  std::vector<std::string> dofs;
  bool accept_units = false;
  ident::DiagnoseOptions diagnose;  // the flags bound to it keep its defaults
};

// The extended model of every diagnosed DOF into the vehicle file `path`.
bool WriteExtendedVehicle(const std::string& path, const std::string& campaign_path,
                          const std::string& source, const model::Vehicle& vehicle,
                          const ident::DiagnosisResult& r) {
  std::vector<const ident::DofIdentification*> dofs;
  for (const ident::DofIdentification& e : r.extended) dofs.push_back(&e);
  std::string effects;
  for (const ident::Finding& f : r.findings) {
    effects += (effects.empty() ? "" : ", ") + std::string(model::DofName(f.dof)) + " " + f.effect;
  }
  return WriteModelVehicle("diagnose", path, campaign_path, source, vehicle, dofs,
                           "the extended model (" +
                               (effects.empty() ? "no effect found" : effects) +
                               "),\nfitted by output error on the fit trials; sigma: 1σ of each "
                               "parameter (0: held at its admissible bound).\nScore it on a "
                               "campaign with `uuvplan score`.");
}

int RunDiagnose(const DiagnoseFlags& co) {
  CheckFilterWindow(co.diagnose.identify.data);
  const model::Campaign campaign = ReadCampaignForIdentification(co.campaign, co.accept_units);
  RefuseWritingOverTheVehicleFile(co.write_vehicle, campaign);
  ident::DiagnoseOptions o = co.diagnose;
  o.dofs = ParseDofFlags(co.dofs);
  o.progress = TerminalProgress("diagnose");
  const ident::DiagnosisResult result = ident::Diagnose(campaign, o);
  text::PrintDiagnosis(result, ReportStream(co.json));
  if (!co.json.empty()) WriteJson(co.json, io::DiagnosisJson(result));
  PrintBriefOnTerminal(result.Summary().Brief());
  const bool written =
      co.write_vehicle.empty() ||
      WriteExtendedVehicle(co.write_vehicle, co.campaign, CampaignVehicleFile(campaign),
                           campaign.vehicle, result);
  // A DOF whose standard model failed is refused: a failure, as identify's (exit 1).
  return result.not_diagnosed.empty() && written ? kExitOk : kExitActionNeeded;
}

void BindDiagnose(CLI::App* sub, DiagnoseFlags* o) {
  sub->add_option("CAMPAIGN", o->campaign, "campaign.yaml or the directory that holds it")
      ->required();
  AddJsonOption(sub, &o->json, "also write the result");
  sub->add_option("--dof", o->dofs, "diagnose only this DOF (repeatable)");
  AddAcceptUnitsFlag(sub, &o->accept_units);
  AddThreadsOption(sub, {&o->diagnose.threads, &o->diagnose.identify.threads},
                   "the candidate fits and the nominal identification");
  sub->add_option("--write-vehicle", o->write_vehicle,
                  "write the extended model (every parameter with sigma, the effects found) "
                  "into this vehicle file, for `uuvplan score` and every command")
      ->check(OutputFile());
  AddFilterWindowOption(sub, &o->diagnose.identify.data);
  sub->add_option("--max-effects", o->diagnose.max_effects, "effects added per DOF at most")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
}

const CommandRegistration kDiagnoseRegistration(MakeCommand<DiagnoseFlags>(
    "diagnose", 82,
    "What the standard model's simulation gets wrong on measured trials, which physical "
    "effect causes it (" +
        model::Effects().NameList() + "), the extended model and its gain.",
    BindDiagnose, RunDiagnose));

}  // namespace
}  // namespace uuvplan::cli
