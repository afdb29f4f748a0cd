// Failure is a status (docs/identification.md "Failure statuses"): a non-physical
// fit, a fit that explains nothing (the virtual twin of tartan yaw) are `failed` with their
// reason, and a trial with more than 5% of its samples excluded as outliers is a warning that
// names it. The real-data cases (bluerov kq < 0, tartan yaw) are in ident_cli_test.cc.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "ident_cases.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/model/campaign_builder.h"

namespace uuvplan::ident {
namespace {

using model::Dof;
using ::testing::HasSubstr;

model::Campaign Virtual(const model::Truth& truth, const std::vector<model::TrialDesign>& designs,
                        std::uint64_t seed) {
  model::VirtualCampaignOptions vo;
  vo.seed = seed;
  vo.unwrap_headings = true;
  return model::BuildVirtualCampaign(truth, designs, vo);
}

TEST(IdentifyFailureTest, NegativeQuadraticDragIsANonPhysicalFailure) {
  // A vehicle whose true kq is −30 N·s²/m² (no such vehicle: the drag would feed energy in),
  // run at speeds where it stays stable (v < k/|kq| = 1.6 m/s): the fit finds kq < 0 far beyond
  // 3σ, outside the family's admissible range (kq ≥ 0, model/parameter.h) — failed, with the
  // parameter and the range in the reason. The same vehicle with kq = +30 is identified.
  using testing::Segments;
  const std::vector<model::TrialDesign> designs = {
      Segments("a", Dof::kSurge, "surge-front", {{10, 60}, {-10, 60}, {15, 60}, {-15, 60}}),
      testing::Sine("b", Dof::kSurge, "surge-front", 0, 15, 26, 130)};
  for (double kq : {-30.0, 30.0}) {
    model::Truth truth = testing::CaseTruth("romeo");
    truth.dofs[Dof::kSurge].params["kq"] = kq;
    const IdentifyResult r = Identify(Virtual(truth, designs, 3), IdentifyOptions{});
    const DofIdentification* d = r.Find(Dof::kSurge);
    ASSERT_NE(d, nullptr);
    if (kq < 0) {
      EXPECT_EQ(d->status, IdentifyStatus::kFailed);
      EXPECT_EQ(r.status, IdentifyStatus::kFailed);
      EXPECT_THAT(d->message, HasSubstr("non-physical fit: kq = "));
      EXPECT_THAT(d->message, HasSubstr("a number >= 0"));
    } else {
      EXPECT_NE(d->status, IdentifyStatus::kFailed) << d->message;
    }
  }
}

TEST(IdentifyFailureTest, AForceUnrelatedToTheMotionFails) {
  // The virtual twin of tartan yaw (closed-loop logs the model cannot explain): ROMEO yaw
  // trials whose logged force is replaced by seeded noise of the same size, unrelated to the
  // motion. Whatever the estimators return, the DOF must not be reported as identified: it is
  // failed with a reason (insignificant dynamics, a diverging free run, or no better than ν ≡ 0).
  model::Campaign c = Virtual(testing::CaseTruth("romeo"), testing::RomeoYawDesigns(), 9);
  std::mt19937_64 rng(42);
  std::normal_distribution<double> noise(0.0, 5.0);  // N·m, the legs' size
  for (auto& t : c.trials) {
    for (double& f : t.log.force[model::Index(Dof::kYaw)]) {
      if (std::isfinite(f)) f = noise(rng);
    }
  }
  IdentifyOptions o;
  o.closed_loop = ClosedLoop::kNo;  // judged on the fit alone, not on the closed-loop caveat
  const IdentifyResult r = Identify(c, o);
  const DofIdentification* d = r.Find(Dof::kYaw);
  ASSERT_NE(d, nullptr);
  EXPECT_EQ(d->status, IdentifyStatus::kFailed) << d->message;
  EXPECT_FALSE(d->message.empty());
  EXPECT_EQ(r.status, IdentifyStatus::kFailed);
  EXPECT_THAT(r.message, HasSubstr("failed: yaw"));
}

TEST(IdentifyFailureTest, ManyOutliersAreAFindingThatNamesTheTrial) {
  // 8% multipath outliers (cases/romeo has 0.5%): more than 5% of a trial's samples excluded is
  // a warning with the count and the trial; 0.5% is not.
  for (double p : {0.08, 0.005}) {
    model::Truth truth = testing::CaseTruth("romeo");
    truth.defects.outlier_probability = p;
    const IdentifyResult r =
        Identify(Virtual(truth, testing::RomeoSurgeDesigns(), 4), IdentifyOptions{});
    const DofIdentification* d = r.Find(Dof::kSurge);
    ASSERT_NE(d, nullptr);
    int findings = 0;
    for (const std::string& w : d->warnings) {
      if (w.find("excluded as outliers, more than 5%") == std::string::npos) continue;
      ++findings;
      EXPECT_THAT(w, ::testing::MatchesRegex("surge_[a-z]+: [0-9]+ of [0-9]+ position samples.*"));
    }
    if (p > 0.05) {
      EXPECT_EQ(findings, 4) << "every trial";
    } else {
      EXPECT_EQ(findings, 0);
    }
  }
}

}  // namespace
}  // namespace uuvplan::ident
