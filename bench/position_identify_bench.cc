// Benchmark of `identify` on a long position-only surge trial: the case a new user
// tried, a sonar-like position sensor alone at 100 Hz (σ 1 cm), columns t, force_surge,
// pos_surge, truth m 900 kg, k 47 N·s/m, kq 306 N·s²/m², bias −2 N
// (bench/cases/position_surge_truth.yaml), run on uuvplan's virtual pool with seed 16.
//
//   position_identify_bench [--rows N]... [--repeat R]
//       writes each trial (default 10,000, 100,000 and 1,000,000 rows) to a temporary
//       directory (not timed), then times ReadCampaign + Identify (default options, as
//       `uuvplan identify`), best of R (default 3); prints the time per row, the scaling
//       exponent between sizes (time ∝ rows^p) and the estimates against the truth.
//   position_identify_bench --write DIR [--rows N]
//       writes the campaign only (for bench/position_identify.sh, which times the CLI against
//       bench/plain_identify.py on the same file).
//   --input legs|sine (either form; default legs) chooses the excitation:
//     legs: force legs alternating in sign, |level| 25, 50 or 75 N, each 10–40 s (seeded): the
//           logged force changes ~400 times in 1M rows;
//     sine: 60 N·sin(2π t/40 s), the logged force changes at every row (the planner's sine
//           trials as a 100 Hz logger records them),
// until the trial has N samples at 100 Hz. Exit status 1 when m is more than 3σ from
// 900 kg or the output error restarted from the a priori values (a poor least-squares start).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "uuvplan/ident/identify.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/virtual_campaign.h"
#include "uuvplan/model/trial_design.h"

