// Benchmark: simulate a 10-minute trial at 100 Hz with every force term and effect on
// (target: under 5 ms), and the same with forward sensitivities.
// The target case is the virtual pool's: commands held at the controller rate (20 Hz) and the
// coupling's yaw rate held from its 10 Hz log, as a real trial is run and logged. A continuous
// sine input and yaw rate (libm sin at every RK4 stage) is reported beside it.
// Run: build/bench/simulate_bench [repetitions] [state]
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <string>

#include "support/every_effect.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/simulator.h"

using namespace uuvplan::model;

namespace {
// Yaw rate held from 10 Hz samples of 0.2·sin(0.3·t).
class HeldYawRate final : public AuxVelocities {
 public:
  explicit HeldYawRate(double duration) {
    for (double t = 0; t <= duration + 1e-9; t += 0.1) r_.push_back(0.2 * std::sin(0.3 * t));
  }
  void At(double t, std::array<double, kNumDofs>* v) const override {
    const std::size_t i = std::min(r_.size() - 1, static_cast<std::size_t>(t * 10.0));
    (*v)[Index(Dof::kYaw)] = r_[i];
  }

 private:
  std::vector<double> r_;
};

class YawRate final : public AuxVelocities {
 public:
  void At(double t, std::array<double, kNumDofs>* v) const override {
    (*v)[Index(Dof::kYaw)] = 0.2 * std::sin(0.3 * t);
  }
};

template <typename F>
double BestMs(int reps, F&& f) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::milli>(t1 - t0).count());
  }
  return best;
}
}  // namespace

int main(int argc, char** argv) {
  const int reps = argc > 1 ? std::atoi(argv[1]) : 20;
  const bool state_only = argc > 2 && std::string(argv[2]) == "state";  // for profiling
  const Vehicle v = uuvplan::testing::FrontRearVehicle();
  // Every effect of the table on (docs/performance.md), coupled to the sway speed too.
  ModelStructure s = uuvplan::testing::EveryEffectStructure(60.0);
  s.parameters.push_back("coupling.vr");
  const DofModel model(v, s);
  std::map<std::string, double> named = uuvplan::testing::EveryEffectValues();
  named["coupling.vr"] = 100.0;
  const Eigen::VectorXd theta = model.Theta(named);
  const double duration = 600.0, rate = 100.0;
  const auto sine = MakeSineExcitation(35.0, 25.0, 2 * M_PI / 26, 0, duration);
  std::vector<double> cmd_t, cmd_f;
  for (int i = 0; i <= static_cast<int>(duration * 20); ++i) {
    cmd_t.push_back(i / 20.0);
    cmd_f.push_back(sine->Force(i / 20.0));
  }
  const auto held = MakeHeldExcitation(cmd_t, cmd_f, std::vector<int>(cmd_t.size(), 0), duration);
  const HeldYawRate held_aux(duration);
  const YawRate aux;
  const TrialConditions c{held.get(), 1, 0.0, &held_aux};
  const TrialConditions c_sine{sine.get(), 1, 0.0, &held_aux};
  std::vector<double> times;
  for (int i = 0; i <= static_cast<int>(duration * rate); ++i) times.push_back(i / rate);
  SimulationOptions o;
  o.step_s = 1.0 / rate;

  double sink = 0.0;
  const double ms =
      BestMs(reps, [&] { sink += SimulateMeasured(model, theta, c, times, o).x(100, 1); });
  if (state_only) {
    std::printf("simulate: held 20 Hz commands, state only  best of %d: %.2f ms\n", reps, ms);
    return sink == 12345.0;
  }
  const double ms_sine =
      BestMs(reps, [&] { sink += SimulateMeasured(model, theta, c_sine, times, o).x(100, 1); });
  // The thrust map's shape costs an exp and a log per input sample: once per breakpoint of a
  // held input, twice per step of a continuous one. The standard terms are all but that one.
  ModelStructure s2 = s;
  s2.Remove("thrust_exponent");
  const DofModel model2(v, s2);
  const Eigen::VectorXd theta2 = model2.Theta({}, &named);
  const double ms_sine2 =
      BestMs(reps, [&] { sink += SimulateMeasured(model2, theta2, c_sine, times, o).x(100, 1); });
  o.sensitivities = true;
  const double ms_s = BestMs(std::max(1, reps / 4), [&] {
    sink += SimulateMeasured(model, theta, c, times, o).x(100, 1);
  });
  std::printf(
      "simulate: 600 s at 100 Hz (60001 outputs, RK4 step 0.01 s), %d params, all terms on\n",
      model.num_parameters());
  std::printf("simulate: held 20 Hz commands, state only  best of %d: %.2f ms (target < 5 ms)\n",
              reps, ms);
  std::printf("simulate: continuous sine, state only      best of %d: %.2f ms\n", reps, ms_sine);
  std::printf("simulate: continuous sine, no thrust_map   best of %d: %.2f ms\n", reps, ms_sine2);
  std::printf("simulate: held commands + sensitivities   best of %d: %.2f ms\n",
              std::max(1, reps / 4), ms_s);
  return sink == 12345.0;  // keep the work observable
}
