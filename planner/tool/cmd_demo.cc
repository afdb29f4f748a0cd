// `uuvplan demo [--cases DIR] [--out DIR] [--seed N]`: the built-in ROMEO story, no files
// needed. For now (until the identification and planning commands land) it runs the heave
// campaign of seed 000 §IV-D on the virtual pool: five trials, one per ballast step (a diver's
// lead of about 0.7 kg in water added each time), each a series of up and down steady legs in
// the vertical-all mapping as in Fig. 4, and writes the campaign for `uuvplan identify`.
#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "command.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/io.h"
#include "uuvplan/model/virtual_pool.h"
#include "uuvplan/planner/schedule.h"

namespace uuvplan::tool {
namespace {

namespace fs = std::filesystem;
using model::InputError;

struct DemoOptions {
  std::string cases = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo";
  std::string out;  ///< empty: a new directory under the system's temporary directory
  std::uint64_t seed = 1;
};

// Nominal heave force of each leg (N, z down: positive pushes ROMEO down, where the vertical
// thrusters work in open water; negative pulls it up, where eta = 0.56, Table II). Three
// levels each way, alternating down and up. Pulling up is weaker (eta), so each trial ends
// 13-23 m deeper than it starts: like seed 000's heave trials it runs under the Antarctic ice,
// not in a pool (cases/romeo/pool.yaml leaves 2 m for heave). The
// largest, 180 N, is 45 N per thruster (6.6 V), well inside the +-10 V range; the smallest,
// 60 N, keeps 15 N per thruster, far from the thrust inversion (min_thrust 2 N).
constexpr double kLegForces[] = {60, -60, 120, -120, 180, -180};
// Each leg lasts 20 s: the slowest linearised time constant m/(k + 2·kq·|w|) of the truth is
// 720/(44.7 + 2·430.3·0.16) = 3.9 s (the slowest leg: ballast 4 pulling up, 18.7 N net, at
// 0.16 m/s), so every leg ends in steady state (seed 000 §III-A needs the regime velocity).
constexpr double kLegS = 20.0;
constexpr int kBallastSteps = 5;  // experiments 0-4 of seed 000 §IV-D
constexpr const char* kMapping = "vertical-all";

std::vector<planner::PlannedTrial> HeavePlan() {
  std::vector<planner::PlannedTrial> plan;
  for (int i = 0; i < kBallastSteps; ++i) {
    planner::PlannedTrial t;
    t.design.id = "heave_ballast_" + std::to_string(i);
    t.design.dof = model::Dof::kHeave;
    t.design.kind = model::TrialKind::kSegments;
    t.design.mapping = kMapping;
    t.design.ballast_steps = i;
    for (double f : kLegForces) {
      t.design.segments.push_back({f, kLegS, ""});
      t.design.duration += kLegS;
    }
    plan.push_back(t);
  }
  return plan;
}

std::string MakeTempDir() {
  std::string pattern = (fs::temp_directory_path() / "uuvplan-demo-XXXXXX").string();
  if (mkdtemp(pattern.data()) == nullptr) {
    throw InputError(pattern, "cannot create a temporary directory for the demo; give --out DIR");
  }
  return pattern;
}

std::size_t CountSamples(const std::vector<double>& column) {
  std::size_t n = 0;
  for (double x : column) n += std::isnan(x) ? 0 : 1;
  return n;
}

int RunDemo(const DemoOptions& o) {
  const std::string truth_path = (fs::path(o.cases) / "truth.yaml").string();
  const model::Truth truth = model::ReadTruth(truth_path);
  if (truth.vehicle.MappingIndex(kMapping) < 0 || truth.dofs.count(model::Dof::kHeave) == 0) {
    throw InputError(truth_path, "the demo needs ROMEO's heave truth (dofs.heave.params) and its "
                                 "'vertical-all' mapping; give --cases the cases/romeo folder");
  }
  const std::string out = o.out.empty() ? MakeTempDir() : o.out;
  const std::vector<planner::PlannedTrial> plan = HeavePlan();

  std::cout << "uuvplan demo: ROMEO (seed 000), the heave campaign of §IV-D on the virtual pool\n\n"
            << "Truth: " << truth_path << "\n  heave:";
  for (const auto& [name, value] : truth.dofs.at(model::Dof::kHeave).params) {
    std::cout << " " << name << " = " << value;
  }
  std::cout << "\n  (m·dw/dt = -k·w - kq·w|w| + eta·phi + bias + i·bias_step, z down; the "
               "numbers identification must recover)\n\n"
            << "Plan (built in, seed 000 Fig. 4): " << kBallastSteps << " trials in mapping '"
            << kMapping << "', trial i with i ballast steps;\n  each " << std::size(kLegForces)
            << " steady legs of " << kLegS << " s with nominal heave force";
  for (double f : kLegForces) std::cout << " " << std::showpos << f << std::noshowpos;
  std::cout << " N (+ = down);\n  in open water, as seed 000's under-ice heave trials: the legs "
               "go deeper than a pool allows\n\n";

  std::vector<model::TrialDesign> designs;
  for (const auto& t : plan) designs.push_back(t.design);
  model::VirtualPoolOptions pool_options;
  pool_options.seed = o.seed;
  const model::Campaign campaign = model::SimulateCampaign(truth, designs, out, pool_options);

  // The plan beside the campaign, readable by `uuvplan simulate --plan`. Only what was decided
  // here is written: travel, thrust_min and predicted precision are the planner's to compute.
  nlohmann::json trials = nlohmann::json::array();
  for (const auto& t : plan) {
    nlohmann::json j = planner::TrialToJson(t);
    j.erase("travel");
    j.erase("thrust_min");
    trials.push_back(j);
  }
  const std::string plan_path = (fs::path(out) / "plan.json").string();
  model::WriteFileAtomically(
      plan_path, nlohmann::json{{"trials", trials},
                                {"note", "built by `uuvplan demo` (seed 000 §IV-D, Fig. 4); no "
                                         "travel, thrust_min or predicted precision: those come "
                                         "from `uuvplan schedule`"}}
                         .dump(2) + "\n");

  std::cout << std::left << std::setw(18) << "trial" << std::right << std::setw(8) << "ballast"
            << std::setw(10) << "duration" << std::setw(8) << "rows" << std::setw(14)
            << "depth samples" << "  file\n";
  std::size_t rows = 0;
  for (std::size_t i = 0; i < campaign.trials.size(); ++i) {
    const auto& e = campaign.trials[i];
    const auto& depth = e.log.position[model::Index(model::Dof::kHeave)];
    const std::size_t samples = CountSamples(depth);
    rows += e.log.size();
    std::cout << std::left << std::setw(18) << designs[i].id << std::right << std::setw(8)
              << e.ballast_steps << std::setw(8) << designs[i].duration << " s" << std::setw(8)
              << e.log.size() << std::setw(14) << samples << "  " << e.file << "\n";
  }
  std::cout << "\nWrote " << campaign.trials.size() << " trials (" << rows << " rows) to " << out
            << ":\n  campaign.yaml, vehicle.yaml, trials/*.csv, plan.json\n"
            << "  re-run the same campaign: uuvplan simulate --truth " << truth_path
            << " --plan " << plan_path << " --out NEW_DIR --seed " << o.seed << "\n\n"
            << "Not in this demo yet: identifying the heave model from this campaign (drag, "
               "weight, ballast step and eta with their sigma, seed 000 Table II), planning the "
               "trials, and diagnosing what the model misses. They arrive with the identify, "
               "schedule, next, loop and diagnose commands; this demo will then tell the whole "
               "story. No estimate is shown here because none has been computed.\n";
  return kExitOk;
}

const CommandRegistration kRegistration({"demo", 80, [](CLI::App& app,
                                                        std::function<int()>* run) {
  auto o = std::make_shared<DemoOptions>();
  CLI::App* sub = app.add_subcommand(
      "demo", "The story on the built-in ROMEO case, no files needed: for now, the heave "
              "campaign of seed 000 simulated on the virtual pool.");
  sub->add_option("--cases", o->cases, "folder with ROMEO's truth.yaml")->capture_default_str();
  sub->add_option("--out", o->out,
                  "campaign directory to create (must be new or empty; default: a new "
                  "temporary directory)");
  sub->add_option("--seed", o->seed, "seed of the virtual pool's noise")->capture_default_str();
  sub->callback([o, run] { *run = [o] { return RunDemo(*o); }; });
}});

}  // namespace
}  // namespace uuvplan::tool
