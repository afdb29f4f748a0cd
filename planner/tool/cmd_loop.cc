// `uuvplan loop --truth TRUTH.yaml --pool POOL [--target PCT] [--budget N] [--seed N]
// [--dof D]... [--json F] [--verbose]`: the design–identify loop against the virtual vehicle
// of a truth file (planner/design_loop.h, docs/loop.md): plan the most informative next trial,
// run it on the virtual vehicle, identify from every trial so far, and repeat until every
// parameter of interest (m; kq where significant, else k; every η) has a percentile error
// below the target, or the trial budget is spent. Prints each iteration (trial planned,
// estimates, σ, pool time) and the total pool time. Deterministic for a given seed.
// Exit status: 0 converged; 1 not converged within the budget, or a DOF cannot be given the
// trial it needs in this pool; 2 bad input.
#include <CLI/CLI.hpp>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "command.h"
#include "identify_table.h"
#include "uuvplan/io/identify_json.h"
#include "loop_report.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/planner/design_loop.h"

namespace uuvplan::tool {
namespace {

using model::InputError;

std::string Str(double v) {
  std::ostringstream s;
  s << v;
  return s.str();
}
using nlohmann::json;

struct LoopCliOptions {
  std::string truth;
  std::string pool;
  std::vector<std::string> dofs;
  double target = 5.0;
  int budget = planner::LoopOptions{}.budget;
  std::uint64_t seed = 1;
  std::string json;
  bool verbose = false;
};

json Num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

std::string Short(double v, int precision) {
  std::ostringstream s;
  s << std::setprecision(precision) << v;
  return s.str();
}

void PrintIteration(const planner::LoopIteration& it, double target, bool verbose,
                    std::ostream& out) {
  const auto& d = it.trial.design;
  out << "#" << std::left << std::setw(3) << it.index + 1 << std::setw(6) << model::DofName(d.dof)
      << std::setw(20) << d.id << TrialLine(d) << "\n     " << it.source << "; pool time "
      << std::fixed << std::setprecision(0) << it.pool_time << " s" << std::defaultfloat << "\n";
  for (const auto& p : it.progress) {
    if (p.dof != it.dof) continue;
    out << "     ";
    for (const auto& q : p.interest) {
      out << " " << q.name << " ";
      if (q.estimated) {
        out << Short(q.value, 5) << "±" << Short(q.sigma, 2) << " (" << std::fixed
            << std::setprecision(q.percent < 10 ? 2 : 1) << q.percent << "%"
            << (q.percent <= target ? "" : "*") << ")" << std::defaultfloat;
      } else {
        out << "—";
      }
    }
    out << "\n";
  }
  if (verbose) {
    for (const auto& n : it.notes) out << "     note: " << n << "\n";
  }
  out.flush();
}

json IterationJson(const planner::LoopIteration& it) {
  json params = json::object();
  for (const auto& [dof, estimates] : it.params) {
    json p = json::object();
    for (const auto& e : estimates) p[e.name] = {{"value", Num(e.value)}, {"sigma", Num(e.sigma)}};
    params[std::string(model::DofName(dof))] = p;
  }
  return {{"trial", io::TrialToJson(it.trial)},
          {"params", params},
          {"dof", std::string(model::DofName(it.dof))},
          {"source", it.source},
          {"start", it.start},
          {"pool_time", it.pool_time},
          {"predicted", PredictedJson(it.dof, it.predicted)},
          {"progress", ProgressJson(it.progress)},
          {"notes", it.notes}};
}

int RunLoopCommand(const LoopCliOptions& o) {
  if (!(o.target > 0) || !std::isfinite(o.target)) {
    throw InputError("--target", "expected a percentile error > 0 (%), got " + Str(o.target));
  }
  if (o.budget < 1) {
    throw InputError("--budget",
                     "expected a number of trials >= 1, got " + std::to_string(o.budget));
  }
  const model::Truth truth = io::ReadTruth(o.truth);
  const model::Pool pool = io::ReadPool(o.pool);
  planner::LoopOptions lo;
  lo.step.target_percent = o.target;
  lo.budget = o.budget;
  lo.seed = o.seed;
  for (const auto& n : o.dofs) {
    const auto d = model::ParseDof(n);
    if (!d) throw InputError("--dof " + n, "expected surge, sway, heave, roll, pitch or yaw");
    if (!truth.dofs.count(*d)) {
      throw InputError(o.truth, "missing dofs." + n + ".params: --dof " + n + " needs the true " +
                                    n + " parameters to simulate");
    }
    lo.step.dofs.push_back(*d);
  }

  std::ostream& out = o.json == "-" ? std::cerr : std::cout;
  out << "Design–identify loop on the virtual '" << truth.vehicle.name << "' of " << o.truth
      << " in pool " << pool.name << " (target " << o.target << "%, budget " << o.budget
      << " trials, seed " << o.seed << ")\n"
      << "Parameters of interest: m; kq where significant, else k; every η "
         "(* = above the target)\n\n";
  const planner::LoopResult r = planner::RunLoop(
      truth, pool, lo,
      [&](const planner::LoopIteration& it) { PrintIteration(it, o.target, o.verbose, out); });

  out << "\n"
      << (r.converged ? "Converged" : "NOT converged") << " after " << r.iterations.size()
      << " trial(s): " << r.message << "\n"
      << "Pool time: " << std::fixed << std::setprecision(0) << r.pool_time << " s ("
      << std::setprecision(1) << r.pool_time / 60.0 << " min, " << lo.step.schedule.planner.pause_s
      << " s pauses between trials included)";
  for (const auto& [dof, t] : r.dof_pool_time) {
    out << std::setprecision(0) << "; " << model::DofName(dof) << " " << t << " s";
  }
  out << std::defaultfloat << "\n\nFinal estimates against the truth:\n";
  PrintProgress(r.progress, o.target, out, &truth);

  if (!o.json.empty()) {
    json iterations = json::array();
    for (const auto& it : r.iterations) iterations.push_back(IterationJson(it));
    json dof_time = json::object();
    for (const auto& [dof, t] : r.dof_pool_time) dof_time[std::string(model::DofName(dof))] = t;
    const json j = {{"iterations", iterations},
                    {"converged", r.converged},
                    {"pool_time", r.pool_time},
                    {"status", std::string(planner::LoopStatusName(r.status))},
                    {"message", r.message},
                    {"target", o.target},
                    {"budget", o.budget},
                    {"seed", o.seed},
                    {"dof_pool_time", dof_time},
                    {"progress", ProgressJson(r.progress)},
                    {"estimates", io::IdentifyJson(r.estimates)}};
    WriteJson(o.json, j);
  }
  return r.converged ? kExitOk : kExitActionNeeded;
}

const CommandRegistration kRegistration(
    {"loop", 46, [](CLI::App& app, std::function<int()>* run) {
       auto o = std::make_shared<LoopCliOptions>();
       CLI::App* sub = app.add_subcommand(
           "loop",
           "Design → run (virtual) → identify → re-plan until every parameter of interest's "
           "percentile error is below the target, or the trial budget is spent.");
       sub->add_option("--truth", o->truth, "truth file: a vehicle plus dofs.<dof>.params")
           ->required();
       sub->add_option("--pool", o->pool, "pool.yaml")->required();
       sub->add_option("--target", o->target,
                       "percentile error 100·σ/|θ| (%) every parameter of interest must reach")
           ->capture_default_str();
       sub->add_option("--budget", o->budget, "most trials to run")->capture_default_str();
       sub->add_option("--seed", o->seed,
                       "seed of the virtual pool (trial i draws from its own stream, as "
                       "`simulate`)")
           ->capture_default_str();
       sub->add_option("--dof", o->dofs,
                       "DOF to identify (repeatable; default: every DOF the truth has "
                       "parameters for)");
       sub->add_option("--json", o->json,
                       "also write the result as JSON to this file ('-' = stdout)");
       sub->add_flag("--verbose", o->verbose,
                     "print each iteration's design and identification notes");
       sub->callback([o, run] { *run = [o] { return RunLoopCommand(*o); }; });
     }});

}  // namespace
}  // namespace uuvplan::tool
