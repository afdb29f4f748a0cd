// `uuvplan identify CAMPAIGN [--json F] [--dof D]... [--steady TRIAL:T0:T1]... [--no-refine]
// [--no-prune] [--closed-loop yes|no|auto]`: parameter estimates with standard deviations and
// the fit of the identified model (ident/identify.h, docs/identification.md). Exit status 0
// when every DOF was identified, 1 when some DOF could not be (the message says what would fix
// it), 2 on bad input.
#include <CLI/CLI.hpp>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "command.h"
#include "identify_table.h"
#include "uuvplan/io/identify_json.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/io/io.h"

namespace uuvplan::tool {
namespace {

using model::InputError;

struct IdentifyCommandOptions {
  std::string campaign;
  std::string json;
  std::vector<std::string> dofs;
  std::vector<std::string> steady;
  bool no_refine = false;
  bool no_prune = false;
  std::string closed_loop = "auto";
};

// TRIAL:T0:T1 with TRIAL a campaign trial's file (as written) or its 0-based index.
void AddSteadyWindow(const std::string& spec, const model::Campaign& c, ident::IdentifyOptions* o) {
  const auto p2 = spec.rfind(':');
  const auto p1 = p2 == std::string::npos || p2 == 0 ? std::string::npos : spec.rfind(':', p2 - 1);
  if (p1 == std::string::npos) {
    throw InputError("--steady " + spec, "expected TRIAL:T0:T1 (trial file or index, times in s)");
  }
  const std::string trial = spec.substr(0, p1);
  double t0 = 0.0, t1 = 0.0;
  try {
    t0 = std::stod(spec.substr(p1 + 1, p2 - p1 - 1));
    t1 = std::stod(spec.substr(p2 + 1));
  } catch (const std::exception&) {
    throw InputError("--steady " + spec, "expected numbers T0 and T1 (s)");
  }
  if (!(t1 > t0)) throw InputError("--steady " + spec, "expected T1 > T0");
  int index = -1;
  for (std::size_t i = 0; i < c.trials.size(); ++i) {
    if (c.trials[i].file == trial) index = static_cast<int>(i);
  }
  if (index < 0) {
    try {
      std::size_t used = 0;
      const int i = std::stoi(trial, &used);
      if (used == trial.size() && i >= 0 && i < static_cast<int>(c.trials.size())) index = i;
    } catch (const std::exception&) {
    }
  }
  if (index < 0) {
    throw InputError("--steady " + spec, "'" + trial + "' is not a trial of the campaign (give its "
                                                        "file as written in the campaign, or its index)");
  }
  o->steady_windows[index].push_back({t0, t1});
}

int RunIdentify(const IdentifyCommandOptions& co) {
  const model::Campaign campaign = io::ReadCampaign(co.campaign);
  ident::IdentifyOptions o;
  for (const std::string& name : co.dofs) {
    const auto dof = model::ParseDof(name);
    if (!dof) {
      throw InputError("--dof " + name, "expected one of surge, sway, heave, roll, pitch, yaw");
    }
    o.dofs.push_back(*dof);
  }
  for (const std::string& s : co.steady) AddSteadyWindow(s, campaign, &o);
  o.refine = !co.no_refine;
  o.prune_insignificant = !co.no_prune;
  if (co.closed_loop == "yes") {
    o.closed_loop = ident::ClosedLoop::kYes;
  } else if (co.closed_loop == "no") {
    o.closed_loop = ident::ClosedLoop::kNo;
  } else if (co.closed_loop != "auto") {
    throw InputError("--closed-loop " + co.closed_loop, "expected yes, no or auto");
  }
  const ident::IdentifyResult result = ident::Identify(campaign, o);

  std::ostream& out = co.json == "-" ? std::cerr : std::cout;
  out << "Identification of " << co.campaign << " (vehicle '" << campaign.vehicle.name << "', "
      << campaign.trials.size() << " trials)\n\n";
  PrintIdentifyTable(result, out);
  if (!co.json.empty()) {
    const std::string text = io::IdentifyJson(result).dump(2) + "\n";
    if (co.json == "-") {
      std::cout << text;
    } else {
      io::WriteFileAtomically(co.json, text);
    }
  }
  return result.status == ident::IdentifyStatus::kFailed ? kExitActionNeeded : kExitOk;
}

const CommandRegistration kRegistration(
    {"identify", 40, [](CLI::App& app, std::function<int()>* run) {
       auto o = std::make_shared<IdentifyCommandOptions>();
       CLI::App* sub = app.add_subcommand(
           "identify",
           "Estimate every DOF's parameters (m, k, kq, bias, bias_step, eta) with standard "
           "deviations from a campaign, and score the identified model by free-run simulation "
           "on its fit and validate trials.");
       sub->add_option("CAMPAIGN", o->campaign, "campaign.yaml")->required();
       sub->add_option("--json", o->json, "also write the result as JSON to this file ('-' = stdout)");
       sub->add_option("--dof", o->dofs, "identify only this DOF (repeatable; default: every DOF "
                                         "with fit trials)");
       sub->add_option("--steady", o->steady,
                       "mark a steady-state window TRIAL:T0:T1 (trial file or index, log time in "
                       "s; repeatable); the trial's steady segments are then not detected")
           ->take_all();
       sub->add_flag("--no-refine", o->no_refine,
                     "skip the output-error refinement (report the least-squares estimates)");
       sub->add_flag("--no-prune", o->no_prune,
                     "keep insignificant drag/bias parameters (no model selection by the "
                     "51.02% rule)");
       sub->add_option("--closed-loop", o->closed_loop,
                       "whether the logs were recorded in closed loop: auto (detect), yes, no")
           ->capture_default_str();
       sub->callback([o, run] { *run = [o] { return RunIdentify(*o); }; });
     }});

}  // namespace
}  // namespace uuvplan::tool
