// Closed-loop data: a virtual campaign flown by a speed controller that reacts
// to the noisy measured velocity (the virtual twin of shared/data/tartan-pool-2022), and tartan
// itself with its fit and validate chunks swapped.
//
// Virtual: ROMEO surge (m 890 kg, k 46.9 N·s/m, kq 306.2 N·s²/m², a constant force of −5 N),
// a P controller u = 400·(v_ref − v_meas) at 20 Hz on a DVL-like sensor (10 Hz, σ 0.01 m/s,
// AR(1) ρ = 0.5), v_ref a seeded random staircase in ±0.5 m/s; four 120 s trials.
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <regex>
#include <sstream>

#include "ident/ident_cases.h"
#include "support/real_data.h"
#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/io/io.h"
#include "uuvplan/model/util/seed.h"
#include "uuvplan/text/diagnosis_notes_text.h"
#include "uuvplan/text/trial_notes_text.h"

namespace uuvplan::ident {
namespace {

using model::Dof;
using uuvplan::testing::RealDataPath;

struct Plant {
  double m = 890, k = 46.9, kq = 306.2, bias = -5.0;
  double Accel(double v, double u) const { return (-k * v - kq * v * std::abs(v) + u + bias) / m; }
};

// One trial: RK4 at 0.01 s with the command held over each 0.05 s controller period; the
// controller reads the latest 10 Hz measurement.
// `disturbance`: σ (N) of an unmodelled white force held over each controller period (waves,
// a tether, the other DOFs' coupling: what sets tartan's rows' error, not its sensor).
// `hover`: the set-point stays 0 (the loop only holds the vehicle, as tartan's depth in the
// chunks labelled surge, sway or yaw).
model::TrialLog ClosedLoopTrial(const Plant& p, double rho, std::uint64_t seed,
                                double disturbance = 0.0, bool hover = false) {
  std::mt19937_64 rng(model::SplitMix64(seed));
  std::normal_distribution<double> n01(0.0, 1.0);
  std::uniform_real_distribution<double> ref(-0.5, 0.5);
  constexpr double kSigma = 0.01, kGain = 400.0, kDuration = 120.0, kCmd = 0.05, kStep = 0.01;
  model::TrialLog log;
  const int si = model::Index(Dof::kSurge);
  double v = 0.0, noise = kSigma * n01(rng), v_meas = v + noise, v_ref = 0.0;
  for (int row = 0; row * kCmd <= kDuration + 1e-9; ++row) {
    const double t = row * kCmd;
    if (row % 160 == 0) v_ref = hover ? 0.0 : ref(rng);  // a new set-point every 8 s
    const bool sample = row % 2 == 0;                    // 10 Hz sensor on every other 20 Hz row
    if (sample && row > 0) {
      noise = rho * noise + std::sqrt(1 - rho * rho) * kSigma * n01(rng);
      v_meas = v + noise;
    }
    const double u = kGain * (v_ref - v_meas);
    const double f = u + (disturbance > 0 ? disturbance * n01(rng) : 0.0);
    log.t.push_back(t);
    log.force[si].push_back(u);
    log.velocity[si].push_back(sample ? v_meas : std::nan(""));
    for (int s = 0; s < static_cast<int>(std::lround(kCmd / kStep)); ++s) {
      const double a1 = p.Accel(v, f), a2 = p.Accel(v + 0.5 * kStep * a1, f);
      const double a3 = p.Accel(v + 0.5 * kStep * a2, f), a4 = p.Accel(v + kStep * a3, f);
      v += kStep / 6 * (a1 + 2 * a2 + 2 * a3 + a4);
    }
  }
  return log;
}

// `hover_trials`: trials 0 and 1 (one in each half) hold v = 0 instead of following set-points.
model::Campaign ClosedLoopCampaign(std::uint64_t seed, bool swapped, double disturbance = 0.0,
                                   bool hover_trials = false) {
  model::Campaign c;
  c.vehicle = testing::CaseTruth("romeo").vehicle;
  c.vehicle.sensors[Dof::kSurge] = {std::nullopt, model::SensorSpec{10.0, 0.01}};
  for (int i = 0; i < 4; ++i) {
    model::TrialEntry e;
    e.file = "closed_loop_" + std::to_string(i) + ".csv";
    e.dof = Dof::kSurge;
    e.mapping = c.vehicle.mappings.front().name;
    e.use = (i % 2 == 0) != swapped ? model::TrialUse::kFit : model::TrialUse::kValidate;
    e.start = 180.0 * i;
    e.has_start = true;
    // The disturbance (if any) in trials 2 and 3 only: one in each half.
    e.log = ClosedLoopTrial(Plant{}, 0.5, model::StreamSeed(seed, i), i >= 2 ? disturbance : 0.0,
                            hover_trials && i < 2);
    c.trials.push_back(std::move(e));
  }
  return c;
}

IdentifyOptions SurgeOptions(const model::Vehicle& v) {
  IdentifyOptions o;
  o.dofs = {Dof::kSurge};
  // One mapping, no installation coefficient: η·m is all a single mapping shows.
  o.structures[Dof::kSurge] = model::ModelStructure::Standard(v, Dof::kSurge, {}, false);
  o.selection.prune_insignificant = false;
  return o;
}

const ParameterEstimate& Param(const DofIdentification& d, const std::string& name) {
  const ParameterEstimate* e = d.Param(name);
  EXPECT_NE(e, nullptr) << name;
  static const ParameterEstimate none;
  return e ? *e : none;
}

TEST(ClosedLoopTest, VirtualFeedbackIsIdentifiedByInstrumentsAndSwapsAgree) {
  std::vector<DofIdentification> both;
  for (bool swapped : {false, true}) {
    const model::Campaign c = ClosedLoopCampaign(3, swapped);
    const IdentifyResult r = Identify(c, SurgeOptions(c.vehicle));
    ASSERT_EQ(r.dofs.size(), 1u);
    const DofIdentification& d = r.dofs[0];
    EXPECT_TRUE(d.closed_loop_suspected);
    ASSERT_EQ(d.estimator, FinalEstimator::kClosedLoopIv) << d.message;
    EXPECT_EQ(FinalEstimatorName(d.estimator), "closed_loop_iv");
    const Plant truth;
    // Every estimate within 3σ of the truth (a 0.3% chance per parameter for a right σ).
    for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
             {"m", truth.m}, {"k", truth.k}, {"kq", truth.kq}, {"bias", truth.bias}}) {
      const ParameterEstimate& e = Param(d, name);
      EXPECT_LE(std::abs(e.value - value), 3 * e.sigma)
          << name << " " << e.value << " ± " << e.sigma;
      std::cout << name << " " << e.value << " ± " << e.sigma << " (truth " << value << ")\n";
    }
    both.push_back(d);
  }
  const ParameterEstimate &a = Param(both[0], "k"), &b = Param(both[1], "k");
  EXPECT_LE(std::abs(a.value - b.value), 3 * std::hypot(a.sigma, b.sigma))
      << a.value << " ± " << a.sigma << " vs " << b.value << " ± " << b.sigma;
}

