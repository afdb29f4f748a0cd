// The full-size comparison of the design–identify loop (planner/loop/design_loop.h) against
// ref 000's own procedure (planner/design/paper_procedure.h) on the virtual ROMEO, same truth,
// pool, sensors, pauses and identification. Prints every loop iteration, the final percentile
// errors (and the true errors) of every parameter of interest for both, the pool times, and the
// wall time per loop iteration.
//
// Run: build/bench/loop_bench [--dof D]... [--seed N] [--budget N] [--target PCT]
//                             [--truth FILE] [--pool FILE] [--no-paper] [--no-loop]
//                             [--paper-ls] [--verbose]
// Default: cases/romeo/truth.yaml and pool.yaml, surge heave yaw, seed 1, budget 40, target 5.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "uuvplan/ident/stats/monte_carlo.h"
#include "uuvplan/io/io.h"
#include "uuvplan/planner/design/paper_procedure.h"
#include "uuvplan/planner/loop/design_loop.h"

using namespace uuvplan;
using planner::DofProgress;

namespace {

void PrintProgress(const char* who, const model::Truth& truth,
                   const std::vector<DofProgress>& progress,
                   const std::map<model::Dof, double>& dof_time) {
  for (const auto& p : progress) {
    const auto t = dof_time.find(p.dof);
    std::printf("  %-6s %-6s pool time %7.0f s, %2d trials, worst %s %.2f%%%s\n", who,
                std::string(model::DofName(p.dof)).c_str(), t == dof_time.end() ? 0.0 : t->second,
                p.trials, p.worst.c_str(), p.worst_percent, p.converged ? " (target met)" : "");
    for (const auto& q : p.interest) {
      const double truev = ident::TrueParameter(truth, p.dof, q.name);
      std::printf("      %-28s %10.4g ± %-9.3g %7.2f%%   true %-8.4g error %+.2f%% (%.1fσ)\n",
                  q.name.c_str(), q.value, q.sigma, q.percent, truev,
                  100.0 * (q.value - truev) / std::abs(truev), (q.value - truev) / q.sigma);
    }
  }
}

}  // namespace

