// Benchmark of the planner (docs/performance.md targets, single-threaded): a robust single-DOF sine
// design in under 200 ms and the whole ROMEO schedule in under 2 s. Reports the best of N runs in
// wall time and in process CPU time (CPU time is what the 2-core CI machine shares out; wall time
// on a loaded machine overstates it).
//
// Run: build/bench/planner_bench [repetitions] [--budgets]
//   --budgets  also prints the sine design's robust criterion against the solver budget
//              (DIRECT-L evaluations / COBYLA evaluations), the figures behind the defaults in
//              planner/design/dof_planning_problem.h.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <string>

#include "uuvplan/io/io.h"
#include "uuvplan/planner/design/sine_design.h"
#include "uuvplan/planner/schedule_planner.h"

using namespace uuvplan;
using namespace uuvplan::planner;

namespace {

struct Timing {
  double wall_ms = 1e300;
  double cpu_ms = 1e300;
};

template <typename F>
Timing Best(int reps, F&& f) {
  Timing t;
  for (int r = 0; r < reps; ++r) {
    const auto w0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    f();
    const std::clock_t c1 = std::clock();
    const auto w1 = std::chrono::steady_clock::now();
    t.wall_ms = std::min(t.wall_ms, std::chrono::duration<double, std::milli>(w1 - w0).count());
    t.cpu_ms = std::min(t.cpu_ms, 1000.0 * (c1 - c0) / CLOCKS_PER_SEC);
  }
  return t;
}

void Print(const char* what, const Timing& t, double target_ms) {
  std::printf("%-58s wall %8.1f ms  cpu %8.1f ms  (target < %.0f ms)\n", what, t.wall_ms, t.cpu_ms,
              target_ms);
}

}  // namespace

int main(int argc, char** argv) {
  int reps = 5;
  bool budgets = false;
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--budgets") == 0) {
      budgets = true;
    } else {
      reps = std::max(1, std::atoi(argv[i]));
    }
  }
  const std::string dir = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/";
  const model::Vehicle v = io::ReadVehicle(dir + "vehicle.yaml");
  const model::Pool pool = io::ReadPool(dir + "pool.yaml");
  std::printf("planner_bench: ROMEO (cases/romeo), pool %s, best of %d\n", pool.name.c_str(), reps);

  SineDesignResult sine;
  const Timing t_sine = Best(reps, [&] {
    const auto ctx =
        DofPlanningProblem::APriori(v, pool, model::Dof::kSurge, PlannerOptions{}, nullptr);
    sine = DesignSine(*ctx, SineDesignOptions{}, {}, "surge-sine");
  });
  Print("robust sine design, surge, 20 m, duration fitted to the pool", t_sine, 200);
  std::printf(
      "    %s; offset %.2f N, amplitude %.2f N, period %.1f s, %.1f s, maximin Ds(m) %.4f\n",
      sine.summary.BriefReport().c_str(), sine.trial.design.offset, sine.trial.design.amplitude,
      2 * M_PI / sine.trial.design.omega, sine.trial.design.duration, sine.criterion);

  SineDesignOptions fixed;
  fixed.fixed_duration_s = 52.0;
  const Timing t_fixed = Best(reps, [&] {
    const auto ctx =
        DofPlanningProblem::APriori(v, pool, model::Dof::kSurge, PlannerOptions{}, nullptr);
    sine = DesignSine(*ctx, fixed, {}, "surge-sine");
  });
  Print("robust sine design, surge, 20 m, 52 s (the seed's duration)", t_fixed, 200);

  const Timing t_yaw = Best(reps, [&] {
    const auto ctx =
        DofPlanningProblem::APriori(v, pool, model::Dof::kYaw, PlannerOptions{}, nullptr);
    sine = DesignSine(*ctx, SineDesignOptions{}, {}, "yaw-sine");
  });
  Print("robust sine design, yaw, 120 s at 10 Hz", t_yaw, 200);

  ScheduleResult whole;
  const Timing t_whole = Best(reps, [&] { whole = PlanSchedule(v, pool, ScheduleOptions{}); });
  Print("whole ROMEO schedule (surge, sway, heave, yaw)", t_whole, 2000);
  std::printf("    %s, %zu trials, pool time %.0f s\n",
              std::string(PlanStatusName(whole.status)).c_str(), whole.schedule.trials.size(),
              whole.schedule.pool_time);

  if (budgets) {
    std::printf(
        "\nsine design (surge, free duration): budget -> maximin Ds(m), evaluations, cpu\n");
    for (auto [g, l] :
         {std::pair{40, 20}, {80, 30}, {100, 30}, {150, 40}, {300, 100}, {600, 200}}) {
      PlannerOptions po;
      po.solver.max_global_evaluations = g;
      po.solver.max_local_evaluations = l;
      const Timing t = Best(1, [&] {
        const auto ctx = DofPlanningProblem::APriori(v, pool, model::Dof::kSurge, po, nullptr);
        sine = DesignSine(*ctx, SineDesignOptions{}, {}, "surge-sine");
      });
      std::printf("  DIRECT-L %4d + COBYLA 2x%4d: %.5f  (%d evaluations, %.0f ms cpu)\n", g, l,
                  sine.criterion, sine.summary.evaluations, t.cpu_ms);
    }
  }
  return 0;
}