// Virtual twin of RealTartanSwappedFitAndValidateAgreeOnSurgeDrag's cause: trials whose rows'
// error is set by an unmodelled force, not by the sensor. Trials 2 and 3 (one fit, one validate)
// carry a white force of σ 500 N held over each controller period, which makes their rows'
// residual variance far above their sensor's. Weighted by the sensor, every trial counts alike
// and the disturbed fit trial swamps the quiet one (seed 5: k 82.3 ± 89.5, as tartan's swapped
// half gave 165.9 ± 85.4); weighted by its residuals (the default), 43.9 ± 20.3. Both must hold
// the truth within 3σ (sandwich σ, valid under either weighting), and the residual weighting
// must be at least twice as tight (it is 4.4× on this seed).
TEST(ClosedLoopTest, TrialsDisturbedByAnUnmodelledForceAreWeightedByTheirResiduals) {
  const model::Campaign c = ClosedLoopCampaign(5, false, 500.0);
  const Plant truth;
  std::map<bool, double> sigma_k;
  for (bool by_residuals : {false, true}) {
    IdentifyOptions o = SurgeOptions(c.vehicle);
    o.closed_loop_iv.weight_by_residuals = by_residuals;
    const IdentifyResult r = Identify(c, o);
    ASSERT_EQ(r.dofs.size(), 1u);
    const DofIdentification& d = r.dofs[0];
    ASSERT_EQ(d.estimator, FinalEstimator::kClosedLoopIv) << d.message;
    ASSERT_TRUE(d.closed_loop_iv.has_value());
    EXPECT_EQ(d.closed_loop_iv->residual_weights, by_residuals);
    for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
             {"m", truth.m}, {"k", truth.k}, {"bias", truth.bias}}) {
      const ParameterEstimate& e = Param(d, name);
      EXPECT_LE(std::abs(e.value - value), 3 * e.sigma)
          << name << " " << e.value << " ± " << e.sigma;
    }
    sigma_k[by_residuals] = Param(d, "k").sigma;
    std::cout << (by_residuals ? "by residuals" : "by sensor") << ": k " << Param(d, "k").value
              << " ± " << sigma_k[by_residuals] << "\n";
  }
  EXPECT_LT(sigma_k[true], 0.5 * sigma_k[false]);
}

