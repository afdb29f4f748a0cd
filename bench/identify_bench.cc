// Benchmark of `identify` (ident/identify.h) on a 1,000,000-sample trial, CSV read included.
//
//   identify_bench [--rows N] [--rate HZ]
//       time ReadCampaign + Identify on a trial of N rows (default 1,000,000) of a gyro at HZ
//       (default 500: a 2000 s trial); target: under 1 s (docs/performance.md).
//
// The full-size Monte Carlo of the uncertainties is tests/validation/identify_validation.cc
// (docs/validation.md).
//
// The timed trial: the VSOR-like yaw of cases/vsor driven by a PRBS of torque legs plus a sine,
// for 2000 s, logged with the yaw-rate gyro at 500 Hz (1,000,000 rows) and the compass at
// 13 Hz, commands held at 20 Hz — a long, high-rate log of the kind an IMU produces. The file
// is written once to a temporary directory (not timed), then read and identified five times;
// the best time is reported with the stages. Exit status 1 when the 1 s target is missed.
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <filesystem>
#include <iostream>
#include <random>
#include <string>

#include "ident/ident_cases.h"  // CaseTruth, Segments, Sine: the test cases' builders
#include "uuvplan/ident/identify.h"
#include "uuvplan/ident/stats/monte_carlo.h"  // TrueParameter
#include "uuvplan/io/io.h"
#include "uuvplan/io/virtual_campaign.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/virtual_pool.h"

namespace {

using namespace uuvplan;
using Clock = std::chrono::steady_clock;
using ident::testing::CaseTruth;
using ident::testing::Segments;
using ident::testing::Sine;

double Seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

// Legs of random duration in [lo, hi] s and random level in ±[a_lo, a_hi], alternating sign.
std::vector<std::pair<double, double>> RandomLegs(int n, double a_lo, double a_hi, double lo,
                                                  double hi, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> dur(lo, hi), amp(a_lo, a_hi);
  std::vector<std::pair<double, double>> legs;
  for (int i = 0; i < n; ++i) legs.push_back({(i % 2 == 0 ? 1.0 : -1.0) * amp(rng), dur(rng)});
  return legs;
}

int TimeIdentify(long rows, double rate) {
  model::Truth truth = CaseTruth("vsor");
  const double duration = rows / rate;
  truth.vehicle.sensors[model::Dof::kYaw].velocity = model::SensorSpec{rate, 0.001};
  // Legs of 5–15 s, then a sine for the rest.
  auto legs = RandomLegs(1000, 15, 80, 5, 15, 3);
  double t = 0.0;
  std::vector<std::pair<double, double>> used;
  for (const auto& l : legs) {
    if (t + l.second > 0.5 * duration) break;
    used.push_back(l);
    t += l.second;
  }
  model::TrialDesign d = Segments("yaw_long", model::Dof::kYaw, "yaw-ht1-ht7", used);
  const model::TrialDesign s =
      Sine("yaw_sine", model::Dof::kYaw, "yaw-ht1-ht7", 45, 30, 20, duration - t);
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("uuvplan_identify_bench_" + std::to_string(::getpid()));
  std::filesystem::remove_all(dir);
  model::VirtualCampaignOptions vo;
  vo.seed = 5;
  const auto t0 = Clock::now();
  // One long trial: the PRBS legs then the sine, as segments sampled finely enough (0.05 s).
  model::TrialDesign all = d;
  const double dt = 0.05;
  for (double x = 0.0; x < s.duration; x += dt) {
    all.segments.push_back({s.offset + s.amplitude * std::sin(s.omega * x), dt, ""});
    all.duration += dt;
  }
  io::SimulateCampaign(truth, {all}, dir.string(), vo);
  const auto t1 = Clock::now();
  const std::string campaign_path = (dir / "campaign.yaml").string();
  std::printf("identify_bench: wrote %s (%.1f s of trial) in %.1f s\n", campaign_path.c_str(),
              all.duration, Seconds(t0, t1));
  // Wall time is the target; the process CPU time (std::clock) is printed beside it because on
  // a shared machine the wall time includes waiting for a core.
  double best = 1e9, best_read = 0.0, best_cpu = 1e9;
  ident::IdentifyResult result;
  std::size_t n_rows = 0;
  for (int run = 0; run < 5; ++run) {
    const std::clock_t cpu0 = std::clock();
    const auto a = Clock::now();
    const model::Campaign c = io::ReadCampaign(campaign_path);
    const auto b = Clock::now();
    result = ident::Identify(c, ident::IdentifyOptions{});
    const auto e = Clock::now();
    best_cpu = std::min(best_cpu, static_cast<double>(std::clock() - cpu0) / CLOCKS_PER_SEC);
    n_rows = c.trials[0].log.size();
    if (Seconds(a, e) < best) {
      best = Seconds(a, e);
      best_read = Seconds(a, b);
    }
  }
  {
    const model::Campaign c = io::ReadCampaign(campaign_path);
    const auto a = Clock::now();
    const ident::TrialData d =
        ident::PrepareTrial(c.trials[0], 0, c.vehicle, ident::TrialDataOptions{});
    std::printf("  (PrepareTrial alone: %.3f s)\n", Seconds(a, Clock::now()));
  }
  std::filesystem::remove_all(dir);
  const ident::DofIdentification& y = result.dofs.at(0);
  std::printf(
      "rows %zu: best of 5: %.3f s wall (CSV read %.3f s, identify %.3f s), %.3f s CPU; "
      "estimator %s\n",
      n_rows, best, best_read, best - best_read, best_cpu,
      std::string(ident::FinalEstimatorName(y.estimator)).c_str());
  for (const auto& [stage, sec] : y.timing)
    std::printf("  stage %-22s %.3f s\n", stage.c_str(), sec);
  for (const auto& n : y.notes) std::printf("  note: %s\n", n.c_str());
  for (const auto& n : y.warnings) std::printf("  warning: %s\n", n.c_str());
  if (y.output_error) std::printf("  %s\n", y.output_error->message.c_str());
  if (y.steady) std::printf("  steady: %s\n", y.steady->message.c_str());
  if (y.inertia) std::printf("  integral: %s\n", y.inertia->message.c_str());
  if (y.one_step) {
    std::printf("  one-step: %s:", y.one_step->message.c_str());
    for (const auto& e : y.one_step->estimates) std::printf(" %s=%.5g", e.name.c_str(), e.value);
    std::printf("\n");
  }
  for (const auto& p : y.params) {
    std::printf("  %-22s %12.6g ± %-10.3g (truth %g)\n", p.name.c_str(), p.value, p.sigma,
                ident::TrueParameter(truth, model::Dof::kYaw, p.name));
  }
  const bool ok = best < 1.0;
  std::printf("target < 1 s: %s\n", ok ? "met" : "MISSED");
  return ok ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  long rows = 1000000;
  double rate = 500.0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--rows" && i + 1 < argc) {
      rows = std::atol(argv[++i]);
    } else if (a == "--rate" && i + 1 < argc) {
      rate = std::atof(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: identify_bench [--rows N] [--rate HZ]\n");
      return 2;
    }
  }
  try {
    return TimeIdentify(rows, rate);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "identify_bench: %s\n", e.what());
    return 2;
  }
}
