// `uuvplan diagnose CAMPAIGN [--json F] [--dof D]...`: what the standard model's simulation
// gets wrong, the physical effect that causes it, the extended model and its gain
// (ident/diagnosis.h, docs/diagnosis.md). Exit 0 (findings are results, not errors), 1 when a
// DOF could not be diagnosed (its standard model's identification or fit failed: the report
// says why), 2 on bad input. Progress lines on stderr once a run has taken 2 s. UUVPLAN_VERBOSE (set, any value) also prints the standard model's fit on stderr. On a
// terminal, the summary's Brief() line follows on stderr.
#include <chrono>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <string>
#include <vector>

#include "command.h"
#include "uuvplan/model/effects.h"
#include "diagnosis_report.h"
#include "uuvplan/io/diagnosis_json.h"
#include "uuvplan/ident/diagnosis.h"
#include "uuvplan/io/io.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::tool {
namespace {

// Progress lines on stderr ("diagnose: 3.1 s: yaw: round 2, ..."), once the run has taken
// `after_s`: a short run stays quiet.
std::function<void(const std::string&)> ProgressAfter(double after_s) {
  const auto start = std::chrono::steady_clock::now();
  return [start, after_s](const std::string& line) {
    const double s =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (s >= after_s) std::cerr << "diagnose: " << model::Significant(s, 3) << " s: " << line << "\n";
  };
}

struct DiagnoseCommandOptions {
  std::string campaign;
  std::string json;
  std::vector<std::string> dofs;
};

int RunDiagnose(const DiagnoseCommandOptions& co) {
  const model::Campaign campaign = io::ReadCampaign(co.campaign);
  ident::DiagnoseOptions o;
  o.dofs = ParseDofFlags(co.dofs);
  o.verbose = std::getenv("UUVPLAN_VERBOSE") != nullptr;
  o.progress = ProgressAfter(2.0);
  const ident::DiagnosisResult result = ident::Diagnose(campaign, o);
  PrintDiagnosis(result, ReportStream(co.json));
  if (!co.json.empty()) WriteJson(co.json, io::DiagnosisJson(result));
  PrintBriefOnTerminal(result.Summary().Brief());
  // A DOF whose standard model failed is refused: a failure, as identify's (exit 1).
  return result.not_diagnosed.empty() ? kExitOk : kExitActionNeeded;
}

void BindDiagnose(CLI::App* sub, DiagnoseCommandOptions* o) {
  sub->add_option("CAMPAIGN", o->campaign, "campaign.yaml or the directory that holds it")->required();
  AddJsonOption(sub, &o->json, "also write the result");
  sub->add_option("--dof", o->dofs, "diagnose only this DOF (repeatable)");
}

const CommandRegistration kRegistration(MakeCommand<DiagnoseCommandOptions>(
    "diagnose", 80,
    "What the standard model's simulation gets wrong on measured trials, which physical "
    "effect causes it (" + model::Effects().NameList() + "), the extended model and its gain.",
    BindDiagnose, RunDiagnose));

}  // namespace
}  // namespace uuvplan::tool
