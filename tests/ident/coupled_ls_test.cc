// The one-step integral least squares of the coupled horizontal model (ident/coupled_ls.h) on
// virtual combined-mode campaigns of the ASV (cases/asv, seed 003).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/coupled_campaign.h"
#include "uuvplan/ident/coupled_ls.h"
#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/model/coupled_model.h"

namespace uuvplan::ident {
namespace {

model::Truth AsvTruth() {
  return io::ReadTruth(std::string(UUVPLAN_SOURCE_DIR) + "/cases/asv/truth.yaml");
}

std::vector<const model::TrialLog*> Pointers(const std::vector<model::TrialLog>& logs) {
  std::vector<const model::TrialLog*> p;
  for (const auto& l : logs) p.push_back(&l);
  return p;
}

// The case's own truth: every parameter within 3σ, and the σ small enough to mean something
// (the coupling's inertias to better than 10%).
TEST(CoupledLeastSquares, RecoversTheAsvCase) {
  const model::Truth truth = AsvTruth();
  const auto logs = testing::RunCoupledCampaign(truth, testing::CombinedModeDesigns(120.0), 11);
  const CoupledLsResult r = CoupledOneStepLeastSquares(Pointers(logs), CoupledLsOptions{});
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(r.instrumental);
  const model::CoupledHorizontalModel want = model::CoupledModelOfTruth(truth);
  for (int j = 0; j < model::kCoupledParameterCount; ++j) {
    EXPECT_LT(std::abs(r.theta[j] - want.theta[j]), 3 * r.Sigma(j))
        << r.names[j] << " = " << r.theta[j] << " ± " << r.Sigma(j) << ", true " << want.theta[j];
  }
  for (int i = 0; i < 3; ++i) {
    const int m = model::CoupledIndex(i, "m");
    EXPECT_LT(r.Sigma(m), 0.1 * want.theta[m]) << r.names[m];
  }
}

// Issue #19 Done when: random coupling truths (seeded), 10 seeds, every coupled parameter within
// 3σ of the truth for >= 90% of the 120 parameter estimates. With a σ that Monte Carlo confirms,
// 99.7% fall within 3σ; a 90% floor fails when σ is too small by a third or more (then about
// 87% or fewer fall within 3σ) or when an estimate is biased by a σ or more.
TEST(CoupledLeastSquares, RandomCouplingTruthsWithin3SigmaOver10Seeds) {
  const model::Truth base = AsvTruth();
  const auto designs = testing::CombinedModeDesigns(120.0);
  int within = 0, total = 0;
  std::string outside;
  double inertia_z = 0.0;  // Σ z of m_u and m_v, the inertias the coupling is made of
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const model::Truth truth = testing::RandomCoupledTruth(base, seed);
    const auto logs = testing::RunCoupledCampaign(truth, designs, 1000 + seed);
    const CoupledLsResult r = CoupledOneStepLeastSquares(Pointers(logs), CoupledLsOptions{});
    ASSERT_TRUE(r.ok()) << "seed " << seed << ": " << r.message;
    const model::CoupledHorizontalModel want = model::CoupledModelOfTruth(truth);
    for (int j = 0; j < model::kCoupledParameterCount; ++j, ++total) {
      const double z = (r.theta[j] - want.theta[j]) / r.Sigma(j);
      if (j == model::CoupledIndex(0, "m") || j == model::CoupledIndex(1, "m")) inertia_z += z;
      if (std::abs(z) < 3) {
        ++within;
      } else {
        outside += " seed " + std::to_string(seed) + " " + r.names[j] + " z = " +
                   std::to_string(z) + ";";
      }
    }
  }
  std::printf("%d of %d within 3σ;%s\n", within, total, outside.c_str());
  EXPECT_GE(within, 0.9 * total) << within << " of " << total << " within 3σ; outside:" << outside;
  // No bias in the coupling's inertias: the mean of 20 unbiased z has σ 1/√20 = 0.22; the bound
  // is 2σ of it, ±0.45 (seeded, so the draw is fixed: +0.22 today). The plain least squares (no
  // instruments) is biased low by errors in variables: −0.64 on these seeds, and −0.9 over 200
  // draws (docs/validation.md); it fails here.
  EXPECT_LT(std::abs(inertia_z / 20), 2 / std::sqrt(20.0)) << "mean z of surge.m, sway.m";
}

TEST(CoupledLeastSquares, NamesTheMissingColumn) {
  auto logs = testing::RunCoupledCampaign(AsvTruth(), testing::CombinedModeDesigns(60.0), 3);
  logs[1].velocity[model::Index(model::Dof::kSway)].clear();
  const CoupledLsResult r = CoupledOneStepLeastSquares(Pointers(logs), CoupledLsOptions{});
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message.find("trial 2: no vel_sway column"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace uuvplan::ident
