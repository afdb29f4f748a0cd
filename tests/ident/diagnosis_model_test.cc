// The model diagnosis writes out: the extended model in the vehicle file, scored by
// `score` on the same data with the same figures; estimates of the ROMEO effects case within
// 3σ of its truth; held-out gains that are numbers or say why not; parameters in their
// admissible ranges. Real-data tests skip without ../shared and each has a virtual twin.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>

#include "support/hidden_effect.h"
#include "support/real_data.h"
#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/ident/score.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/schedule_json.h"
#include "uuvplan/io/virtual_campaign.h"

namespace uuvplan::ident {
namespace {

namespace fs = std::filesystem;
using uuvplan::testing::RealDataPath;

// A fresh directory under the system's temporary one (removed with its content at the end).
struct TempDir {
  fs::path path;
  explicit TempDir(const std::string& name)
      : path(fs::temp_directory_path() / (name + "-" + std::to_string(::getpid()))) {
    fs::remove_all(path);
    fs::create_directories(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

// Writes `models` of `r` into a vehicle file, reads it back as every command does (vehicle)
// and as `score` does (model), and scores `campaign` with it: the DOF's pooled validate MAE.
double ScoreWritten(const model::Campaign& campaign, const std::vector<DofIdentification>& models,
                    const fs::path& file, double step_s) {
  model::Vehicle written = campaign.vehicle;
  for (const DofIdentification& d : models) written.models[d.dof] = ModelOf(d);
  io::WriteVehicleYaml(file.string(), written, "test");
  EXPECT_NO_THROW(io::ReadVehicle(file.string()));  // loadable by every command
  const model::Truth read = io::ReadTruth(file.string());
  for (const auto& [dof, m] : written.models) {
    for (const auto& [name, sigma] : m.sigma) {  // every parameter with its σ, 2 digits
      EXPECT_NEAR(read.dofs.at(dof).sigma.at(name), sigma, 0.05 * sigma) << name;
    }
  }
  ScoreOptions o;
  o.step_s = step_s;
  const ScoreResult s = ScoreCampaign(campaign, read, o);
  EXPECT_EQ(s.dofs.size(), 1u);
  return s.dofs.empty() ? std::nan("") : s.dofs[0].velocity_mae_validate;
}

// Every parameter of every finding and extended model in its family's admissible range.
void ExpectPhysical(const DiagnosisResult& r) {
  for (const DofIdentification& e : r.extended) {
    EXPECT_EQ(Inadmissible(ModelOf(e)), "") << model::DofName(e.dof);
  }
  for (const CandidateTest& t : r.tests) {
    if (t.accepted) EXPECT_EQ(t.non_physical, "") << t.effect;
  }
}

// Scoring the written models must give diagnosis's own figures: the same free runs of the
// same parameters, rounded in the file one digit past their σ's second (at most σ/200 away).
// On held-out trials the MAE moves to first order: rounding at σ/20 moved the BlueROV
// standard model's by 1.2e-3 relative, so σ/200 keeps it near 1e-4; 1e-3 bounds it. Findings are
// listed by gain; each accepted one lowers the validate MAE, so the first accepted has the
// largest `before` (the standard model's) and the last the smallest `after` (the extended's).
void ExpectScoreReproducesGains(const model::Campaign& campaign, const DiagnosisResult& r,
                                const std::string& name, double step_s) {
  ASSERT_GE(r.findings.size(), 2u);
  double before = 0.0, after = 1e300;
  for (const Finding& f : r.findings) {
    before = std::max(before, f.gain.before);
    after = std::min(after, f.gain.after);
  }
  TempDir dir(name);
  const double standard = ScoreWritten(campaign, r.standard, dir.path / "standard.yaml", step_s);
  const double extended = ScoreWritten(campaign, r.extended, dir.path / "extended.yaml", step_s);
  EXPECT_NEAR(standard, before, 1e-3 * standard);
  EXPECT_NEAR(extended, after, 1e-3 * extended);
  EXPECT_NEAR(extended, r.extended[0].fit.velocity_mae_validate, 1e-3 * extended);
}

// `identify` on the campaign whose vehicle file carries diagnosis's extended model (written
// and read back) fits that model: every finding's parameter estimated again with a σ, within
// one of diagnosis's own σ of its value (the same structure fitted on the same trials from the
// written values: the same optimum up to the file's rounding, σ/200), with the validate MAE that
// `score` gives the written model (1e-3 relative: ExpectScoreReproducesGains's reason).
void ExpectIdentifyRefitsWrittenModel(const model::Campaign& campaign, const DiagnosisResult& r,
                                      const std::string& name, double step_s) {
  ASSERT_EQ(r.extended.size(), 1u);
  TempDir dir(name + "-identify");
  const fs::path file = dir.path / "extended.yaml";
  const double scored = ScoreWritten(campaign, r.extended, file, step_s);
  model::Campaign with_model = campaign;
  with_model.vehicle = io::ReadVehicle(file.string());
  IdentifyOptions o;
  o.dofs = {r.extended[0].dof};
  const IdentifyResult id = Identify(with_model, o);
  ASSERT_EQ(id.dofs.size(), 1u);
  const DofIdentification& d = id.dofs[0];
  ASSERT_NE(d.status, IdentifyStatus::kFailed) << d.message;
  EXPECT_THAT(d.notes, ::testing::Contains(::testing::HasSubstr("fitted in the vehicle file's")));
  for (const Finding& f : r.findings) {
    for (const ParameterEstimate& p : f.params) {
      const ParameterEstimate* q = d.Param(p.name);
      ASSERT_NE(q, nullptr) << p.name;
      EXPECT_EQ(q->state, ParameterState::kEstimated) << p.name;
      EXPECT_GT(q->sigma, 0.0) << p.name;
      EXPECT_NEAR(q->value, p.value, p.sigma) << p.name;
    }
  }
  EXPECT_NEAR(d.fit.velocity_mae_validate, scored, 1e-3 * scored);
}

const Finding* Named(const DiagnosisResult& r, const std::string& effect) {
  for (const Finding& f : r.findings) {
    if (f.effect == effect) return &f;
  }
  return nullptr;
}

// A thrust_map finding compares the three static maps, each physical and scored on the
// validate trials with a σ, and tabulates the chosen one at every command of its tables.
void ExpectStaticMapChosen(const Finding& f) {
  ASSERT_EQ(f.static_maps.size(), 3u);
  for (const StaticMapCandidate& c : f.static_maps) {
    EXPECT_TRUE(c.scored) << c.shape << ": " << c.why;
    EXPECT_TRUE(std::isfinite(c.vs_power_law_sigma)) << c.shape;
    EXPECT_TRUE(c.physical) << c.shape << ": " << c.why;
  }
  ASSERT_FALSE(f.chosen_map.empty());
  for (const CorrectedThrustMap& m : f.thrust_maps) {
    ASSERT_EQ(m.chosen_force.size(), m.rows.size());
    for (std::size_t i = 0; i < m.rows.size(); ++i) {
      EXPECT_TRUE(std::isfinite(m.chosen_force[i])) << m.mapping << " row " << i;
      EXPECT_GE(m.chosen_force[i] * m.rows[i].command, 0.0);  // thrust follows the command's sign
    }
  }
}

// Virtual twin of the BlueROV test below: a thrust map wrong in shape (hidden-effect draw 1)
// plus a thruster lag of 0.25 time constants (the middle of the draws' 0.15–0.35). Diagnosis
// must name both with a gain on the validate trials, give the corrected map and σ for the
// screen's lag, and `score` on the written models must reproduce the gains.
TEST(DiagnosisModelTest, ThrustMapAndLagWrittenOutAndScored) {
  uuvplan::testing::HiddenEffectCase c = uuvplan::testing::DrawHiddenEffectCase("thrust_map", 1);
  c.truth.dofs[c.dof].params["lag"] = c.effect_params["lag"] = 0.25 * c.time_constant_s;
  const model::Campaign campaign = uuvplan::testing::RunHiddenEffectCase(c, 1);
  DiagnoseOptions o = uuvplan::testing::DiagnoseOptionsFor(c);
  o.max_effects = 2;
  const DiagnosisResult r = Diagnose(campaign, o);
  for (const char* effect : {"thrust_map", "thruster_lag"}) {
    const Finding* f = Named(r, effect);
    ASSERT_NE(f, nullptr) << effect;
    EXPECT_EQ(f->gain.on, "validate");
    EXPECT_GT(f->gain.relative, 0.005) << effect;  // DiagnoseOptions::min_gain
    for (const ParameterEstimate& p : f->params) {
      const double truth = c.effect_params.at(p.name);
      EXPECT_NEAR(p.value, truth, 3 * p.sigma) << p.name;
    }
  }
  ASSERT_EQ(Named(r, "thrust_map")->thrust_maps.size(), 2u);  // mappings A and B
  EXPECT_FALSE(Named(r, "thrust_map")->thrust_maps[0].shape.empty());
  ExpectStaticMapChosen(*Named(r, "thrust_map"));
  ASSERT_EQ(r.breakdowns.size(), 1u);
  EXPECT_GT(r.breakdowns[0].lag_sigma_s, 0.0);
  EXPECT_GT(r.breakdowns[0].drift_sigma_per_hour, 0.0);
  ExpectPhysical(r);
  ExpectScoreReproducesGains(campaign, r, "thrust-map-lag", o.output_error.step_s);
  ExpectIdentifyRefitsWrittenModel(campaign, r, "thrust-map-lag", o.output_error.step_s);
}

// The 13 BlueROV runs (campaign_all.yaml; README defects 1 and 2): the thrust table is wrong in
// shape — the delivered torque is close to linear in the command, where the table is square —
// and the torque lags the command. Both named with their held-out gain (thrust map 28%, lag
// 13% on these logs; ≥ 10% asserted, the README's own fits give 20–30% and 10–20%), and `score`
// on the written models reproduces the gains.
TEST(DiagnosisModelTest, RealBluerovThrustMapShapeAndLagScored) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("bluerov-yaw-2016");
  const model::Campaign campaign =
      io::ReadCampaign(RealDataPath("bluerov-yaw-2016/campaign_all.yaml"));
  DiagnoseOptions o;
  o.max_effects = 2;
  const DiagnosisResult r = Diagnose(campaign, o);
  ASSERT_EQ(r.findings.size(), 2u);
  EXPECT_EQ(r.findings[0].effect, "thrust_map");
  EXPECT_EQ(r.findings[1].effect, "thruster_lag");
  for (const Finding& f : r.findings) {
    EXPECT_EQ(f.gain.on, "validate");
    EXPECT_GT(f.gain.relative, 0.10) << f.effect;
  }
  // The README's gains relative to |u| = 0.7 (4.84 at 0.1 … 1.54 at 0.4) are a power law in
  // the nominal torque with p ≈ −0.44 (ln 4.84 / ln(0.181/6.366)); [−0.7, −0.3] allows for
  // its equation-error fits without the lag.
  ASSERT_EQ(r.findings[0].params.size(), 1u);
  EXPECT_GT(r.findings[0].params[0].value, -0.7);
  EXPECT_LT(r.findings[0].params[0].value, -0.3);
  ASSERT_EQ(r.findings[0].thrust_maps.size(), 1u);
  EXPECT_EQ(r.findings[0].thrust_maps[0].shape, "linear in the command");
  // The static map in place of the power law: linear (README defect 1). The dead band and the
  // reverse gain fit better by AIC but predict the validate runs no better than 2σ.
  ExpectStaticMapChosen(r.findings[0]);
  EXPECT_EQ(r.findings[0].chosen_map, "linear");
  ExpectPhysical(r);
  ExpectScoreReproducesGains(campaign, r, "bluerov-all", o.output_error.step_s);
  ExpectIdentifyRefitsWrittenModel(campaign, r, "bluerov-all", o.output_error.step_s);
}

// cases/romeo/truth-effects.yaml (ref 000 Table IV: η 0.73/0.80/0.89, asymmetric surge drag),
// the ROMEO surge and sway schedules (tests/data/romeo, `uuvplan schedule ... --dof surge|sway
// --json`), simulated with seed 7 as `uuvplan simulate --seed 7` does. Every η and drag
// parameter found must lie within 3σ of its truth (the case: 0.741 and 0.808 for 0.80
// and 0.89, 33σ off, before the findings were re-estimated in the final model).
void ExpectRomeoTruthWithin3Sigma(model::Dof dof, const std::string& schedule) {
  const std::string source = UUVPLAN_SOURCE_DIR;
  const model::Truth truth = io::ReadTruth(source + "/cases/romeo/truth-effects.yaml");
  std::vector<model::TrialDesign> designs;
  for (const auto& t : io::ReadScheduleJson(source + "/tests/data/romeo/" + schedule).trials) {
    designs.push_back(t.design);
  }
  TempDir dir("romeo-" + schedule);
  model::VirtualCampaignOptions vo;
  vo.seed = 7;
  io::SimulateCampaign(truth, designs, (dir.path / "c").string(), vo);
  const model::Campaign campaign = io::ReadCampaign((dir.path / "c").string());
  DiagnoseOptions o;
  o.dofs = {dof};
  const DiagnosisResult r = Diagnose(campaign, o);
  const Finding* eta = Named(r, "installation_loss");
  ASSERT_NE(eta, nullptr);
  const std::map<std::string, double>& params = truth.dofs.at(dof).params;
  int checked = 0;
  for (const Finding& f : r.findings) {
    for (const ParameterEstimate& p : f.params) {
      ASSERT_TRUE(params.count(p.name)) << p.name << " is not in the truth";
      EXPECT_NEAR(p.value, params.at(p.name), 3 * p.sigma) << p.name;
      ++checked;
    }
  }
  EXPECT_GE(checked, 4);  // the four η of the DOF's non-open-water directions
  ExpectPhysical(r);
}

TEST(DiagnosisModelTest, RomeoSurgeEffectsWithin3SigmaOfTruth) {
  ExpectRomeoTruthWithin3Sigma(model::Dof::kSurge, "schedule-surge.json");
}

TEST(DiagnosisModelTest, RomeoSwayEtaFound) {
  ExpectRomeoTruthWithin3Sigma(model::Dof::kSway, "schedule-sway.json");
}

// With one fit trial and no validate trial, a held-out gain cannot be scored: the candidate is
// not accepted and the test says why (never a NaN folded to 0). The result does not depend on
// the number of threads.
TEST(DiagnosisModelTest, UnscorableSplitIsSaidAndThreadsDoNotChangeTheResult) {
  uuvplan::testing::HiddenEffectCase c = uuvplan::testing::DrawHiddenEffectCase("thruster_lag", 1);
  c.trials = {c.trials[4]};  // the a_sine trial
  c.use = {model::TrialUse::kFit};
  const model::Campaign campaign = uuvplan::testing::RunHiddenEffectCase(c, 1);
  DiagnoseOptions o = uuvplan::testing::DiagnoseOptionsFor(c);
  o.max_effects = 1;
  o.threads = 1;
  const DiagnosisResult one = Diagnose(campaign, o);
  o.threads = 2;
  const DiagnosisResult two = Diagnose(campaign, o);
  EXPECT_TRUE(one.findings.empty());
  bool said = false;
  for (const CandidateTest& t : one.tests) {
    if (!t.significant) continue;
    EXPECT_TRUE(std::isnan(t.gain)) << t.effect;
    EXPECT_THAT(t.unscored, ::testing::HasSubstr("needs at least 2 fit trials"));
    said = true;
  }
  EXPECT_TRUE(said) << "no significant candidate: the case no longer tests the split";
  ASSERT_EQ(one.tests.size(), two.tests.size());
  for (std::size_t i = 0; i < one.tests.size(); ++i) {
    EXPECT_EQ(one.tests[i].statistic, two.tests[i].statistic) << one.tests[i].effect;
  }
}

}  // namespace
}  // namespace uuvplan::ident
