// The joint one-step integral least squares (ident/estimators/joint_ls.h) of the coupled
// horizontal model (model/coupled_model.h) on virtual combined-mode campaigns of the ASV
// (cases/asv, ref 003).
#include "uuvplan/ident/estimators/joint_ls.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "support/asv.h"
#include "support/coupled_campaign.h"
#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/model/coupled_model.h"
#include "uuvplan/text/finding_text.h"

namespace uuvplan::ident {
namespace {

using uuvplan::testing::AsvCoupledModel;
using uuvplan::testing::AsvTruth;

// `truth`'s θ of the ASV's coupled model.
Eigen::VectorXd TrueTheta(const model::Truth& truth) {
  return model::CoupledThetaOfTruth(AsvCoupledModel(), truth);
}
int InertiaIndex(int i) { return 4 * i; }  // [m, k, kq, bias] of surge, sway, yaw

std::vector<const model::TrialLog*> Pointers(const std::vector<model::TrialLog>& logs) {
  std::vector<const model::TrialLog*> p;
  for (const auto& l : logs) p.push_back(&l);
  return p;
}

JointLsResult Fit(const std::vector<model::TrialLog>& logs) {
  return JointOneStepLeastSquares(AsvCoupledModel(), Pointers(logs), JointLsOptions{});
}

// The case's own truth: every parameter within 3σ, and the σ small enough to mean something
// (the coupling's inertias to better than 10%).
TEST(CoupledLeastSquares, RecoversTheAsvCase) {
  const model::Truth truth = AsvTruth();
  const auto logs =
      uuvplan::testing::RunCoupledCampaign(truth, uuvplan::testing::CombinedModeDesigns(120.0), 11);
  const JointLsResult r = Fit(logs);
  ASSERT_TRUE(r.ok()) << r.message;
  EXPECT_TRUE(r.instrumental);
  const Eigen::VectorXd want = TrueTheta(truth);
  ASSERT_EQ(r.names.size(), 12u);
  for (int j = 0; j < 12; ++j) {
    EXPECT_LT(std::abs(r.theta[j] - want[j]), 3 * r.Sigma(j))
        << r.names[j] << " = " << r.theta[j] << " ± " << r.Sigma(j) << ", true " << want[j];
  }
  for (int i = 0; i < 3; ++i) {
    const int m = InertiaIndex(i);
    EXPECT_LT(r.Sigma(m), 0.1 * want[m]) << r.names[m];
  }
}

// Random coupling truths (seeded), 10 seeds, every coupled parameter within
// 3σ of the truth for >= 90% of the 120 parameter estimates. With a σ that Monte Carlo confirms,
// 99.7% fall within 3σ; a 90% floor fails when σ is too small by a third or more (then about
// 87% or fewer fall within 3σ) or when an estimate is biased by a σ or more.
TEST(CoupledLeastSquares, RandomCouplingTruthsWithin3SigmaOver10Seeds) {
  const model::Truth base = AsvTruth();
  const auto designs = uuvplan::testing::CombinedModeDesigns(120.0);
  int within = 0, total = 0;
  std::string outside;
  double inertia_z = 0.0;  // Σ z of m_u and m_v, the inertias the coupling is made of
  for (std::uint64_t seed = 1; seed <= 10; ++seed) {
    const model::Truth truth = uuvplan::testing::RandomCoupledTruth(base, seed);
    const auto logs = uuvplan::testing::RunCoupledCampaign(truth, designs, 1000 + seed);
    const JointLsResult r = Fit(logs);
    ASSERT_TRUE(r.ok()) << "seed " << seed << ": " << r.message;
    const Eigen::VectorXd want = TrueTheta(truth);
    for (int j = 0; j < 12; ++j, ++total) {
      const double z = (r.theta[j] - want[j]) / r.Sigma(j);
      if (j == InertiaIndex(0) || j == InertiaIndex(1)) inertia_z += z;
      if (std::abs(z) < 3) {
        ++within;
      } else {
        outside +=
            " seed " + std::to_string(seed) + " " + r.names[j] + " z = " + std::to_string(z) + ";";
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
  auto logs = uuvplan::testing::RunCoupledCampaign(AsvTruth(),
                                                   uuvplan::testing::CombinedModeDesigns(60.0), 3);
  logs[1].velocity[model::Index(model::Dof::kSway)].clear();
  const JointLsResult r = Fit(logs);
  EXPECT_FALSE(r.ok());
  EXPECT_NE(r.message.find("trial 2: no vel_sway column"), std::string::npos) << r.message;
}

// A surge+yaw trial alone pushes no sway: the sway equation has no thrust, so nothing fixes the
// scale of its terms (m_u among them), and the residual-weighted least squares drove every
// inertia towards 0 (surge.m 0.31 ± 0.05 kg, status ok) or, through the instruments, to NaN:
// a failure naming the DOF.
TEST(CoupledLeastSquares, ATrialSetThatPushesNoSwayFailsNamingIt) {
  const auto designs = uuvplan::testing::CombinedModeDesigns(120.0);
  const auto logs = uuvplan::testing::RunCoupledCampaign(AsvTruth(), {designs[0]}, 5);  // surge+yaw
  const JointLsResult r = Fit(logs);
  EXPECT_EQ(r.status, JointLsStatus::kTooFewData);
  EXPECT_NE(r.message.find("no fit trial pushes sway"), std::string::npos) << r.message;
}

// A campaign of the ASV's combined-mode trials read as 1-DOF trials (each trial once per DOF
// it pushes, as a user's campaign would list it): the first run fitted, a second run (other
// noise) held out.
model::Campaign OneDofCampaignOfCombinedModes(const model::Truth& truth) {
  const auto designs = uuvplan::testing::CombinedModeDesigns(120.0);
  model::Campaign c;
  c.vehicle = truth.vehicle;
  for (int run = 0; run < 2; ++run) {
    const auto logs = uuvplan::testing::RunCoupledCampaign(truth, designs, 11 + run);
    for (std::size_t i = 0; i < designs.size(); ++i) {
      for (const model::TrialDesign& in : designs[i].inputs) {
        model::TrialEntry e;
        e.file = designs[i].id + "_" + std::string(model::DofName(in.dof)) + "_run" +
                 std::to_string(run) + ".csv";
        e.path = e.file;
        e.dof = in.dof;
        e.mapping = in.mapping;
        e.use = run == 0 ? model::TrialUse::kFit : model::TrialUse::kValidate;
        e.log = logs[i];
        c.trials.push_back(std::move(e));
      }
    }
  }
  return c;
}

TEST(CoupledDiagnosis, NamesTheCoriolisCouplingOfEachDofOnA1DofFittedCampaign) {
  // The 1-DOF standard model fitted to a 3-DOF campaign misses ref 003's Coriolis
  // terms; diagnosis names, in each DOF, exactly the product the coupled model has there, with
  // its coefficient (surge m_v·v·r, sway −m_u·u·r, yaw (m_u − m_v)·u·v), a held-out gain, and
  // offers the coupled model. Measured: v·r 511.2 ± 1.9 (m_v 510), u·r −330.2 ±
  // 1.3 (−m_u −330), u·v −178.8 ± 2.1 (m_u − m_v −180); validate velocity MAE 86%, 82%, 95%
  // better.
  const model::Truth truth = AsvTruth();
  const Eigen::VectorXd want = TrueTheta(truth);
  const double m_u = want[InertiaIndex(0)], m_v = want[InertiaIndex(1)];
  const struct {
    model::Dof dof;
    const char* param;
    double coefficient;
  } expected[] = {{model::Dof::kSurge, "coupling.vr", m_v},
                  {model::Dof::kSway, "coupling.ur", -m_u},
                  {model::Dof::kYaw, "coupling.uv", m_u - m_v}};
  const DiagnosisResult r = Diagnose(OneDofCampaignOfCombinedModes(truth), DiagnoseOptions{});
  for (const auto& e : expected) {
    SCOPED_TRACE(std::string(model::DofName(e.dof)));
    const Finding* found = nullptr;
    for (const Finding& f : r.findings) {
      if (f.dof == e.dof && f.effect == "coupling") found = &f;
    }
    ASSERT_NE(found, nullptr) << "no coupling finding";
    const int j = FindEstimate(found->params, e.param);
    ASSERT_GE(j, 0) << "the coupling found is not the Coriolis product " << e.param;
    const ParameterEstimate& c = found->params[j];
    // 3σ: a correct σ puts the truth outside 0.27% of the time.
    EXPECT_LE(std::abs(c.value - e.coefficient), 3 * c.sigma)
        << c.name << " = " << c.value << " ± " << c.sigma << ", true " << e.coefficient;
    // The missing term carries most of the 1-DOF model's error: held out, at least half of it
    // goes (measured 82–95%).
    EXPECT_EQ(found->gain.on, "validate");
    EXPECT_GT(found->gain.relative, 0.5) << found->gain.before << " -> " << found->gain.after;
    const std::string what = text::FindingSentence(r, *found);
    EXPECT_NE(what.find("--model coupled"), std::string::npos) << what;
  }
}

}  // namespace
}  // namespace uuvplan::ident
