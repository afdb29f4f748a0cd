// Full-size validation of the coupled horizontal model's one-step least squares (
// ident/estimators/joint_ls.h): N random coupling truths of the ASV (cases/asv, ref 003), each run
// through the three combined modes in the virtual pool and identified. Prints per parameter the
// share of estimates within 1σ, 2σ and 3σ of the truth (Gaussian: 68.3%, 95.4%, 99.7%), the
// mean z = (θ̂ − θ)/σ (bias, in σ) and the standard deviation of z (1 when σ is right).
// Run: build/coupled_validation [draws = 200] [first seed = 1] [trial duration s = 120]
//      [instrumental-variable iterations = 2; 0: the papers' plain least squares]
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "support/coupled_campaign.h"
#include "uuvplan/ident/estimators/joint_ls.h"
#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/model/coupled_model.h"

using namespace uuvplan;

int main(int argc, char** argv) {
  const int draws = argc > 1 ? std::atoi(argv[1]) : 200;
  const std::uint64_t first = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  const double duration = argc > 3 ? std::atof(argv[3]) : 120.0;
  ident::JointLsOptions options;
  if (argc > 4) options.iv_iterations = std::atoi(argv[4]);
  if (draws <= 0 || first == 0 || !(duration > 0) || argc > 5 || !options.IsValid(nullptr)) {
    std::fprintf(stderr,
                 "usage: coupled_validation [draws > 0] [first seed > 0] [duration s] "
                 "[iv iterations 0..20]\n");
    return 2;
  }
  const model::Truth base =
      io::ReadTruth(std::string(UUVPLAN_SOURCE_DIR) + "/cases/asv/truth.yaml");
  const auto designs = testing::CombinedModeDesigns(duration);
  constexpr int P = 12;  // [m, k, kq, bias] of surge, sway, yaw
  std::vector<std::vector<double>> z(P);
  int failed = 0;
  for (int i = 0; i < draws; ++i) {
    const std::uint64_t seed = first + i;
    const model::Truth truth = testing::RandomCoupledTruth(base, seed);
    const auto logs = testing::RunCoupledCampaign(truth, designs, 1000 + seed);
    std::vector<const model::TrialLog*> p;
    for (const auto& l : logs) p.push_back(&l);
    const ident::JointLsResult r =
        ident::JointOneStepLeastSquares(model::CoupledHorizontalModel(truth.vehicle), p, options);
    if (!r.ok()) {
      std::printf("seed %llu: %s\n", static_cast<unsigned long long>(seed), r.message.c_str());
      ++failed;
      continue;
    }
    const Eigen::VectorXd want =
        model::CoupledThetaOfTruth(model::CoupledHorizontalModel(truth.vehicle), truth);
    for (int j = 0; j < P; ++j) z[j].push_back((r.theta[j] - want[j]) / r.Sigma(j));
  }
  const std::vector<std::string> names =
      model::CoupledHorizontalModel(base.vehicle).parameter_names();
  std::printf("%d draws from seed %llu, trials of %g s, %d IV iterations, %d failed fits\n", draws,
              static_cast<unsigned long long>(first), duration, options.iv_iterations, failed);
  std::printf("%-12s %7s %7s %7s %8s %7s\n", "parameter", "1σ %", "2σ %", "3σ %", "mean z", "sd z");
  int within3 = 0, total = 0;
  for (int j = 0; j < P; ++j) {
    int c1 = 0, c2 = 0, c3 = 0;
    double mean = 0, sq = 0;
    for (double v : z[j]) {
      c1 += std::abs(v) < 1, c2 += std::abs(v) < 2, c3 += std::abs(v) < 3;
      mean += v;
    }
    const double n = static_cast<double>(z[j].size());
    mean /= n;
    for (double v : z[j]) sq += (v - mean) * (v - mean);
    within3 += c3;
    total += static_cast<int>(z[j].size());
    std::printf("%-12s %7.1f %7.1f %7.1f %8.3f %7.3f\n", names[j].c_str(), 100 * c1 / n,
                100 * c2 / n, 100 * c3 / n, mean, std::sqrt(sq / (n - 1)));
  }
  std::printf("all parameters within 3σ: %.1f%% of %d\n", 100.0 * within3 / total, total);
  return failed > 0 ? 1 : 0;
}