// A recorder backlog (tartan chunk_00: 4.6 s of navigation rows before the first wrench row):
// the velocity was logged but the force was not. Holding the first command back over those
// seconds invents a force; the trial starts at its first force row instead, and the estimates
// are those of the log without the backlog. Before: the first command was held back to the
// first row and the backlog's motion (here a 0.3 m/s sine the held command does not drive)
// entered the rows and moved every estimate.
TEST(ClosedLoopTest, MeasurementsBeforeTheFirstForceRowAreNotUsed) {
  const model::Campaign plain = ClosedLoopCampaign(3, false);
  model::Campaign backlog = plain;
  constexpr double kBacklog = 5.0;  // s, 50 velocity rows at 10 Hz without a force value
  const int si = model::Index(Dof::kSurge);
  model::TrialLog& log = backlog.trials[0].log;
  model::TrialLog with;
  for (int i = 0; i < 50; ++i) {
    with.t.push_back(0.1 * i);
    with.force[si].push_back(std::nan(""));
    with.velocity[si].push_back(0.3 * std::sin(0.1 * i));
  }
  for (std::size_t i = 0; i < log.t.size(); ++i) {
    with.t.push_back(log.t[i] + kBacklog);
    with.force[si].push_back(log.force[si][i]);
    with.velocity[si].push_back(log.velocity[si][i]);
  }
  log = with;
  const TrialData d = PrepareTrial(backlog.trials[0], 0, backlog.vehicle, TrialDataOptions{});
  EXPECT_DOUBLE_EQ(d.time_offset, kBacklog);
  ASSERT_FALSE(d.velocity.t.empty());
  EXPECT_GE(d.velocity.t.front(), 0.0);
  EXPECT_THAT(text::NoteTexts(d.notes),
              ::testing::Contains(::testing::HasSubstr("precede its first force row")));
  const IdentifyResult a = Identify(plain, SurgeOptions(plain.vehicle));
  const IdentifyResult b = Identify(backlog, SurgeOptions(backlog.vehicle));
  ASSERT_EQ(a.dofs.size(), 1u);
  ASSERT_EQ(b.dofs.size(), 1u);
  for (const char* name : {"m", "k", "kq", "bias"}) {
    const ParameterEstimate &x = Param(a.dofs[0], name), &y = Param(b.dofs[0], name);
    // The same rows up to the rounding of t + 5 − 5 (1e-15 s): equal to a millionth of σ.
    EXPECT_NEAR(x.value, y.value, 1e-6 * x.sigma) << name;
    EXPECT_NEAR(x.sigma, y.sigma, 1e-6 * x.sigma) << name;
  }
}

