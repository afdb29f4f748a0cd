// Diagnosis. The statistical claim (≥ 95% of 200 draws per effect named correctly,
// ≤ 5% false findings on clean data, the hidden parameter within 3σ) is checked at full size
// by `build/tests/diagnose_validation` (docs/validation.md). Here a seeded subset of the same
// generator: the draws are fixed, so every one of them must be diagnosed exactly; a change
// that breaks the tests, the candidate fits or the generator's hiding fails it.
#include "uuvplan/ident/diagnosis/diagnosis.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <iterator>

#include "support/hidden_effect.h"
#include "support/real_data.h"
#include "uuvplan/ident/stats/chi_square.h"
#include "uuvplan/io/io.h"
#include "uuvplan/text/diagnosis_notes_text.h"
#include "uuvplan/text/finding_text.h"

namespace uuvplan::ident {
namespace {

using uuvplan::testing::RealDataPath;

TEST(ChiSquareTest, MatchesTabulatedQuantiles) {
  // 95% and 99.9% quantiles from standard χ² tables (4 significant digits: tolerance 1e-4).
  EXPECT_NEAR(ChiSquareSurvival(3.841, 1), 0.05, 1e-4);
  EXPECT_NEAR(ChiSquareSurvival(5.991, 2), 0.05, 1e-4);
  EXPECT_NEAR(ChiSquareSurvival(18.307, 10), 0.05, 1e-4);
  EXPECT_NEAR(ChiSquareSurvival(10.828, 1), 0.001, 1e-5);
  EXPECT_NEAR(ChiSquareSurvival(13.816, 2), 0.001, 1e-5);
  EXPECT_DOUBLE_EQ(ChiSquareSurvival(0.0, 3), 1.0);
}

constexpr int kDrawsPerEffect = 3;  // seeds 1..3 per effect; full size: 200

class HiddenEffectTest : public ::testing::TestWithParam<int> {};

TEST_P(HiddenEffectTest, NamesTheHiddenEffectAndOnlyIt) {
  const int e = GetParam();
  const std::vector<std::string> names = model::Effects().Diagnosable();
  const std::optional<std::string> effect =
      e < 0 ? std::nullopt : std::optional<std::string>(names[e]);
  for (std::uint64_t seed = 1; seed <= kDrawsPerEffect; ++seed) {
    const uuvplan::testing::HiddenEffectCase c =
        uuvplan::testing::DrawHiddenEffectCase(effect, seed);
    const model::Campaign campaign = uuvplan::testing::RunHiddenEffectCase(c, seed);
    const DiagnosisResult r = Diagnose(campaign, uuvplan::testing::DiagnoseOptionsFor(c));
    const uuvplan::testing::Verdict v = uuvplan::testing::Judge(c, r);
    EXPECT_TRUE(v.correct) << "seed " << seed << ": hidden " << effect.value_or("none")
                           << ", found [" << v.found << "]";
    if (effect) {
      EXPECT_TRUE(v.within_3_sigma) << "seed " << seed << ": parameter beyond 3σ of the truth";
      ASSERT_FALSE(r.findings.empty());
      // The extension must pay off where the effect was hidden (validate trials).
      EXPECT_GT(r.findings[0].gain.relative, 0.0) << "seed " << seed;
      EXPECT_EQ(r.findings[0].gain.on, "validate");
      EXPECT_FALSE(text::FindingSentence(r, r.findings[0]).empty());
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryEffectAndNone, HiddenEffectTest,
                         ::testing::Range(-1,
                                          static_cast<int>(model::Effects().Diagnosable().size())),
                         [](const ::testing::TestParamInfo<int>& info) {
                           return info.param < 0 ? std::string("none")
                                                 : model::Effects().Diagnosable()[info.param];
                         });

// Coupling draws 21 and 24 once gave a spurious second effect (drift; asymmetric drag and
// drift): the coupling's logged velocities of other DOFs are noisy, which the likelihood ratio
// reads as structure. The extra effects are significant by D but predict held-out data no
// better, and must be rejected for it (docs/diagnosis.md §3).
TEST(DiagnosisTest, SpuriousEffectsWithoutHeldOutGainAreRejected) {
  for (std::uint64_t seed : {21u, 24u}) {
    const uuvplan::testing::HiddenEffectCase c =
        uuvplan::testing::DrawHiddenEffectCase("coupling", seed);
    const DiagnosisResult r = Diagnose(uuvplan::testing::RunHiddenEffectCase(c, seed),
                                       uuvplan::testing::DiagnoseOptionsFor(c));
    const uuvplan::testing::Verdict v = uuvplan::testing::Judge(c, r);
    EXPECT_TRUE(v.correct) << "seed " << seed << ": found [" << v.found << "]";
    int rejected = 0;
    for (const auto& t : r.tests) {
      if (t.round == 1 && t.significant && !t.accepted) {
        ++rejected;
        EXPECT_LT(t.gain, 0.01) << t.effect;
      }
    }
    EXPECT_GE(rejected, 1) << "seed " << seed << ": the spurious effect should be significant by D";
  }
}

// The coupling's logged velocities of other DOFs are noisy inputs: the output-error σ, which
// take inputs as exact, understated the spread (hidden coupling, seeds 1–200: the coefficient
// beyond 3σ in 25 of 195 draws). Redrawing that noise in refits adds its covariance.
TEST(DiagnosisTest, CouplingSigmaIncludesTheNoiseOfTheLoggedVelocities) {
  const std::uint64_t seed = 21;
  const uuvplan::testing::HiddenEffectCase c =
      uuvplan::testing::DrawHiddenEffectCase("coupling", seed);
  const model::Campaign campaign = uuvplan::testing::RunHiddenEffectCase(c, seed);
  DiagnoseOptions with = uuvplan::testing::DiagnoseOptionsFor(c);
  DiagnoseOptions without = with;
  without.input_noise_replicates = 0;
  const DiagnosisResult a = Diagnose(campaign, with);
  const DiagnosisResult b = Diagnose(campaign, without);
  ASSERT_EQ(a.findings.size(), 1u);
  ASSERT_EQ(b.findings.size(), 1u);
  ASSERT_EQ(a.findings[0].params.size(), 1u);
  // Same estimate (the refits only add covariance), larger σ.
  EXPECT_DOUBLE_EQ(a.findings[0].params[0].value, b.findings[0].params[0].value);
  EXPECT_GT(a.findings[0].params[0].sigma, b.findings[0].params[0].sigma);
  bool noted = false;
  for (const std::string& n : text::NoteTexts(a.notes))
    noted = noted || n.find("noise of the logged velocities") != std::string::npos;
  EXPECT_TRUE(noted);
}

// Real logs are the final judge (docs/diagnosis.md, "On real logs"; the identification of the
// same logs is tested in ident_cli_test.cc). shared/data/bluerov-yaw-2016/README.md, defect 2:
// the fit improves markedly when the torque passes through a first-order lag of about 60 ms (a
// 20–30 ms pure delay fits less well). The diagnosis must name that effect first, with a lag of
// the same order — 40–120 ms: the README's 60 ms came from an equation-error fit on a grid of
// lags, and motor spin-up plus command transport make the exact value uncertain — and it must
// pay off on the held-out runs yaw_4, yaw_5: ≥ 10% (a ~70 ms lag against a time constant
// I/k ≈ 0.25 s; 19% on these logs).
TEST(DiagnosisTest, RealBluerovYawRunsShowTheThrusterLag) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("bluerov-yaw-2016");
  const model::Campaign campaign = io::ReadCampaign(RealDataPath("bluerov-yaw-2016/campaign.yaml"));
  const DiagnosisResult r = Diagnose(campaign, DiagnoseOptions{});
  ASSERT_FALSE(r.findings.empty());
  const Finding& first = r.findings.front();
  EXPECT_EQ(first.effect, "thruster_lag");
  EXPECT_EQ(first.dof, model::Dof::kYaw);
  ASSERT_EQ(first.params.size(), 1u);
  EXPECT_GT(first.params[0].value, 0.04);
  EXPECT_LT(first.params[0].value, 0.12);
  EXPECT_EQ(first.gain.on, "validate");
  EXPECT_GT(first.gain.relative, 0.10);
}

// The 13 runs of three sessions (campaign_all.yaml): diagnosis_model_test.cc
// (DiagnosisModelTest.RealBluerovThrustMapShapeAndLagScored).

// tartan-pool-2022 is closed-loop flight without trial start times (its README, defect 1;
// notes/pitfalls.md: say so rather than report a confident answer). The diagnosis must put the
// closed-loop caveat beside its findings, and not test or quote a drift over a campaign clock
// the file does not give.
TEST(DiagnosisTest, RealClosedLoopLogsWithoutClockAreQualified) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("tartan-pool-2022");
  const model::Campaign campaign = io::ReadCampaign(RealDataPath("tartan-pool-2022/campaign.yaml"));
  DiagnoseOptions o;
  o.dofs = {model::Dof::kHeave};
  const DiagnosisResult r = Diagnose(campaign, o);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_THAT(text::NoteText(r.warnings[0]),
              ::testing::HasSubstr("heave: closed-loop data suspected"));
  ASSERT_EQ(r.breakdowns.size(), 1u);
  EXPECT_TRUE(std::isnan(r.breakdowns[0].drift_per_hour));
  for (const CandidateTest& t : r.tests) EXPECT_NE(t.effect, "parameter_drift");
  EXPECT_THAT(text::NoteTexts(r.notes),
              ::testing::Contains(::testing::HasSubstr("parameter_drift not tested")));
}

}  // namespace
}  // namespace uuvplan::ident
