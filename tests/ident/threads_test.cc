// Monte Carlo's repetitions and identification's trials and DOFs run on several
// threads (`--threads`) with results identical to one thread: each job fills its own slot.
// (Diagnosis's candidate fits: DiagnosisModelTest, tests/ident/diagnosis_model_test.cc.)
#include <gtest/gtest.h>

#include "ident_cases.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/ident/stats/monte_carlo.h"
#include "uuvplan/model/campaign_builder.h"

namespace uuvplan::ident {
namespace {

TEST(MonteCarloThreadsTest, TwoThreadsGiveTheReportOfOne) {
  MonteCarloOptions o;
  o.repetitions = 4;  // enough for each thread to take several, in any order
  o.seed = 16;
  o.cramer_rao = true;  // the bound comes from the first repetition's campaign, rebuilt
  const model::Truth truth = testing::CaseTruth("vsor");
  const std::vector<model::TrialDesign> designs = {testing::VsorDesigns()[0]};
  o.threads = 1;
  const MonteCarloReport one = RunMonteCarlo(truth, designs, o);
  o.threads = 2;
  const MonteCarloReport two = RunMonteCarlo(truth, designs, o);
  EXPECT_EQ(one.failures, two.failures);
  EXPECT_EQ(one.notes, two.notes);
  ASSERT_EQ(one.cells.size(), two.cells.size());
  ASSERT_FALSE(one.cells.empty());
  for (std::size_t i = 0; i < one.cells.size(); ++i) {
    const CoverageCell &a = one.cells[i], &b = two.cells[i];
    SCOPED_TRACE(a.estimator + " " + a.name);
    EXPECT_EQ(a.estimator, b.estimator);
    EXPECT_EQ(a.name, b.name);
    EXPECT_EQ(a.n, b.n);
    EXPECT_EQ(a.covered, b.covered);
    // Exactly equal: the same floating-point operations in the same order.
    EXPECT_EQ(a.mean, b.mean);
    EXPECT_EQ(a.sd, b.sd);
    EXPECT_EQ(a.mean_sigma, b.mean_sigma);
    EXPECT_EQ(a.crb_sigma, b.crb_sigma);
  }
}

TEST(IdentifyThreadsTest, TwoThreadsGiveTheResultOfOne) {
  // Two DOFs (ROMEO yaw and heave), so that both the trials and the DOFs run in parallel.
  const model::Truth truth = testing::CaseTruth("romeo");
  std::vector<model::TrialDesign> designs = testing::RomeoYawDesigns();
  for (const auto& d : testing::RomeoHeaveDesigns()) designs.push_back(d);
  model::VirtualCampaignOptions vo;
  vo.seed = 16;
  const model::Campaign campaign = model::BuildVirtualCampaign(truth, designs, vo);
  IdentifyOptions o;
  o.threads = 1;
  const IdentifyResult one = Identify(campaign, o);
  o.threads = 2;
  const IdentifyResult two = Identify(campaign, o);
  EXPECT_EQ(one.message, two.message);
  ASSERT_EQ(one.trials.size(), two.trials.size());
  ASSERT_EQ(one.dofs.size(), 2u);
  ASSERT_EQ(two.dofs.size(), 2u);
  for (std::size_t k = 0; k < one.dofs.size(); ++k) {
    const DofIdentification &a = one.dofs[k], &b = two.dofs[k];
    EXPECT_EQ(a.dof, b.dof);
    EXPECT_EQ(a.status, b.status);
    EXPECT_EQ(a.notes, b.notes);
    EXPECT_EQ(a.warnings, b.warnings);
    EXPECT_EQ(a.parameter_names, b.parameter_names);
    // Exactly equal: the same floating-point operations in the same order.
    EXPECT_EQ(a.theta, b.theta);
    EXPECT_EQ(a.covariance, b.covariance);
  }
}

}  // namespace
}  // namespace uuvplan::ident