// The virtual twin of DiagnosisTest.RealClosedLoopLogsWithoutClockAreQualified (tartan: closed
// loop, no trial start times): the diagnosis puts the closed-loop caveat beside its findings and
// neither tests nor quotes a drift over a campaign clock the campaign does not give.
TEST(ClosedLoopTest, VirtualClosedLoopWithoutClockIsQualifiedByDiagnosis) {
  model::Campaign c = ClosedLoopCampaign(3, false);
  for (auto& e : c.trials) e.has_start = false;
  DiagnoseOptions o;
  o.dofs = {Dof::kSurge};
  o.identify = SurgeOptions(c.vehicle);
  const DiagnosisResult r = Diagnose(c, o);
  ASSERT_EQ(r.warnings.size(), 1u);
  EXPECT_THAT(text::NoteText(r.warnings[0]),
              ::testing::HasSubstr("surge: closed-loop data suspected"));
  ASSERT_EQ(r.breakdowns.size(), 1u);
  EXPECT_TRUE(std::isnan(r.breakdowns[0].drift_per_hour));
  for (const CandidateTest& t : r.tests) EXPECT_NE(t.effect, "parameter_drift");
  EXPECT_THAT(text::NoteTexts(r.notes),
              ::testing::Contains(::testing::HasSubstr("parameter_drift not tested")));
}

TEST(ClosedLoopTest, InstrumentalIntervalsCoverTheTruth) {
  // 40 seeded campaigns: a 95% interval covers a true 90% below 0.90 − 2.33·√(0.09/40) = 0.795
  // only 1% of the time; below that the σ (or the estimator) is wrong.
  constexpr int kReps = 40;
  const Plant truth;
  std::map<std::string, int> covered, reported;
  std::map<std::string, double> z2;
  for (int rep = 0; rep < kReps; ++rep) {
    const model::Campaign c = ClosedLoopCampaign(100 + rep, false);
    const IdentifyResult r = Identify(c, SurgeOptions(c.vehicle));
    ASSERT_EQ(r.dofs.size(), 1u);
    const DofIdentification& d = r.dofs[0];
    if (d.estimator != FinalEstimator::kClosedLoopIv) continue;
    for (const auto& [name, value] : std::vector<std::pair<std::string, double>>{
             {"m", truth.m}, {"k", truth.k}, {"kq", truth.kq}, {"bias", truth.bias}}) {
      const ParameterEstimate* e = d.Param(name);
      if (!e || e->state != ParameterState::kEstimated) continue;
      ++reported[name];
      covered[name] += std::abs(e->value - value) <= 1.959963984540054 * e->sigma;
      z2[name] += std::pow((e->value - value) / e->sigma, 2);
    }
  }
  // And the RMS of (θ̂ − θ)/σ: 1 for a right σ, standard error ~1/√80 = 0.11 at n = 40. Above
  // 1.3 σ is too small; below 0.5 it is twice too large. Seed 100–139: m 0.77, k 0.85,
  // kq 0.84, bias 0.58 (the MA(1) sandwich is conservative for the bias).
  for (const char* name : {"m", "k", "kq", "bias"}) {
    const double rms = std::sqrt(z2[name] / std::max(1, reported[name]));
    std::cout << name << ": " << covered[name] << "/" << reported[name] << " covered, RMS z " << rms
              << "\n";
    ASSERT_GE(reported[name], 36) << name << ": the instrumental estimate in too few campaigns";
    EXPECT_GE(covered[name], 0.795 * reported[name])
        << name << " " << covered[name] << "/" << reported[name];
    EXPECT_LE(rms, 1.3) << name;
    EXPECT_GE(rms, 0.5) << name;
  }
}

// tartan's campaign with fit and validate exchanged, written beside a copy with absolute paths.
std::string SwappedTartan(const std::filesystem::path& dir) {
  const std::string src = RealDataPath("tartan-pool-2022/campaign.yaml");
  const std::string base = std::filesystem::path(src).parent_path().string() + "/";
  std::ifstream in(src);
  std::stringstream text;
  text << in.rdbuf();
  std::string s = std::regex_replace(text.str(), std::regex("use: fit"), "use: TMP");
  s = std::regex_replace(s, std::regex("use: validate"), "use: fit");
  s = std::regex_replace(s, std::regex("use: TMP"), "use: validate");
  s = std::regex_replace(s, std::regex("file: trials/"), "file: " + base + "trials/");
  s = std::regex_replace(s, std::regex("vehicle: vehicle.yaml"),
                         "vehicle: " + base + "vehicle.yaml");
  const std::string out = (dir / "campaign_swapped.yaml").string();
  std::ofstream(out) << s;
  return out;
}