int main(int argc, char** argv) {
  std::string truth_path = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/truth.yaml";
  std::string pool_path = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/pool.yaml";
  planner::LoopOptions lo;
  planner::PaperProcedureOptions po;
  bool run_paper = true, run_loop = true, verbose = false;
  std::vector<model::Dof> dofs;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) {
        std::fprintf(stderr, "%s needs a value\n", a.c_str());
        std::exit(2);
      }
      return argv[++i];
    };
    if (a == "--dof") {
      auto d = model::ParseDof(next());
      if (!d) {
        std::fprintf(stderr, "unknown DOF\n");
        return 2;
      }
      dofs.push_back(*d);
    } else if (a == "--seed") {
      lo.seed = po.seed = std::strtoull(next().c_str(), nullptr, 10);
    } else if (a == "--budget") {
      lo.budget = std::atoi(next().c_str());
    } else if (a == "--target") {
      lo.step.target_percent = po.progress.target_percent = std::atof(next().c_str());
    } else if (a == "--truth") {
      truth_path = next();
    } else if (a == "--pool") {
      pool_path = next();
    } else if (a == "--paper-ls") {
      po.identify.refine = false;
    } else if (a == "--verbose") {
      verbose = true;
    } else if (a == "--no-paper") {
      run_paper = false;
    } else if (a == "--no-loop") {
      run_loop = false;
    } else {
      std::fprintf(stderr, "unknown argument %s\n", a.c_str());
      return 2;
    }
  }
  if (dofs.empty()) dofs = {model::Dof::kSurge, model::Dof::kHeave, model::Dof::kYaw};
  lo.step.dofs = po.dofs = dofs;
  const model::Truth truth = io::ReadTruth(truth_path);
  const model::Pool pool = io::ReadPool(pool_path);

  double paper_time = 0.0, loop_time = 0.0;
  if (run_paper) {
    const auto t0 = std::chrono::steady_clock::now();
    const planner::PaperProcedureResult pr = planner::RunPaperProcedure(truth, pool, po);
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("Seed 000 procedure: %zu trials, pool time %.0f s (%.1f s wall)\n",
                pr.trials.size(), pr.pool_time, wall);
    for (std::size_t i = 0; i < pr.trials.size(); ++i) {
      const auto& d = pr.trials[i].design;
      // Excursion actually logged on the virtual vehicle (the a priori box's is wider).
      const auto& pos = pr.campaign.trials[i].log.position[model::Index(d.dof)];
      double lo = 0.0, hi = 0.0, p0 = NAN;
      for (double p : pos) {
        if (std::isnan(p)) continue;
        if (std::isnan(p0)) p0 = p;
        lo = std::min(lo, p - p0);
        hi = std::max(hi, p - p0);
      }
      std::printf("  %-28s %-8s %-22s %6.1f s  logged travel [%.2f, %.2f], box [%.2f, %.2f]%s\n",
                  d.id.c_str(), std::string(model::TrialKindName(d.kind)).c_str(),
                  d.mapping.c_str(), d.duration, lo, hi, pr.trials[i].travel[0],
                  pr.trials[i].travel[1],
                  pr.checks[i].feasible ? "" : "  (planner check: infeasible)");
      if (verbose) {
        for (const auto& reason : pr.checks[i].reasons) std::printf("      %s\n", reason.c_str());
      }
    }
    for (const auto& n : pr.notes) std::printf("  note: %s\n", n.c_str());
    for (const auto& d : pr.estimates.dofs) {
      for (const auto& w : d.warnings) {
        std::printf("  identify %s: %s\n", std::string(model::DofName(d.dof)).c_str(), w.c_str());
      }
    }
    PrintProgress("paper", truth, pr.progress, pr.dof_pool_time);
    paper_time = pr.pool_time;
  }
  if (run_loop) {
    const auto t0 = std::chrono::steady_clock::now();
    double worst_wall = 0.0;
    const planner::LoopResult lr =
        planner::RunLoop(truth, pool, lo, [&](const planner::LoopIteration& it) {
          worst_wall = std::max(worst_wall, it.wall_seconds);
          const auto& d = it.trial.design;
          std::printf("  #%-2d %-6s %-20s %-9s %-22s %6.1f s  pool %6.0f s  (%.1f s wall)\n",
                      it.index + 1, std::string(model::DofName(it.dof)).c_str(), d.id.c_str(),
                      std::string(model::TrialKindName(d.kind)).c_str(), d.mapping.c_str(),
                      d.duration, it.pool_time, it.wall_seconds);
          for (const auto& p : it.progress) {
            if (p.dof != it.dof) continue;
            std::printf("       ");
            for (const auto& q : p.interest) {
              std::printf(" %s %.4g±%.2g (%.1f%%)", q.name.c_str(), q.value, q.sigma, q.percent);
            }
            std::printf("\n");
          }
          if (verbose) {
            for (const auto& n : it.notes) std::printf("         note: %s\n", n.c_str());
          }
          std::fflush(stdout);
        });
    const double wall =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf(
        "Loop: %s after %zu trials, pool time %.0f s (%.1f s wall, worst iteration "
        "%.1f s)\n  %s\n",
        std::string(planner::LoopStatusName(lr.status)).c_str(), lr.iterations.size(), lr.pool_time,
        wall, worst_wall, lr.message.c_str());
    PrintProgress("loop", truth, lr.progress, lr.dof_pool_time);
    loop_time = lr.pool_time;
  }
  if (run_paper && run_loop) {
    std::printf("Pool time: loop %.0f s, seed 000 procedure %.0f s (loop/paper %.2f)\n", loop_time,
                paper_time, loop_time / paper_time);
  }
  return 0;
}
