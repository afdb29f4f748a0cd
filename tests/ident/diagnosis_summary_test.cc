// DiagnosisResult::Summary (summary.h, Ceres' Solver::Summary is the model): the status word,
// the driver's four stages timed in order, a one-line Brief() naming what was found, and a
// Full() with a line per DOF. On seeded hidden-effect draws (tests/support/hidden_effect.h)
// that diagnosis_test.cc shows to be diagnosed exactly.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "support/hidden_effect.h"
#include "uuvplan/ident/diagnosis/diagnosis.h"

namespace uuvplan::ident {
namespace {

DiagnosisResult DiagnoseDraw(const std::optional<std::string>& effect, std::uint64_t seed) {
  const uuvplan::testing::HiddenEffectCase c = uuvplan::testing::DrawHiddenEffectCase(effect, seed);
  return Diagnose(uuvplan::testing::RunHiddenEffectCase(c, seed),
                  uuvplan::testing::DiagnoseOptionsFor(c));
}

void ExpectFourStagesInOrder(const PipelineSummary& s) {
  const std::vector<std::string> stages = {"screen", "test", "extend", "measure"};
  ASSERT_EQ(s.stages.size(), stages.size());
  for (std::size_t i = 0; i < stages.size(); ++i) {
    EXPECT_EQ(s.stages[i].stage, stages[i]);
    EXPECT_GE(s.stages[i].seconds, 0.0);
  }
  EXPECT_GT(s.total_seconds(), 0.0);
}

TEST(DiagnosisSummaryTest, FindingsNamedInBriefWithStagesInOrder) {
  const DiagnosisResult r = DiagnoseDraw("asymmetric_drag", 1);
  ASSERT_EQ(r.findings.size(), 1u);
  const PipelineSummary s = r.Summary();
  EXPECT_EQ(s.pipeline, "diagnose");
  EXPECT_EQ(s.status, "findings");
  EXPECT_EQ(s.num_trials, static_cast<int>(r.nominal.trials.size()));
  ExpectFourStagesInOrder(s);
  const std::string brief = s.Brief();
  EXPECT_EQ(brief.find('\n'), std::string::npos) << brief;
  EXPECT_EQ(brief.rfind("diagnose: findings, 1 DOF(s) from ", 0), 0u) << brief;
  EXPECT_NE(brief.find("asymmetric_drag"), std::string::npos) << brief;
  const std::string full = s.Full();
  EXPECT_EQ(full.rfind(brief + "\n", 0), 0u) << full;
  EXPECT_NE(full.find("stages: screen"), std::string::npos) << full;
  EXPECT_NE(full.find("1 effect(s): asymmetric_drag (held-out gain "), std::string::npos) << full;
}

TEST(DiagnosisSummaryTest, CleanDataGivesNone) {
  const DiagnosisResult r = DiagnoseDraw(std::nullopt, 1);
  ASSERT_TRUE(r.findings.empty());
  const PipelineSummary s = r.Summary();
  EXPECT_EQ(s.status, "none");
  ExpectFourStagesInOrder(s);
  ASSERT_EQ(s.dofs.size(), 1u);
  EXPECT_EQ(s.dofs[0].brief, "none");
}

TEST(DiagnosisSummaryTest, NoDiagnosableDofIsFailed) {
  // A DOF without trials has no standard model to fit: nothing could be diagnosed.
  const uuvplan::testing::HiddenEffectCase c =
      uuvplan::testing::DrawHiddenEffectCase(std::nullopt, 1);
  DiagnoseOptions o = uuvplan::testing::DiagnoseOptionsFor(c);
  o.dofs = {c.dof == model::Dof::kYaw ? model::Dof::kSurge : model::Dof::kYaw};
  const PipelineSummary s = Diagnose(uuvplan::testing::RunHiddenEffectCase(c, 1), o).Summary();
  EXPECT_EQ(s.status, "failed");
  EXPECT_FALSE(s.message.empty());
  ASSERT_EQ(s.dofs.size(), 1u);
  EXPECT_EQ(s.dofs[0].brief, "not diagnosed");
}

}  // namespace
}  // namespace uuvplan::ident