TEST(ClosedLoopTest, RealTartanSwappedFitAndValidateAgreeOnSurgeDrag) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("tartan-pool-2022");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("uuvplan_tartan_swap_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  IdentifyOptions o;
  o.dofs = {Dof::kSurge, Dof::kHeave};
  std::vector<IdentifyResult> runs;
  for (const std::string& path :
       {RealDataPath("tartan-pool-2022/campaign.yaml"), SwappedTartan(dir)}) {
    runs.push_back(Identify(io::ReadCampaign(path), o));
  }
  std::filesystem::remove_all(dir);
  ASSERT_EQ(runs[0].dofs.size(), 2u);
  ASSERT_EQ(runs[1].dofs.size(), 2u);
  for (const IdentifyResult& r : runs) {
    for (const DofIdentification& d : r.dofs) {
      EXPECT_TRUE(d.closed_loop_suspected);
      EXPECT_EQ(d.estimator, FinalEstimator::kClosedLoopIv) << d.message;
    }
  }
  // Before: 140.9 ± 1.8 against 75.0 ± 1.0 N·s/m (32σ apart). Same vehicle, same afternoon:
  // within 3 combined σ, and on two informative halves: each k at least 3σ from 0 (with the
  // rows weighted by the sensor the swapped half gave 165.9 ± 85.4, agreeing only because it
  // said nothing; weighted by their residuals, 116.8 ± 15.5 against 86.8 ± 16.3; 119.2 ± 12.3
  // against 90.1 ± 18.2 since trials start at their first force row).
  const ParameterEstimate &a = Param(runs[0].dofs[0], "k"), &b = Param(runs[1].dofs[0], "k");
  EXPECT_GT(a.value, 3 * a.sigma);
  EXPECT_GT(b.value, 3 * b.sigma);
  EXPECT_LE(std::abs(a.value - b.value), 3 * std::hypot(a.sigma, b.sigma))
      << a.value << " ± " << a.sigma << " vs " << b.value << " ± " << b.sigma;
  // The heave buoyancy both ways, consistent with each other within 3 combined σ.
  const ParameterEstimate &ha = Param(runs[0].dofs[1], "bias"),
                          &hb = Param(runs[1].dofs[1], "bias");
  EXPECT_LE(std::abs(ha.value - hb.value), 3 * std::hypot(ha.sigma, hb.sigma));
  std::cout << "surge k " << a.value << " ± " << a.sigma << " / " << b.value << " ± " << b.sigma
            << "; heave bias " << ha.value << " ± " << ha.sigma << " / " << hb.value << " ± "
            << hb.sigma << "\n";
}

// Virtual twin of RealTartanHeaveBiasOfEveryChunkIsTheForceThatHoldsDepth: each half of the
// campaign holds one trial where the loop only holds the vehicle (v_ref = 0: the command sits
// near the force that holds it, 4.5 N against the −5 N bias) and one that follows set-points.
// The residual weights let the quiet held trial dominate (tartan: −7.89 ± 0.14 N over all
// chunks sits on the held chunks' −7.84); the bias must still be the truth within 3σ in both
// halves, and the halves agree within 3 combined σ.
TEST(ClosedLoopTest, VirtualHeldAndDrivenTrialsGiveTheBiasBothWays) {
  const Plant truth;
  std::vector<ParameterEstimate> bias;
  for (bool swapped : {false, true}) {
    const model::Campaign c = ClosedLoopCampaign(3, swapped, 0.0, true);
    const IdentifyResult r = Identify(c, SurgeOptions(c.vehicle));
    ASSERT_EQ(r.dofs.size(), 1u);
    ASSERT_EQ(r.dofs[0].estimator, FinalEstimator::kClosedLoopIv) << r.dofs[0].message;
    bias.push_back(Param(r.dofs[0], "bias"));
    EXPECT_LE(std::abs(bias.back().value - truth.bias), 3 * bias.back().sigma)
        << bias.back().value << " ± " << bias.back().sigma;
    std::cout << "bias " << bias.back().value << " ± " << bias.back().sigma << "\n";
  }
  EXPECT_LE(std::abs(bias[0].value - bias[1].value), 3 * std::hypot(bias[0].sigma, bias[1].sigma));
}

