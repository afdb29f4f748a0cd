// Whether a trial starts at rest (start_at_rest.h), and what the output error makes of a trial
// that starts moving (docs/identification.md §6, "Each trial's initial velocity is estimated").
#include "uuvplan/ident/prepare/start_at_rest.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "ident_cases.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/ident/stats/monte_carlo.h"

namespace uuvplan::ident {
namespace {

using model::Dof;

// ROMEO surge (cases/romeo/truth.yaml: m 900 kg, k 46.9 N·s/m, kq 306.2 N·s²/m²) under 50 N
// from velocity v0, 60 s of positions at 100 Hz with white noise of 1 cm (a camera or an
// acoustic fix at rate), prepared as the output error's trial data are: the filter's window of
// 41 samples, the noise σ declared.
TrialData RomeoSurgeStart(double v0, std::uint64_t seed) {
  const double m = 900, k = 46.9, kq = 306.2, force = 50, h = 1e-3;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> noise(0.0, 0.01);
  TrialData d;
  std::vector<double> t, y;
  double x = 0, v = v0;
  for (int i = 0; i <= 60000; ++i) {  // explicit Euler at 1 ms: 1e-5 m of error over 60 s
    if (i % 10 == 0) {
      t.push_back(i * h);
      y.push_back(x + noise(rng));
    }
    x += h * v;
    v += h * (force - k * v - kq * v * std::abs(v)) / m;
  }
  d.position.t = std::move(t);
  d.position.y = std::move(y);
  d.position_sigma = 0.01;
  d.sg_window = 41;
  return d;
}

TEST(JudgeStartTest, AStartFromRestIsAtRestAndAMovingOneGetsTheLongestWindowsVelocity) {
  // Over the filter's 41 samples the initial velocity's σ is 5 cm/s: a start from rest is judged
  // at rest unless its estimate falls beyond 3σ (0.27%: at most 1 of 40, P(≥ 2) ≈ 0.5%), a start
  // at 0.3 m/s (6σ) is judged moving. Its velocity is then that of the cubic through the longest
  // window, at least 160 samples: within 1 cm/s (the filter's edge value scatters by 5 cm/s).
  int rest_judged_moving = 0, moving_judged_moving = 0;
  for (std::uint64_t seed = 1; seed <= 40; ++seed) {
    rest_judged_moving += JudgeStart(RomeoSurgeStart(0.0, seed)).at_rest ? 0 : 1;
    const TrialStart moving = JudgeStart(RomeoSurgeStart(0.3, seed));
    moving_judged_moving += moving.at_rest ? 0 : 1;
    EXPECT_NEAR(moving.velocity, 0.3, 0.01) << "seed " << seed;
  }
  EXPECT_LE(rest_judged_moving, 1);
  EXPECT_EQ(moving_judged_moving, 40);
}

TEST(JudgeStartTest, ACommandStepEndsTheWindow) {
  // A step of the command 0.5 s in: the window stops there (the motion after a step is no
  // longer one polynomial), so no window longer than the filter's gives the velocity.
  TrialData d = RomeoSurgeStart(0.3, 7);
  d.force_jumps = {0.5};
  const TrialStart start = JudgeStart(d);
  EXPECT_FALSE(start.at_rest);
  EXPECT_FALSE(std::isfinite(start.velocity));
}

// A ROMEO surge campaign logged at 100 Hz with 1 cm of noise whose first trial starts from rest
// and the second is the same run's record cut `cut_s` after its start: a recording started late.
model::Campaign CutCampaign(double cut_s) {
  model::Truth truth = testing::CaseTruth("romeo");
  truth.vehicle.sensors[Dof::kSurge] = model::DofSensors{};
  truth.vehicle.sensors[Dof::kSurge].position = model::SensorSpec{100.0, 0.01};
  const model::TrialDesign legs =
      testing::Segments("legs", Dof::kSurge, "surge-front", {{50, 40}, {-40, 40}, {70, 40}});
  model::Campaign c = VirtualCampaign(truth, {legs, legs}, 11);
  model::TrialLog& log = c.trials[1].log;
  std::size_t cut = 0;
  while (log.t[cut] < cut_s) ++cut;
  const double t0 = log.t[cut];
  const auto keep = [cut](std::vector<double>& column) {
    if (!column.empty()) column.erase(column.begin(), column.begin() + cut);
  };
  // The command in force at the cut on its first row (a zero-order hold's value there).
  std::vector<double>& force = log.force[model::Index(Dof::kSurge)];
  for (std::size_t i = cut; i-- > 0 && std::isnan(force[cut]);) force[cut] = force[i];
  keep(log.t);
  for (auto& column : log.force) keep(column);
  for (auto& column : log.position) keep(column);
  for (auto& column : log.velocity) keep(column);
  for (double& t : log.t) t -= t0;
  return c;
}

// Every parameter of ROMEO surge within 3σ of the truth (four parameters: all within 3σ with
// probability ≈ 0.99 for a calibrated σ; the seed is fixed).
void ExpectTruthWithinThreeSigma(const DofIdentification& s) {
  const model::Truth truth = testing::CaseTruth("romeo");
  for (const std::string name : {"m", "k", "kq"}) {
    const ParameterEstimate& e = s.params[FindEstimate(s.params, name)];
    EXPECT_LT(std::abs(e.value - TrueParameter(truth, Dof::kSurge, name)), 3 * e.sigma) << name;
  }
}

TEST(JudgeStartTest, ARecordCutAfterItsStartIsFittedFromItsOwnInitialVelocity) {
  // Cut 6 s after its start the vehicle is at ≈ 0.3 m/s: its first samples say so, and its ξ0
  // is estimated; the trial from rest keeps ξ0 = 0 (the score test does not refute it).
  const IdentifyResult r = Identify(CutCampaign(6.0), IdentifyOptions{});
  const DofIdentification* s = r.Find(Dof::kSurge);
  ASSERT_NE(s, nullptr);
  ASSERT_TRUE(s->output_error && s->output_error->ok()) << s->message;
  ExpectTruthWithinThreeSigma(*s);
  ASSERT_EQ(s->output_error->initial.size(), 2u);
  EXPECT_FALSE(s->output_error->initial[0].xi0_estimated);
  EXPECT_TRUE(s->output_error->initial[1].xi0_estimated);
  EXPECT_GT(s->output_error->initial[1].xi0, 0.2);  // 50 N for 6 s from rest: ≈ 0.3 m/s
  // The free-run score of the cut trial starts from its fitted state: its position RMS is
  // the noise's (1 cm), not a drift from the filter's edge velocity.
  EXPECT_LT(s->fit.trials[1].position_rms, 0.015);
}

TEST(JudgeStartTest, AStartTooSlowForItsFirstSamplesIsRefutedByTheWholeFit) {
  // Cut 0.05 s after its start the vehicle moves at ≈ 2.8 mm/s (50 N on 900 kg): within 3σ of
  // rest over the first samples (σ ≈ 2 mm/s at best), but far outside it over the trial's 120 s.
  // The score test of the fixed ξ0 refutes the start at rest, the fit is redone with every ξ0
  // free, and a note says so.
  const model::Campaign c = CutCampaign(0.05);
  ASSERT_TRUE(PrepareTrial(c.trials[1], 1, c.vehicle, TrialDataOptions{}).starts_at_rest);
  const IdentifyResult r = Identify(c, IdentifyOptions{});
  const DofIdentification* s = r.Find(Dof::kSurge);
  ASSERT_NE(s, nullptr);
  ASSERT_TRUE(s->output_error && s->output_error->ok()) << s->message;
  ExpectTruthWithinThreeSigma(*s);
  for (const TrialInitialState& init : s->output_error->initial) {
    EXPECT_TRUE(init.xi0_estimated) << "trial " << init.trial;
  }
  EXPECT_NEAR(s->output_error->initial[1].xi0, 0.0028, 0.0015);
  const std::vector<std::string>& notes = s->output_error->notes;
  EXPECT_TRUE(std::any_of(notes.begin(), notes.end(), [](const std::string& n) {
    return n.find("score test") != std::string::npos;
  }));
}

}  // namespace
}  // namespace uuvplan::ident
