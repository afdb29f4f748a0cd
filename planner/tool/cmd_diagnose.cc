// `uuvplan diagnose CAMPAIGN [--json F] [--dof D]...`: what the standard model's simulation
// gets wrong, the physical effect that causes it, the extended model and its gain
// (ident/diagnosis.h, docs/diagnosis.md). Exit 0 (findings are results, not errors), 1 when no
// DOF could be diagnosed (its standard model could not be fitted: the notes say why), 2 on bad
// input.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>

#include "command.h"
#include "diagnosis_report.h"
#include "uuvplan/io/diagnosis_json.h"
#include "uuvplan/ident/diagnosis.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/io/io.h"

namespace uuvplan::tool {
namespace {

struct DiagnoseCommandOptions {
  std::string campaign;
  std::string json;
  std::vector<std::string> dofs;
};

int Run(const DiagnoseCommandOptions& co) {
  const model::Campaign campaign = io::ReadCampaign(co.campaign);
  ident::DiagnoseOptions o;
  for (const auto& d : co.dofs) {
    const auto dof = model::ParseDof(d);
    if (!dof) throw model::InputError("--dof " + d, "expected surge, sway, heave, roll, pitch or yaw");
    o.dofs.push_back(*dof);
  }
  const ident::DiagnosisResult result = ident::Diagnose(campaign, o);
  std::ostream& out = co.json == "-" ? std::cerr : std::cout;
  PrintDiagnosis(result, out);
  if (!co.json.empty()) {
    const std::string text = io::DiagnosisJson(result).dump(2) + "\n";
    if (co.json == "-") {
      std::cout << text;
    } else {
      io::WriteFileAtomically(co.json, text);
    }
  }
  // A breakdown exists for each DOF whose standard model was fitted, i.e. diagnosed.
  return result.breakdowns.empty() ? kExitActionNeeded : kExitOk;
}

const CommandRegistration kRegistration(
    {"diagnose", 80, [](CLI::App& app, std::function<int()>* run) {
       auto o = std::make_shared<DiagnoseCommandOptions>();
       CLI::App* sub = app.add_subcommand(
           "diagnose",
           "What the standard model's simulation gets wrong on measured trials, which physical "
           "effect causes it (installation loss, asymmetric drag, thruster lag, dead zone, "
           "advance-speed loss, coupling, sensor delay, drift, a thrust map wrong in shape), the extended "
           "model and its gain.");
       sub->add_option("CAMPAIGN", o->campaign, "campaign.yaml")->required();
       sub->add_option("--json", o->json, "also write the result as JSON to this file ('-' = stdout)");
       sub->add_option("--dof", o->dofs, "diagnose only this DOF (repeatable)");
       sub->callback([o, run] { *run = [o] { return Run(*o); }; });
     }});

}  // namespace
}  // namespace uuvplan::tool