namespace {

using namespace uuvplan;
using Clock = std::chrono::steady_clock;
namespace fs = std::filesystem;

constexpr double kRateHz = 100.0;
constexpr double kTrueM = 900.0;

double Seconds(Clock::time_point a, Clock::time_point b) {
  return std::chrono::duration<double>(b - a).count();
}

/// The bench's surge trial of `kind` in surge-front, before its input.
model::TrialDesign SurgeDesign(model::TrialKind kind) {
  model::TrialDesign d;
  d.id = "surge_position";
  d.dof = model::Dof::kSurge;
  d.kind = kind;
  d.mapping = "surge-front";
  return d;
}

/// Force legs of the trial: alternating sign, |level| 25, 50 or 75 N (a designed input takes
/// few levels; distinct random levels would read as a controller's, CommandRoughness), 10–40 s,
/// seeded, covering `duration` seconds.
model::TrialDesign LegDesign(double duration) {
  model::TrialDesign d = SurgeDesign(model::TrialKind::kSegments);
  std::mt19937_64 rng(16);
  std::uniform_int_distribution<int> level(1, 3);
  std::uniform_real_distribution<double> length(10.0, 40.0);
  for (int i = 0; d.duration < duration; ++i) {
    const double s = std::min(length(rng), duration - d.duration);
    d.segments.push_back({(i % 2 == 0 ? 25.0 : -25.0) * level(rng), s, ""});
    d.duration += s;
  }
  return d;
}

/// A sine about zero, 60 N, period 40 s (twice the truth's time constant m/k ≈ 19 s), covering
/// `duration` seconds: the force changes at every sample.
model::TrialDesign SineDesign(double duration) {
  model::TrialDesign d = SurgeDesign(model::TrialKind::kSine);
  d.amplitude = 60.0;
  d.omega = 2.0 * M_PI / 40.0;
  d.duration = duration;
  return d;
}

bool g_sine_input = false;  // --input sine

/// Writes the campaign of a trial of `rows` samples into `dir` (must be new or empty).
std::string WriteCase(long rows, const fs::path& dir) {
  const model::Truth truth =
      io::ReadTruth(std::string(UUVPLAN_SOURCE_DIR) + "/bench/cases/position_surge_truth.yaml");
  model::VirtualCampaignOptions vo;
  vo.seed = 16;
  if (g_sine_input) vo.command_rate_hz = kRateHz;  // a new force value at every sample
  // rows samples at 100 Hz span (rows − 1)/100 s; the last sample lands on the end.
  const double duration = (rows - 1) / kRateHz;
  io::SimulateCampaign(truth, {g_sine_input ? SineDesign(duration) : LegDesign(duration)},
                       dir.string(), vo);
  return (dir / "campaign.yaml").string();
}

struct Timed {
  long rows = 0;
  double best_s = 0.0;
  ident::IdentifyResult result;
};

Timed TimeSize(long rows, int repeat) {
  const fs::path dir =
      fs::temp_directory_path() /
      ("uuvplan_position_bench_" + std::to_string(::getpid()) + "_" + std::to_string(rows));
  fs::remove_all(dir);
  const std::string campaign = WriteCase(rows, dir);
  Timed t;
  t.best_s = 1e9;
  for (int r = 0; r < repeat; ++r) {
    const auto a = Clock::now();
    const model::Campaign c = io::ReadCampaign(campaign);
    ident::IdentifyResult result = ident::Identify(c, ident::IdentifyOptions{});
    const double s = Seconds(a, Clock::now());
    t.rows = static_cast<long>(c.trials.at(0).log.size());
    if (s < t.best_s) {
      t.best_s = s;
      t.result = std::move(result);
    }
  }
  fs::remove_all(dir);
  return t;
}

/// Prints the estimates of the largest size; false when m is off by more than 3σ or the output
/// error restarted from the a priori values.
bool ReportEstimates(const Timed& t) {
  const ident::DofIdentification& y = t.result.dofs.at(0);
  bool restarted = false;
  for (const auto& [stage, sec] : y.timing)
    std::printf("  stage %-22s %.3f s\n", stage.c_str(), sec);
  for (const auto& n : y.notes) {
    std::printf("  note: %s\n", n.c_str());
    restarted = restarted || n.find("restarted") != std::string::npos;
  }
  for (const auto& w : y.warnings) std::printf("  warning: %s\n", w.c_str());
  double m = 0.0, sm = 0.0;
  for (const auto& p : y.params) {
    std::printf("  %-6s %12.6g ± %.3g\n", p.name.c_str(), p.value, p.sigma);
    if (p.name == "m") m = p.value, sm = p.sigma;
  }
  const double z = sm > 0.0 ? std::abs(m - kTrueM) / sm : 1e9;
  std::printf("  m − 900 kg = %.3g σ (%s); output error %s\n", z, z <= 3.0 ? "within 3σ" : "OFF",
              restarted ? "RESTARTED from the a priori values" : "started from least squares");
  return z <= 3.0 && !restarted;
}

int Run(std::vector<long> sizes, int repeat) {
  if (sizes.empty()) sizes = {10000, 100000, 1000000};
  std::vector<Timed> timed;
  std::printf("position_identify_bench: ReadCampaign + Identify, best of %d\n", repeat);
  std::printf("  %10s %10s %14s %10s\n", "rows", "time s", "time/row µs", "exponent");
  for (std::size_t i = 0; i < sizes.size(); ++i) {
    timed.push_back(TimeSize(sizes[i], repeat));
    const Timed& t = timed.back();
    char exponent[32] = "";
    if (i > 0) {
      const Timed& p = timed[i - 1];
      std::snprintf(exponent, sizeof exponent, "%.2f",
                    std::log(t.best_s / p.best_s) / std::log(double(t.rows) / double(p.rows)));
    }
    std::printf("  %10ld %10.3f %14.3f %10s\n", t.rows, t.best_s, 1e6 * t.best_s / t.rows,
                exponent);
    std::fflush(stdout);
  }
  if (timed.size() > 1) {
    const Timed &a = timed.front(), &b = timed.back();
    std::printf("  scaling exponent %ld → %ld rows: %.2f (1 = linear)\n", a.rows, b.rows,
                std::log(b.best_s / a.best_s) / std::log(double(b.rows) / double(a.rows)));
  }
  std::printf("estimates at %ld rows (truth m 900, k 47, kq 306, bias −2):\n", timed.back().rows);
  return ReportEstimates(timed.back()) ? 0 : 1;
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<long> sizes;
  int repeat = 3;
  std::string write_dir;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--rows" && i + 1 < argc) {
      sizes.push_back(std::atol(argv[++i]));
    } else if (a == "--repeat" && i + 1 < argc) {
      repeat = std::max(1, std::atoi(argv[++i]));
    } else if (a == "--write" && i + 1 < argc) {
      write_dir = argv[++i];
    } else if (a == "--input" && i + 1 < argc &&
               (argv[i + 1] == std::string("sine") || argv[i + 1] == std::string("legs"))) {
      g_sine_input = argv[++i] == std::string("sine");
    } else {
      std::fprintf(stderr,
                   "usage: position_identify_bench [--rows N]... [--repeat R] | --write DIR "
                   "[--rows N] (either with [--input legs|sine])\n");
      return 2;
    }
  }
  try {
    if (!write_dir.empty()) {
      const long rows = sizes.empty() ? 1000000 : sizes.front();
      std::printf("%s\n", WriteCase(rows, write_dir).c_str());
      return 0;
    }
    return Run(sizes, repeat);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "position_identify_bench: %s\n", e.what());
    return 2;
  }
}
