// `uuvplan demo [--cases DIR] [--out DIR] [--seed N]`: the built-in ROMEO story, no files
// needed (issue #5 §3):
//  1. the a priori surge schedule in ROMEO's pool and its pool check (planner);
//  2. the design–identify loop on the virtual ROMEO until 5% percentile error (planner + ident);
//  3. the heave campaign of seed 000 §IV-D (five ballast steps, up and down steady legs in
//     vertical-all, Fig. 4) on a vehicle with the paper's propeller–hull interaction
//     (eta = 0.56 pulling up): the standard model's error, the cause named, the gain (diagnose).
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <memory>
#include <sstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "command.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/io.h"
#include "uuvplan/model/virtual_pool.h"
#include "diagnosis_json.h"
#include "uuvplan/ident/diagnosis.h"
#include "uuvplan/planner/design_loop.h"
#include "uuvplan/planner/pool_check.h"
#include "uuvplan/planner/schedule.h"
#include "uuvplan/planner/schedule_planner.h"

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

// "v ± s" with s to two significant digits and v to the same decimals.
std::string WithSigma(double v, double s) {
  const int decimals =
      s > 0 && std::isfinite(s) ? std::clamp(1 - static_cast<int>(std::floor(std::log10(s))), 0, 6) : 3;
  std::ostringstream out;
  out << std::fixed << std::setprecision(decimals) << v << " ± " << s;
  return out.str();
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
    throw InputError(truth_path,
                     "the demo needs ROMEO's heave truth (dofs.heave.params) and its "
                     "'vertical-all' mapping; give --cases the cases/romeo folder");
  }
  // "dir/" and "dir" are the same directory; SimulateCampaign builds its temporary sibling by
  // appending to the name, so the name must not end with a separator.
  fs::path out_path = fs::path(o.out.empty() ? MakeTempDir() : o.out).lexically_normal();
  if (out_path.filename().empty() && out_path.has_parent_path()) out_path = out_path.parent_path();
  const std::string out = out_path.string();
  const std::vector<planner::PlannedTrial> plan = HeavePlan();

  std::cout << "uuvplan demo: ROMEO (seed 000), 450 kg open-frame ROV\n\n";
  const std::string pool_path = (fs::path(o.cases) / "pool.yaml").string();
  const model::Pool pool = model::ReadPool(pool_path);
  std::cout << std::fixed << std::setprecision(3);

  // 1. The a priori schedule for surge and whether the pool hosts it.
  planner::ScheduleOptions so;
  so.dofs = {model::Dof::kSurge};
  const planner::ScheduleResult schedule = planner::PlanSchedule(truth.vehicle, pool, so);
  std::cout << "1. A priori surge schedule in pool '" << pool.name << "' ("
            << pool.Available(model::Dof::kSurge) << " m free), robust over m in ["
            << truth.vehicle.InertiaBounds(model::Dof::kSurge)[0] << ", "
            << truth.vehicle.InertiaBounds(model::Dof::kSurge)[1] << "] kg:\n";
  for (const auto& t : schedule.schedule.trials) {
    const auto& d = t.design;
    std::cout << "   " << std::left << std::setw(14) << d.id << std::right << std::setw(9)
              << model::TrialKindName(d.kind) << "  " << std::setw(6) << std::setprecision(1)
              << d.duration << " s  mapping " << d.mapping << "  travel [" << t.travel[0] << ", "
              << t.travel[1] << "] m\n";
  }
  for (const auto& [dof, pred] : schedule.schedule.predicted) {
    std::cout << "   predicted sigma (whole schedule, a priori):\n";
    std::string line;  // three columns of 38 characters, no trailing blanks
    int column = 0;
    for (const auto& [name, sigma] : pred.sigma) {
      std::ostringstream item;
      item << name << " " << std::setprecision(2) << std::defaultfloat << sigma;
      line += item.str();
      if (++column % 3 == 0 || column == static_cast<int>(pred.sigma.size())) {
        std::cout << "     " << line << "\n";
        line.clear();
      } else {
        line.resize(std::max<std::size_t>(line.size() + 1, 38 * (column % 3)), ' ');
      }
    }
    std::cout << std::fixed;
  }
  const planner::PoolCheckResult check =
      planner::CheckPool(truth.vehicle, pool, schedule.schedule, planner::PoolCheckOptions{});
  std::cout << "   pool check: " << (check.feasible ? "the pool hosts every trial" : "NOT feasible")
            << " (needs length " << std::setprecision(1) << check.required_length << " m)\n\n";

  // 2. The design–identify loop on the virtual ROMEO.
  planner::LoopOptions lo;
  lo.seed = o.seed;
  lo.budget = 12;
  lo.step.dofs = {model::Dof::kSurge};
  std::cout << "2. Design -> run (virtual pool) -> identify -> re-plan, surge, until every "
               "parameter of interest is below 5%:\n";
  const planner::LoopResult loop = planner::RunLoop(
      truth, pool, lo, [](const planner::LoopIteration& it) {
        std::cout << "   trial " << std::setw(2) << it.index + 1 << " (" << it.source << ")";
        for (const auto& p : it.progress) {
          std::cout << "  worst " << p.worst << " " << std::setprecision(1) << p.worst_percent << "%";
        }
        std::cout << "  pool time " << std::setprecision(0) << it.pool_time << " s\n";
      });
  std::cout << "   " << (loop.converged ? "converged" : "did not converge") << " after "
            << loop.iterations.size() << " trials, " << std::setprecision(0) << loop.pool_time
            << " s of pool time\n";
  for (const auto& p : loop.progress) {
    for (const auto& ip : p.interest) {
      const auto& tp = truth.dofs.at(p.dof).params;
      std::cout << "   " << std::left << std::setw(30) << ip.name << std::right << std::setprecision(3)
                << ip.value << " ± " << ip.sigma << "  (" << std::setprecision(1) << ip.percent
                << "%)  truth " << std::setprecision(3)
                << (tp.count(ip.name) ? tp.at(ip.name) : std::nan("")) << "\n";
    }
  }
  std::cout << std::setprecision(3) << "\n3. Diagnosis: the heave campaign of seed 000 §IV-D on the virtual pool\n"
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
                                {"note",
                                 "built by `uuvplan demo` (seed 000 §IV-D, Fig. 4); no "
                                 "travel, thrust_min or predicted precision: those come "
                                 "from `uuvplan schedule`"}}
                         .dump(2) +
                     "\n");

  std::cout << std::left << std::setw(18) << "trial" << std::right << std::setw(8) << "ballast"
            << std::setw(10) << "duration" << std::setw(8) << "rows" << std::setw(14)
            << "depth samples"
            << "  file\n";
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
            << " (campaign.yaml, vehicle.yaml, trials/*.csv, plan.json)\n\n";

  const ident::DiagnosisResult diagnosis = ident::Diagnose(campaign, ident::DiagnoseOptions{});
  std::cout << "The standard model (all eta = 1) fitted to it, as seed 000 Fig. 6 warns, "
               "absorbs the weaker upward thrust into the weight:\n";
  if (const auto* d = diagnosis.nominal.Find(model::Dof::kHeave)) {
    for (const auto& p : d->params) {
      std::cout << "   " << std::left << std::setw(10) << p.name << std::right
                << WithSigma(p.value, p.sigma) << "\n";
    }
  }
  std::cout << "Findings:\n";
  if (diagnosis.findings.empty()) std::cout << "   none\n";
  for (const auto& f : diagnosis.findings) {
    std::cout << "   " << f.effect << " (" << model::DofName(f.dof)
              << "): " << f.what << "\n";
    for (const auto& p : f.params) {
      std::cout << "     " << p.name << " = " << WithSigma(p.value, p.sigma)
                << "  (truth 0.56; paper, Table II: 0.56 ± 0.023)\n";
    }
    std::cout << "     free-run velocity MAE " << std::setprecision(4) << f.gain.before << " -> "
              << f.gain.after << " m/s (" << std::setprecision(0) << 100 * f.gain.relative
              << "% better, " << f.gain.on << ")\n";
  }
  std::cout << "\nMore: uuvplan diagnose " << out << "/campaign.yaml  (full report)\n";
  return kExitOk;
}

const CommandRegistration kRegistration(
    {"demo", 80, [](CLI::App& app, std::function<int()>* run) {
       auto o = std::make_shared<DemoOptions>();
       CLI::App* sub = app.add_subcommand(
           "demo",
           "The whole story on the built-in ROMEO case, no files needed: the a priori schedule "
           "and pool check, the design-identify loop converging, and a diagnosis of the paper's "
           "propeller-hull interaction (eta = 0.56 upward).");
       sub->add_option("--cases", o->cases, "folder with ROMEO's truth.yaml")
           ->capture_default_str();
       sub->add_option("--out", o->out,
                       "campaign directory to create (must be new or empty; default: a new "
                       "temporary directory)");
       sub->add_option("--seed", o->seed, "seed of the virtual pool's noise")
           ->capture_default_str();
       sub->callback([o, run] { *run = [o] { return RunDemo(*o); }; });
     }});

}  // namespace
}  // namespace uuvplan::tool
