// `uuvplan diagnose CAMPAIGN [--json F] [--dof D]...`: what the standard model's simulation
// gets wrong, the physical effect that causes it, the extended model and its gain
// (ident/diagnosis.h, docs/diagnosis.md). Exit 0 (findings are results, not errors), 1 when no
// DOF could be diagnosed (its standard model could not be fitted: the notes say why), 2 on bad
// input. UUVPLAN_VERBOSE (set, any value) also prints the standard model's fit on stderr. On a
// terminal, the summary's Brief() line follows on stderr.
#include <cstdlib>
#include <string>
#include <vector>

#include "command.h"
#include "uuvplan/model/effects.h"
#include "diagnosis_report.h"
#include "uuvplan/io/diagnosis_json.h"
#include "uuvplan/ident/diagnosis.h"
#include "uuvplan/io/io.h"

namespace uuvplan::tool {
namespace {

struct DiagnoseCommandOptions {
  std::string campaign;
  std::string json;
  std::vector<std::string> dofs;
  bool accept_units = false;
};

int RunDiagnose(const DiagnoseCommandOptions& co) {
  const model::Campaign campaign = ReadCampaignForIdentification(co.campaign, co.accept_units);
  ident::DiagnoseOptions o;
  o.dofs = ParseDofFlags(co.dofs);
  o.verbose = std::getenv("UUVPLAN_VERBOSE") != nullptr;
  const ident::DiagnosisResult result = ident::Diagnose(campaign, o);
  PrintDiagnosis(result, ReportStream(co.json));
  if (!co.json.empty()) WriteJson(co.json, io::DiagnosisJson(result));
  PrintBriefOnTerminal(result.Summary().Brief());
  // A breakdown exists for each DOF whose standard model was fitted, i.e. diagnosed.
  return result.breakdowns.empty() ? kExitActionNeeded : kExitOk;
}

void BindDiagnose(CLI::App* sub, DiagnoseCommandOptions* o) {
  sub->add_option("CAMPAIGN", o->campaign, "campaign.yaml or the directory that holds it")->required();
  AddJsonOption(sub, &o->json, "also write the result");
  sub->add_option("--dof", o->dofs, "diagnose only this DOF (repeatable)");
  AddAcceptUnitsFlag(sub, &o->accept_units);
}

const CommandRegistration kRegistration(MakeCommand<DiagnoseCommandOptions>(
    "diagnose", 80,
    "What the standard model's simulation gets wrong on measured trials, which physical "
    "effect causes it (" + model::Effects().NameList() + "), the extended model and its gain.",
    BindDiagnose, RunDiagnose));

}  // namespace
}  // namespace uuvplan::tool
