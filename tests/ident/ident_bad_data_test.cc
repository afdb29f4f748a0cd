// Bad data gets clear errors or warnings, never silent garbage: a trial that does not excite
// the parameters (condition number and the parameters named), too few steady-state segments,
// all-NaN or missing columns, unknown mappings, invalid options, gaps, closed-loop logs.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "ident_cases.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/ident/stats/monte_carlo.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/text/trial_notes_text.h"

namespace uuvplan::ident {
namespace {

using model::Dof;

bool AnyContains(const std::vector<std::string>& v, const std::string& a,
                 const std::string& b = "") {
  for (const auto& s : v) {
    if (s.find(a) != std::string::npos && (b.empty() || s.find(b) != std::string::npos))
      return true;
  }
  return false;
}

std::string ErrorOf(const model::Campaign& c, const IdentifyOptions& o = {}) {
  try {
    Identify(c, o);
  } catch (const model::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(BadDataTest, OneConstantForceDoesNotExciteTheModel) {
  // One steady leg from rest at one force: the drag terms and the inertia cannot all be
  // separated. The result must say which parameters are not identifiable and give the
  // condition number, not report confident numbers.
  const model::Truth truth = testing::CaseTruth("romeo");
  model::TrialDesign d = testing::Segments("const", Dof::kSurge, "surge-front", {{30, 120}});
  const model::Campaign c = VirtualCampaign(truth, {d}, 3);
  const IdentifyResult r = Identify(c, IdentifyOptions{});
  const DofIdentification* s = r.Find(Dof::kSurge);
  ASSERT_NE(s, nullptr);
  EXPECT_NE(s->status, IdentifyStatus::kOk);
  EXPECT_TRUE(AnyContains(s->warnings, "not identifiable", "condition number")) << s->message;
  // The steady-state method saw one segment for its unknowns and says how many it needs.
  EXPECT_TRUE(AnyContains(s->notes, "too few steady-state segments", "at least"));
}

// A log whose force cells are empty for 10 s while the vehicle moves (a recorder that lost
// the command): the last command is held across the hole, as a zero-order hold does, but the
// data does not say it held — a warning names the trial and the span. The same trial logged
// whole gets no such warning.
TEST(BadDataTest, ForceMissingOverSecondsIsAWarningNamingTheSpan) {
  const model::Truth truth = testing::CaseTruth("romeo");
  model::TrialDesign d =
      testing::Segments("legs", Dof::kSurge, "surge-front", {{40, 30}, {80, 30}});
  model::Campaign c = VirtualCampaign(truth, {d}, 3);
  const auto warned = [](const model::Campaign& campaign) {
    const IdentifyResult r = Identify(campaign, IdentifyOptions{});
    const DofIdentification* s = r.Find(Dof::kSurge);
    return s != nullptr && AnyContains(s->warnings, "no force value for", "held across it");
  };
  EXPECT_FALSE(warned(c));
  model::TrialLog& log = c.trials[0].log;
  for (std::size_t i = 0; i < log.t.size(); ++i) {
    if (log.t[i] >= 25.0 && log.t[i] < 35.0) log.force[model::Index(Dof::kSurge)][i] = std::nan("");
  }
  EXPECT_TRUE(warned(c));
}

TEST(BadDataTest, ATrialAtRestIdentifiesNothingAndSaysSo) {
  // 20 s of ROMEO surge with no thrust: the vehicle stays at rest (truth bias 0); no estimator
  // can fit it. That is no usable estimate: status failed, which `uuvplan identify` turns into
  // exit 1, with what would fix it. (A run whose estimates all come out insignificant fails
  // the same way: IdentifyCliTest.ThreeSamplesIdentifyNothingAndExitOne.)
  const model::Truth truth = testing::CaseTruth("romeo");
  model::TrialDesign d = testing::Segments("rest", Dof::kSurge, "surge-front", {{0, 20}});
  const model::Campaign c = VirtualCampaign(truth, {d}, 3);
  const IdentifyResult r = Identify(c, IdentifyOptions{});
  const DofIdentification* s = r.Find(Dof::kSurge);
  ASSERT_NE(s, nullptr);
  for (const auto& e : s->params)
    EXPECT_FALSE(e.significant && e.state == ParameterState::kEstimated) << e.name;
  EXPECT_EQ(s->status, IdentifyStatus::kFailed) << s->message;
  EXPECT_EQ(r.status, IdentifyStatus::kFailed);
  EXPECT_NE(s->message.find("longer trials, steady runs at several levels, a sine"),
            std::string::npos)
      << s->message;
}

TEST(BadDataTest, AllNaNPositionColumnIsAnInputErrorNamingFileAndColumn) {
  const model::Truth truth = testing::CaseTruth("romeo");
  model::Campaign c = VirtualCampaign(truth, {testing::RomeoSurgeDesigns()[3]}, 3);
  c.trials[0].path = "trials/surge_sine.csv";
  for (double& v : c.trials[0].log.position[model::Index(Dof::kSurge)]) v = std::nan("");
  const std::string e = ErrorOf(c);
  EXPECT_NE(e.find("trials/surge_sine.csv"), std::string::npos) << e;
  EXPECT_NE(e.find("pos_surge"), std::string::npos) << e;
  EXPECT_NE(e.find("fewer than 3 samples"), std::string::npos) << e;
}

TEST(BadDataTest, AllNaNVelocityColumnBesideUsablePositionsIsAWarningNamingTheColumn) {
  // cases/vsor yaw logs the compass (pos_yaw) and the gyro (vel_yaw). A gyro column of NaN
  // only must not be dropped silently: the DOF is identified from the compass and warns.
  const model::Truth truth = testing::CaseTruth("vsor");
  model::Campaign c = VirtualCampaign(truth, testing::VsorDesigns(), 3);
  ASSERT_TRUE(c.trials[0].log.HasPosition(Dof::kYaw));
  for (double& v : c.trials[0].log.velocity[model::Index(Dof::kYaw)]) v = std::nan("");
  const IdentifyResult r = Identify(c, IdentifyOptions{});
  const DofIdentification* y = r.Find(Dof::kYaw);
  ASSERT_NE(y, nullptr);
  EXPECT_NE(y->status, IdentifyStatus::kFailed) << y->message;
  EXPECT_EQ(y->status, IdentifyStatus::kWarnings);
  EXPECT_TRUE(AnyContains(y->warnings, "vel_yaw", "no usable value"));
  EXPECT_TRUE(AnyContains(text::NoteTexts(r.trials[0].notes), "vel_yaw"));
}

TEST(BadDataTest, MissingOrEmptyForceColumnIsAnInputError) {
  const model::Truth truth = testing::CaseTruth("romeo");
  model::Campaign c = VirtualCampaign(truth, {testing::RomeoSurgeDesigns()[3]}, 3);
  c.trials[0].path = "trials/x.csv";
  for (double& v : c.trials[0].log.force[model::Index(Dof::kSurge)]) v = std::nan("");
  EXPECT_NE(ErrorOf(c).find("force_surge has no value"), std::string::npos) << ErrorOf(c);
  c.trials[0].log.force[model::Index(Dof::kSurge)].clear();
  EXPECT_NE(ErrorOf(c).find("no column force_surge"), std::string::npos) << ErrorOf(c);
}

TEST(BadDataTest, UnknownMappingIsAnInputError) {
  const model::Truth truth = testing::CaseTruth("romeo");
  model::Campaign c = VirtualCampaign(truth, {testing::RomeoSurgeDesigns()[3]}, 3);
  c.trials[0].mapping = "surge-sideways";
  EXPECT_NE(ErrorOf(c).find("'surge-sideways' is not a mapping"), std::string::npos) << ErrorOf(c);
}

TEST(BadDataTest, InvalidOptionsAreRefusedWithTheViolatedConstraint) {
  const model::Truth truth = testing::CaseTruth("romeo");
  const model::Campaign c = VirtualCampaign(truth, {testing::RomeoSurgeDesigns()[3]}, 3);
  IdentifyOptions o;
  o.data.sg_window = 20;  // even
  EXPECT_NE(ErrorOf(c, o).find("sg_window"), std::string::npos);
  o = IdentifyOptions{};
  o.output_error.step_s = -1;
  EXPECT_NE(ErrorOf(c, o).find("step_s > 0"), std::string::npos);
}

// A log stopped early: its rows up to the `samples`-th surge position sample.
model::TrialLog FirstPositions(model::TrialLog log, int samples) {
  const std::vector<double>& pos = log.position[model::Index(Dof::kSurge)];
  std::size_t rows = 0;
  for (int seen = 0; rows < pos.size() && seen < samples; ++rows) seen += std::isfinite(pos[rows]);
  auto keep = [rows](auto& v) {
    if (v.size() > rows) v.resize(rows);
  };
  keep(log.t);
  keep(log.mapping);
  for (int i = 0; i < model::kNumDofs; ++i) {
    keep(log.force[i]);
    keep(log.position[i]);
    keep(log.velocity[i]);
  }
  return log;
}

TEST(BadDataTest, AFilterWindowLongerThanTheRecordIsAnInputErrorAndTheDefaultOneShortens) {
  // No stretch of the record holds the window: the filter would fit one polynomial to the
  // whole record and the estimators drop every row within a half window of its ends. A window
  // set longer than the record is refused naming the file and the longest allowed; the
  // default window (21–41 points, ref 000 §IV-D) shortens to a short record, and the window
  // recorded is the one used.
  const model::Truth truth = testing::CaseTruth("romeo");
  model::Campaign c = VirtualCampaign(truth, {testing::RomeoSurgeDesigns()[3]}, 3);
  c.trials[0].path = "trials/short.csv";
  IdentifyOptions o;
  o.data.sg_window = 100001;
  const std::string too_long = ErrorOf(c, o);
  EXPECT_NE(too_long.find("trials/short.csv"), std::string::npos) << too_long;
  EXPECT_NE(too_long.find("window (--sg-window) of 100001 points"), std::string::npos) << too_long;
  EXPECT_NE(too_long.find("expected at most"), std::string::npos) << too_long;
  o.data.sg_window = 21;
  EXPECT_EQ(ErrorOf(c, o), "");

  const TrialDataOptions defaults;
  // 7 positions at one force: 21 points for the rate, 9 for the input's time scale, 7 for
  // the record (and none before: every velocity NaN, a fit without rows).
  c.trials[0].log = FirstPositions(c.trials[0].log, 7);
  const TrialData d = PrepareTrial(c.trials[0], 0, c.vehicle, defaults);
  EXPECT_EQ(d.sg_window, 7);
  EXPECT_EQ(d.sg_options.window, 7);
}

TEST(BadDataTest, GapsAreFoundAndReported) {
  // Ref 000 Fig. 14: missing sonar samples between 70–85 s. A 15 s hole in the record is a
  // gap in the report and the identification still succeeds.
  const model::Truth truth = testing::CaseTruth("romeo");
  model::Campaign c = VirtualCampaign(truth, testing::RomeoSurgeDesigns(), 3);
  auto& log = c.trials[3].log;
  for (std::size_t i = 0; i < log.size(); ++i) {
    if (log.t[i] > 70 && log.t[i] < 85) log.position[model::Index(Dof::kSurge)][i] = std::nan("");
  }
  const IdentifyResult r = Identify(c, IdentifyOptions{});
  bool found = false;
  for (const auto& g : r.trials[3].gaps) found = found || (g.t0 < 70.5 && g.t1 > 84.5);
  EXPECT_TRUE(found);
  EXPECT_NE(r.status, IdentifyStatus::kFailed);
  EXPECT_TRUE(AnyContains(text::NoteTexts(r.trials[3].notes), "gap"));
}

TEST(BadDataTest, ClosedLoopLogIsFlaggedAndTheInertiaNotTrusted) {
  // A vehicle held by a PD controller on noisy measurements: the logged force changes at every
  // row with the noise (the signature of closed loop) and correlates with the velocity. The
  // result must say so and mark m unreliable (notes/pitfalls.md).
  model::Truth truth = testing::CaseTruth("romeo");
  const double m = 890, k = 46.9, kq = 306.2, dt = 0.05;
  std::mt19937_64 rng(4);
  std::normal_distribution<double> n01(0, 1);
  model::TrialLog log;
  double x = 0.0, v = 0.0;
  for (int i = 0; i < 4000; ++i) {
    const double t = i * dt;
    const double ref = 2.0 * std::sin(0.05 * t);
    const double x_meas = x + 0.02 * n01(rng);
    const double v_meas = v + 0.01 * n01(rng);
    const double f = 120.0 * (ref - x_meas) - 300.0 * v_meas;
    log.t.push_back(t);
    log.force[model::Index(Dof::kSurge)].push_back(f);
    log.position[model::Index(Dof::kSurge)].push_back(x_meas);
    for (int s = 0; s < 10; ++s) {  // Euler sub-steps of the true dynamics
      const double a = (-k * v - kq * v * std::abs(v) + f) / m;
      x += v * dt / 10;
      v += a * dt / 10;
    }
  }
  model::Campaign c;
  c.vehicle = truth.vehicle;
  model::TrialEntry e;
  e.file = e.path = "closed_loop.csv";
  e.dof = Dof::kSurge;
  e.mapping = "horizontal-all-surge";
  e.log = std::move(log);
  c.trials.push_back(std::move(e));
  IdentifyOptions o;
  o.structures[Dof::kSurge] =
      model::ModelStructure::Standard(truth.vehicle, Dof::kSurge, {}, false);
  const IdentifyResult r = Identify(c, o);
  const DofIdentification* s = r.Find(Dof::kSurge);
  ASSERT_NE(s, nullptr);
  EXPECT_TRUE(s->closed_loop_suspected);
  EXPECT_TRUE(AnyContains(s->warnings, "closed-loop"));
  EXPECT_NE(std::find(s->unreliable.begin(), s->unreliable.end(), "m"), s->unreliable.end());
  // The open-loop virtual trials are not flagged.
  const IdentifyResult open =
      Identify(VirtualCampaign(truth, testing::RomeoSurgeDesigns(), 3), IdentifyOptions{});
  EXPECT_FALSE(open.Find(Dof::kSurge)->closed_loop_suspected);
}

TEST(BadDataTest, ShortHeaveTrialsGiveEstimatesWithinTheirSigmaOrAWarning) {
  // Short heave legs from rest, one per ballast step and alternating sign (15–21 s: the
  // vehicle never settles, τ = m/k_L ≈ 15 s): W, ΔW and η cannot all be separated, the least
  // squares give no answer and the output error must hold some parameters. Every estimated
  // parameter must then either lie within 4σ of the truth (4σ: over ~5 parameters × 6 seeds a
  // right σ exceeds it with probability ~0.2%) or be marked unreliable with a warning — the
  // others are conditional on held a priori values (this once reported kq = 826 ± 35 for a
  // true 430).
  const model::Truth truth = testing::CaseTruth("romeo");
  std::vector<model::TrialDesign> designs;
  for (int i = 0; i < 4; ++i) {
    designs.push_back(testing::Segments("heave_short_" + std::to_string(i), Dof::kHeave,
                                        "vertical-all",
                                        {{i % 2 == 0 ? 40.0 : -40.0, 15.0 + 2.0 * i}}, i));
  }
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    SCOPED_TRACE("seed " + std::to_string(seed));
    const IdentifyResult r = Identify(VirtualCampaign(truth, designs, seed), IdentifyOptions{});
    const DofIdentification* h = r.Find(Dof::kHeave);
    ASSERT_NE(h, nullptr);
    if (h->status == IdentifyStatus::kFailed) {
      EXPECT_FALSE(h->message.empty());
      continue;
    }
    EXPECT_TRUE(AnyContains(h->warnings, "not identifiable", "condition number"));
    if (!h->unreliable.empty()) EXPECT_TRUE(AnyContains(h->warnings, "NOT reliable"));
    for (const auto& e : h->params) {
      if (e.state != ParameterState::kEstimated) continue;
      if (std::find(h->unreliable.begin(), h->unreliable.end(), e.name) != h->unreliable.end())
        continue;
      const double t = TrueParameter(truth, Dof::kHeave, e.name);
      EXPECT_LE(std::abs(e.value - t), 4 * e.sigma)
          << e.name << " = " << e.value << " ± " << e.sigma << " (truth " << t << "), "
          << h->message;
    }
  }
}

}  // namespace
}  // namespace uuvplan::ident