// tartan's 16 chunks all identified in heave (every chunk logs the depth loop's force and
// motion), the even chunks fit (or, `swapped`, the odd ones): the rows the data's README fitted
// its "−8.46 ± 0.16 N" on.
std::string AllChunksInHeave(const std::filesystem::path& dir, bool swapped) {
  std::ifstream in(swapped ? SwappedTartan(dir) : RealDataPath("tartan-pool-2022/campaign.yaml"));
  std::stringstream text;
  text << in.rdbuf();
  std::string s = std::regex_replace(text.str(), std::regex("dof: [a-z]+"), "dof: heave");
  s = std::regex_replace(s, std::regex("mapping: tam-[a-z]+"), "mapping: tam-heave");
  if (!swapped) {
    const std::string base = std::filesystem::path(RealDataPath("tartan-pool-2022/campaign.yaml"))
                                 .parent_path()
                                 .string() +
                             "/";
    s = std::regex_replace(s, std::regex("file: trials/"), "file: " + base + "trials/");
    s = std::regex_replace(s, std::regex("vehicle: vehicle.yaml"),
                           "vehicle: " + base + "vehicle.yaml");
  }
  const std::string out = (dir / (swapped ? "heave_odd.yaml" : "heave_even.yaml")).string();
  std::ofstream(out) << s;
  return out;
}

// The claim "heave bias −8 ± 1 N holds", on the rows the claim was computed on. campaign.yaml's
// heave trials (chunks 2, 6 fit; 5, 7 validate) are all chunks where the depth was driven
// (commands −14…+33 N): there the linear thrust map's bias takes up the map's curvature (a
// concave map needs a larger mean command for the same mean thrust) and the drag times the
// asymmetric motion (the buoyant vehicle rises faster than it sinks): −9.5 ± 1.1 N, swapped
// −10.5 ± 1.2 N (RealTartanSwappedFitAndValidateAgreeOnSurgeDrag). The eight chunks where
// the depth was only held (commands 4…11 N, |w| ≈ 0.01 m/s) measure the force that holds depth
// directly; over all 16 chunks, each half of the campaign must give −8 ± 1 N, and the two halves
// must agree within 3 combined σ (docs/validation.md, tartan heave).
TEST(ClosedLoopTest, RealTartanHeaveBiasOfEveryChunkIsTheForceThatHoldsDepth) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("tartan-pool-2022");
  const std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                    ("uuvplan_tartan_heave_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  IdentifyOptions o;
  o.dofs = {Dof::kHeave};
  std::vector<ParameterEstimate> bias;
  for (bool swapped : {false, true}) {
    const IdentifyResult r = Identify(io::ReadCampaign(AllChunksInHeave(dir, swapped)), o);
    ASSERT_EQ(r.dofs.size(), 1u);
    EXPECT_EQ(r.dofs[0].estimator, FinalEstimator::kClosedLoopIv) << r.dofs[0].message;
    bias.push_back(Param(r.dofs[0], "bias"));
    std::cout << (swapped ? "odd" : "even") << " chunks fit: heave bias " << bias.back().value
              << " ± " << bias.back().sigma << " N\n";
  }
  std::filesystem::remove_all(dir);
  for (const ParameterEstimate& b : bias) {
    EXPECT_LE(std::abs(b.value - (-8.0)), 1.0) << b.value << " ± " << b.sigma;  // the claim
  }
  EXPECT_LE(std::abs(bias[0].value - bias[1].value), 3 * std::hypot(bias[0].sigma, bias[1].sigma));
}

}  // namespace
}  // namespace uuvplan::ident
