// `uuvplan identify CAMPAIGN [--json F] [--dof D]... [--steady TRIAL:T0:T1]... [--no-refine]
// [--no-prune] [--closed-loop yes|no|auto] [--method M [--forgetting λ]] [--sg-window N]
// [--model dof|coupled] [--accept-units] [--write-vehicle OUT]`:
// parameter estimates with standard deviations and the fit of the identified model
// (ident/identify.h, docs/identification.md); --method runs one of the papers' estimators alone.
// Exit status 0 when every DOF was identified, 1 when some DOF failed (its FAILED line says
// why) or its model does not explain the data (status model_error: run diagnose), 2 on bad input —
// units or signs that look wrong among it (ident/prepare/input_sanity.h) unless
// --accept-units. On a terminal, the summary's Brief() line follows on stderr.
#include <iostream>
#include <string>
#include <vector>

#include "uuvplan/cli/command.h"
#include "uuvplan/cli/coupled_identify.h"
#include "uuvplan/cli/filter_window_flag.h"
#include "uuvplan/cli/method_flags.h"
#include "uuvplan/cli/model_vehicle_file.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/io/identify_json.h"
#include "uuvplan/io/io.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/text/identify_table.h"

namespace uuvplan::cli {
namespace {

using model::InputError;

// The values of --closed-loop.
constexpr model::EnumNames<ident::ClosedLoop, 3> kClosedLoopNames{{{
    {ident::ClosedLoop::kAuto, "auto"},
    {ident::ClosedLoop::kYes, "yes"},
    {ident::ClosedLoop::kNo, "no"},
}}};

struct IdentifyFlags {
  std::string campaign;
  std::string json;
  std::string write_vehicle;
  std::vector<std::string> dofs;
  std::vector<std::string> steady;
  std::string closed_loop{kClosedLoopNames.Name(ident::IdentifyOptions{}.closed_loop)};
  MethodFlags method;  ///< --method, --forgetting
  bool accept_units = false;
  std::string model_kind = "dof";   ///< --model: dof (one model per DOF) or coupled (ref 003)
  ident::IdentifyOptions identify;  ///< --no-refine, --no-prune bound here
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
    throw InputError("--steady " + spec, "'" + trial +
                                             "' is not a trial of the campaign (give its "
                                             "file as written in the campaign, or its index)");
  }
  o->steady_windows[index].push_back({t0, t1});
}

// `--model coupled` fits ref 003's model by its own estimator (joint_ls.h) on every DOF
// at once: the options of the per-DOF chain do not apply, and one given would be ignored.
void RefuseChainOptionsWithCoupled(const IdentifyFlags& co) {
  const ident::IdentifyOptions chain;
  std::vector<std::string> given;
  if (!co.dofs.empty()) given.push_back("--dof");
  if (!co.steady.empty()) given.push_back("--steady");
  if (co.identify.refine != chain.refine) given.push_back("--no-refine");
  const ident::ModelSelectionOptions& selection = co.identify.selection;
  if (selection.prune_insignificant != chain.selection.prune_insignificant) {
    given.push_back("--no-prune");
  }
  if (selection.drop_correlation != chain.selection.drop_correlation) {
    given.push_back("--seed-selection");
  }
  if (co.closed_loop != kClosedLoopNames.Name(chain.closed_loop)) given.push_back("--closed-loop");
  if (co.method.method != ident::MethodName(chain.method)) given.push_back("--method");
  if (co.method.forgetting_given) given.push_back("--forgetting");
  if (co.identify.data.sg_window != chain.data.sg_window) given.push_back("--sg-window");
  if (!given.empty()) {
    throw InputError("--model coupled", "no " + model::Join(given) +
                                            ": the coupled model is fitted by its own estimator "
                                            "(one-step LS with instruments) on surge, sway and "
                                            "yaw together; drop them, or use --model dof");
  }
}

int RunIdentify(const IdentifyFlags& co) {
  if (co.model_kind == "coupled") RefuseChainOptionsWithCoupled(co);
  CheckFilterWindow(co.identify.data);
  model::Campaign campaign = ReadCampaignForIdentification(co.campaign, co.accept_units);
  RefuseWritingOverTheVehicleFile(co.write_vehicle, campaign);
  if (co.model_kind == "coupled") return RunCoupledIdentify(campaign, co.campaign, co.json);
  ident::IdentifyOptions o = co.identify;
  o.dofs = ParseDofFlags(co.dofs);
  for (const std::string& s : co.steady) AddSteadyWindow(s, campaign, &o);
  const auto closed_loop = kClosedLoopNames.Parse(co.closed_loop);
  if (!closed_loop) {
    throw InputError("--closed-loop " + co.closed_loop, "expected yes, no or auto");
  }
  o.closed_loop = *closed_loop;
  ApplyMethodFlags(co.method, &o);
  const ident::IdentifyResult result = ident::IdentifyReleasingLogs(&campaign, o);

  std::ostream& out = ReportStream(co.json);
  out << "Identification of " << co.campaign << " (vehicle '" << campaign.vehicle.name << "', "
      << campaign.trials.size() << " trials; method " << ident::MethodName(result.method)
      << ")\n\n";
  text::PrintIdentifyTable(result, out);
  if (!co.json.empty()) WriteJson(co.json, io::IdentifyJson(result));
  PrintBriefOnTerminal(result.Summary().Brief());
  const bool written = co.write_vehicle.empty() ||
                       WriteIdentifiedVehicle("identify", co.write_vehicle, co.campaign,
                                              CampaignVehicleFile(campaign), campaign.vehicle,
                                              result, "the identified model");
  const bool act = result.status == ident::IdentifyStatus::kFailed ||
                   result.status == ident::IdentifyStatus::kModelError || !written;
  return act ? kExitActionNeeded : kExitOk;
}

void BindIdentify(CLI::App* sub, IdentifyFlags* o) {
  sub->add_option("CAMPAIGN", o->campaign, "campaign.yaml or the directory that holds it")
      ->required();
  AddJsonOption(sub, &o->json, "also write the result");
  sub->add_option("--write-vehicle", o->write_vehicle,
                  "write the identified model (every parameter with sigma) into this vehicle "
                  "file: schedule, next and loop then plan about the estimates")
      ->check(OutputFile());
  sub->add_option("--dof", o->dofs,
                  "identify only this DOF (repeatable; default: every DOF with fit trials)");
  sub->add_option("--steady", o->steady,
                  "mark a steady-state window TRIAL:T0:T1 (trial file or index, log time in "
                  "s; repeatable); the trial's steady segments are then not detected")
      ->take_all();
  sub->add_flag_callback(
      "--no-refine", [o] { o->identify.refine = false; },
      "skip the output-error refinement (report the least-squares estimates)");
  sub->add_flag_callback(
      "--no-prune", [o] { o->identify.selection.prune_insignificant = false; },
      "keep insignificant drag/bias parameters (no model selection by the 51.02% rule)");
  sub->add_flag_callback(
         "--seed-selection",
         [o] { o->identify.selection.drop_correlation = ident::kSeedDropCorrelation; },
         "drop an insignificant parameter even where it is correlated with another, as seed 000 "
         "§IV-D does (by default it is kept: the others' σ would assume it exactly 0)")
      ->excludes("--no-prune");
  sub->add_option("--closed-loop", o->closed_loop,
                  "whether the logs were recorded in closed loop: auto (detect), yes, no")
      ->capture_default_str();
  AddMethodOptions(sub, &o->method);
  AddFilterWindowOption(sub, &o->identify.data);
  sub->add_option("--model", o->model_kind,
                  "dof (a model per DOF) or coupled (seed 003's surge-sway-yaw model from "
                  "combined-mode trials, docs/identification.md)")
      ->check(CLI::IsMember({"dof", "coupled"}))
      ->capture_default_str();
  AddAcceptUnitsFlag(sub, &o->accept_units);
  AddThreadsOption(sub, {&o->identify.threads}, "preparing the trials and fitting the DOFs");
}

const CommandRegistration kIdentifyRegistration(MakeCommand<IdentifyFlags>(
    "identify", 40,
    "Estimate every DOF's parameters (m, k, kq, bias, bias_step, eta) with standard "
    "deviations from a campaign, and score the identified model by free-run simulation "
    "on its fit and validate trials.",
    BindIdentify, RunIdentify));

}  // namespace
}  // namespace uuvplan::cli
