// `uuvplan simulate --truth TRUTH.yaml --plan PLAN.json --out DIR [--pool POOL] [--seed N]
// [--step S] [--json F]`: runs a plan on the virtual vehicle of a truth file
// (model/virtual_pool.h) and writes the campaign as a pool team would log it: DIR/campaign.yaml,
// DIR/vehicle.yaml and DIR/trials/<id>.csv. DIR must be new or empty; it is written whole or not
// at all. With --pool, exit 1 when a trial of the truth leaves the pool's free volume.
#include <cmath>
#include <filesystem>
#include <iostream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>

#include "uuvplan/cli/command.h"
#include "uuvplan/io/combined_design_json.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/json_value.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/io/simulation_json.h"
#include "uuvplan/io/virtual_campaign.h"
#include "uuvplan/model/campaign_builder.h"
#include "uuvplan/model/coupled_model.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/util/seed.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/model/virtual_pool.h"
#include "uuvplan/planner/design/thrust_limits.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/text/text_table.h"

namespace uuvplan::cli {
namespace {

namespace fs = std::filesystem;
using model::InputError;

struct SimulateFlags {
  std::string truth;
  std::string plan;
  std::string out;
  double step_s = std::numeric_limits<double>::quiet_NaN();  ///< NaN: the truth's step
  std::string json;
  std::string pool;  ///< --pool: the free volume every trial of the truth must keep
  model::VirtualCampaignOptions campaign;  ///< --seed bound here; its pause_s between trials
};

std::string MappingNames(const model::Vehicle& v, model::Dof dof) {
  std::string names;
  for (int i : v.MappingsOf(dof)) names += (names.empty() ? "" : ", ") + v.mappings[i].name;
  return names.empty() ? "none" : names;
}

// A mapping named in the plan must be one of the truth vehicle's mappings of the trial's DOF.
void CheckMapping(const model::Vehicle& v, const model::TrialDesign& d, const std::string& name,
                  const std::string& where) {
  const int i = v.MappingIndex(name);
  if (i >= 0 && v.mappings[i].dof == d.dof) return;
  throw InputError(where, "expected a " + std::string(model::DofName(d.dof)) +
                              " mapping of vehicle '" + v.name + "' (" + MappingNames(v, d.dof) +
                              "), got '" + name + "'");
}

// Everything the virtual pool needs for each trial, checked up front so that the message names
// the plan's trial and the truth file rather than failing half-way through the campaign.
void CheckPlanAgainstTruth(const planner::Schedule& plan, const model::Truth& truth,
                           const std::string& plan_path, const std::string& truth_path) {
  const model::Vehicle& v = truth.vehicle;
  for (std::size_t i = 0; i < plan.trials.size(); ++i) {
    const model::TrialDesign& d = plan.trials[i].design;
    const std::string where = plan_path + ": trials[" + std::to_string(i) + "]";
    const std::string dof(model::DofName(d.dof));
    CheckMapping(v, d, d.mapping, where + ".mapping");
    for (std::size_t k = 0; k < d.segments.size(); ++k) {
      if (!d.segments[k].mapping.empty()) {
        CheckMapping(v, d, d.segments[k].mapping,
                     where + ".segments[" + std::to_string(k) + "].mapping");
      }
    }
    if (truth.dofs.count(d.dof) == 0) {
      throw InputError(truth_path, "missing dofs." + dof + ".params: trial '" + d.id + "' (" +
                                       where + ") is a " + dof +
                                       " trial, and the truth has no true " + dof +
                                       " parameters to simulate it with");
    }
    const auto s = v.sensors.find(d.dof);
    if (s == v.sensors.end() || (!s->second.position && !s->second.velocity)) {
      throw InputError(truth_path, "missing sensors." + dof + ": trial '" + d.id + "' needs a " +
                                       dof + " position or velocity sensor");
    }
  }
}

// The virtual pool applies whatever force is asked; a real thruster saturates. One note per
// trial whose force profile asks a thruster more than its command range gives, checked as the
// planner checks it (planner::CheckThrust on phi_n(t) itself: a multisine's peak lies below the
// sum of its amplitudes).
std::vector<std::string> SaturationNotes(const planner::Schedule& plan, const model::Vehicle& v) {
  std::vector<std::string> notes;
  for (const auto& t : plan.trials) {
    const auto input = model::MakeExcitation(v, t.design);
    const planner::ThrustCheck c = planner::CheckThrust(v, *input, t.design.duration);
    if (!c.overload) continue;
    std::ostringstream s;
    s << "trial '" << t.design.id << "' asks a thruster up to "
      << model::Significant(100.0 * (c.thrust_max_ratio - 1.0), 3)
      << "% more than its command range gives (the virtual pool does not saturate thrusters)";
    notes.push_back(s.str());
  }
  return notes;
}

// Where trial `t` of the truth goes in the pool, from the negative end of its free travel (the
// rear or port wall's margin line, the surface's, or the tether's counter-clockwise end): the
// planned start plus the truth's travel (model::TrueTravel), or the travel alone from 0 when the
// plan places no start. "" when it stays within [0, FreeTravel].
std::string LeavesThePool(const planner::PlannedTrial& t, const model::Truth& truth,
                          const model::TrialEntry& entry, const model::Pool& pool,
                          double command_rate_hz) {
  const model::TrialDesign& d = t.design;
  const double free = pool.FreeTravel(d.dof);
  if (!std::isfinite(free)) return "";
  const auto travel = model::TrueTravel(truth, d, entry.start, command_rate_hz);
  const bool rotation = model::IsRotational(d.dof);
  const double start = t.start.from.empty() ? -travel[0]
                       : rotation           ? t.start.value * M_PI / 180.0
                                            : t.start.value - pool.margin;
  const double lo = start + travel[0], hi = start + travel[1];
  if (lo >= -1e-9 && hi <= free + 1e-9) return "";
  const double scale = rotation ? 180.0 / M_PI : 1.0;
  const std::string unit = rotation ? " deg" : " m";
  std::ostringstream s;
  s << "trial '" << d.id << "': the truth's " << model::DofName(d.dof);
  if (t.start.from.empty()) {
    s << " spans " << model::Significant((hi - lo) * scale, 3) << unit
      << " (the plan places no start)";
  } else {
    s << " goes from " << model::Significant(lo * scale, 3) << " to "
      << model::Significant(hi * scale, 3) << unit << " from "
      << (rotation ? t.start.from : "the margin line of " + t.start.from) << " (planned start "
      << model::Significant(t.start.value, 4) << " " << t.start.unit << ")";
  }
  s << "; pool " << pool.name << " leaves " << model::Significant(free * scale, 3) << unit
    << " free";
  return s.str();
}

// --out must be new or empty: nothing is overwritten.
void CheckNewOrEmpty(const std::string& out) {
  std::error_code ec;
  if (!fs::exists(out, ec)) return;
  if (!fs::is_directory(out, ec)) {
    throw InputError(out, "--out exists and is not a directory; choose a new directory");
  }
  if (!fs::is_empty(out, ec)) {
    throw InputError(out,
                     "--out exists and is not empty; choose a new directory (nothing "
                     "is overwritten)");
  }
}

void PrintCampaignTable(const model::Campaign& campaign,
                        const std::vector<model::TrialDesign>& designs, std::ostream& out) {
  // trial, dof, kind, mapping, duration, rows; then the file, unpadded.
  const std::vector<text::FixedColumn> columns{{22}, {7}, {10}, {24}, {10, true}, {8, true}};
  out << text::FixedRow(columns, {"trial", "dof", "kind", "mapping", "duration", "rows"})
      << "  file\n";
  for (std::size_t i = 0; i < campaign.trials.size(); ++i) {
    const auto& e = campaign.trials[i];
    const auto& d = designs[i];
    out << text::FixedRow(
               columns,
               {d.id, std::string(model::DofName(d.dof)), std::string(model::TrialKindName(d.kind)),
                d.mapping, model::Decimals(d.duration, 1) + " s", std::to_string(e.log.size())})
        << "  " << e.file << "\n";
  }
}

// A coupled schedule (`schedule --model coupled --json`): its combined trial flown by the
// coupled model's virtual pool (model/virtual_pool.h RunCombinedTrial, seed StreamSeed(seed, 0) as
// trial 0 of a campaign), written as a one-trial campaign listed under its first DOF, as `identify
// --model coupled` reads it.
int RunCoupledSimulate(const SimulateFlags& o, const model::Truth& truth,
                       const nlohmann::json& root) {
  const model::MultiDofModel coupled = model::CoupledModelOfTruth(truth);
  const model::CombinedTrialDesign trial = io::CombinedTrialOfJson(root, o.plan, coupled);
  for (const model::TrialDesign& in : trial.inputs) {
    const int m = truth.vehicle.MappingIndex(in.mapping);
    if (m < 0 || truth.vehicle.mappings[m].dof != in.dof) {
      throw InputError(o.plan + ": trial.inputs", "mapping '" + in.mapping + "' is not a " +
                                                      std::string(model::DofName(in.dof)) +
                                                      " mapping of the truth's vehicle (" +
                                                      MappingNames(truth.vehicle, in.dof) + ")");
    }
  }
  model::VirtualPoolOptions pool;
  pool.seed = model::StreamSeed(o.campaign.seed, 0);
  pool.command_rate_hz = o.campaign.command_rate_hz;
  model::Campaign campaign;
  campaign.vehicle = truth.vehicle;
  model::TrialEntry e;
  e.file = "trials/" + trial.id + ".csv";
  e.dof = trial.inputs.front().dof;
  e.mapping = trial.inputs.front().mapping;
  e.start = 0.0;
  e.has_start = true;
  e.log = model::RunCombinedTrial(truth, coupled, model::CoupledThetaOfTruth(coupled, truth), trial,
                                  pool);
  const std::size_t rows = e.log.t.size();
  campaign.trials.push_back(std::move(e));
  io::WriteCampaign(
      o.out, std::move(campaign), truth.vehicle,
      {"uuvplan virtual pool: truth vehicle '" + truth.vehicle.name + "', combined trial '" +
       trial.id + "', seed " + std::to_string(o.campaign.seed)});
  const std::string campaign_path = (fs::path(o.out) / "campaign.yaml").string();
  std::ostream& out = ReportStream(o.json);
  out << "Simulated the combined " << model::DofList(trial.dofs) << " trial '" << trial.id
      << "' of plan " << o.plan << " on the virtual '" << truth.vehicle.name << "' of " << o.truth
      << " (coupled horizontal model, seed 003)\n(seed " << o.campaign.seed << ", RK4 step "
      << truth.integration_step_s << " s): " << trial.duration << " s, " << rows
      << " rows\nCampaign: " << campaign_path << "  (identify it with --model coupled)\n";
  if (!o.json.empty()) {
    WriteJson(o.json, io::CoupledSimulationJson(trial, rows, campaign_path, o.campaign.seed,
                                                truth.integration_step_s));
  }
  return kExitOk;
}

int RunSimulate(const SimulateFlags& options) {
  SimulateFlags o = options;
  o.out = DirectoryName(o.out);
  if (!std::isnan(o.step_s) && !(o.step_s > 0 && std::isfinite(o.step_s))) {
    throw InputError("--step",
                     "expected a positive integration step in s, got " + std::to_string(o.step_s));
  }
  CheckNewOrEmpty(o.out);
  model::Truth truth = io::ReadTruth(o.truth);
  if (!std::isnan(o.step_s)) truth.integration_step_s = o.step_s;
  if (const nlohmann::json root = io::LoadJson(o.plan);
      io::IsCombinedScheduleJson(root, model::kCoupledModelName)) {
    if (!o.pool.empty()) {
      throw InputError("--pool",
                       "not checked for a coupled plan (its planar track is checked "
                       "by the planner over the box): leave it out");
    }
    return RunCoupledSimulate(o, truth, root);
  }
  const planner::Schedule plan = io::ReadScheduleJson(o.plan);
  CheckPlanAgainstTruth(plan, truth, o.plan, o.truth);
  std::optional<model::Pool> pool;
  if (!o.pool.empty()) pool = io::ReadPool(o.pool);

  std::vector<model::TrialDesign> designs;
  for (const auto& t : plan.trials) designs.push_back(t.design);
  const model::Campaign campaign = io::SimulateCampaign(truth, designs, o.out, o.campaign);

  for (const std::string& note : SaturationNotes(plan, truth.vehicle)) {
    std::cerr << "uuvplan simulate: note: " << note << "\n";
  }
  std::ostream& out = ReportStream(o.json);
  out << "Simulated " << campaign.trials.size() << " trial(s) of plan " << o.plan
      << " on the virtual '" << truth.vehicle.name << "' of " << o.truth << "\n"
      << "(seed " << o.campaign.seed << ", RK4 step " << truth.integration_step_s << " s, "
      << o.campaign.pause_s << " s pause between trials)\n\n";
  PrintCampaignTable(campaign, designs, out);
  const io::CampaignTotals totals = io::Totals(campaign, designs);
  const std::string campaign_path = (fs::path(o.out) / "campaign.yaml").string();
  out << "\n"
      << campaign.trials.size() << " trials, " << totals.rows << " rows, "
      << model::DurationText(totals.trial_time) << " of trials, "
      << model::DurationText(totals.clock) << " of pool time with pauses\n"
      << "Campaign: " << campaign_path << "\n";
  std::vector<std::string> outside;
  for (std::size_t i = 0; pool && i < plan.trials.size(); ++i) {
    std::string s =
        LeavesThePool(plan.trials[i], truth, campaign.trials[i], *pool, o.campaign.command_rate_hz);
    if (!s.empty()) outside.push_back(std::move(s));
  }
  for (const std::string& s : outside) out << "NOT IN THE POOL: " << s << "\n";
  if (!o.json.empty()) {
    nlohmann::json j = io::SimulationJson(campaign, designs, campaign_path, o.campaign.seed,
                                          truth.integration_step_s);
    if (pool) j["outside_pool"] = outside;  // one sentence per trial that leaves it
    WriteJson(o.json, j);
  }
  return outside.empty() ? kExitOk : kExitActionNeeded;
}

void BindSimulate(CLI::App* sub, SimulateFlags* o) {
  sub->add_option("--truth", o->truth, "truth file: a vehicle plus dofs.<dof>.params")->required();
  sub->add_option("--plan", o->plan,
                  "plan JSON: a `schedule --json` result (also `--model coupled`), or a `next "
                  "--json` result (its trial)")
      ->required();
  sub->add_option("--out", o->out, "campaign directory to create (must be new or empty)")
      ->required();
  sub->add_option("--pool", o->pool,
                  "pool file (YAML): every trial of the truth checked against its free volume "
                  "(exit 1 if one leaves it; the campaign is written all the same)");
  sub->add_option("--seed", o->campaign.seed, "seed of the sensor noise, drop-outs and outliers")
      ->capture_default_str();
  sub->add_option("--step", o->step_s,
                  "RK4 integration step in s (default: the truth's virtual_pool.step, else 0.01)");
  AddJsonOption(sub, &o->json, "also write a summary", /*check_now=*/false);
}

const CommandRegistration kSimulateRegistration(MakeCommand<SimulateFlags>(
    "simulate", 30,
    "Run a plan on the virtual vehicle of a truth file and write the campaign (campaign.yaml, "
    "vehicle.yaml, trials/<id>.csv) as a pool team would log it.",
    BindSimulate, RunSimulate));

}  // namespace
}  // namespace uuvplan::cli
