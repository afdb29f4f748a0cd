// Monte Carlo checks of the reported σ (ident/stats/monte_carlo.h): for cases/romeo (surge, heave,
// yaw), cases/vsor and cases/uris, the same virtual campaign with independent seeds, and for
// every estimator that reports σ the coverage of its 95% intervals and the spread of its
// estimates against its mean σ; and the output-error spread against the Cramér–Rao bound on the
// ROMEO surge sine trial.
//
// The CI runs a seeded subset (30 repetitions, 50 for the CRB: the first repetitions of the
// full run, same seeds), with white and with AR(1) ρ = 0.9 sensor noise; the full size is
// tests/validation/identify_validation.cc
//   build/tests/identify_validation 200 [case|all] [ρ] [lag=T]
// which checks the issue's [90%, 99%] band on every cell; figures in docs/validation.md.
//
// Model selection is off (fixed structures): coverage is a property of an estimator of a given
// model; the 51.02% rule is tested in ident_estimators_test.cc.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>

#include "ident_cases.h"
#include "uuvplan/ident/stats/monte_carlo.h"
#include "uuvplan/text/monte_carlo_table.h"

namespace uuvplan::ident {
namespace {

using model::Dof;

int Repetitions(int dflt) {
  const char* e = std::getenv("UUVPLAN_MC_REPS");
  return e ? std::max(10, std::atoi(e)) : dflt;
}

struct McCase {
  std::string name;
  std::string truth;
  std::vector<model::TrialDesign> designs;
  double ar1 = 0.0;  ///< sensor noise AR(1) coefficient (model::SensorDefects::noise_ar1)
};
void PrintTo(const McCase& c, std::ostream* os) { *os << c.name; }

class CoverageTest : public ::testing::TestWithParam<McCase> {};

TEST_P(CoverageTest, IntervalsCoverTheTruthAndSigmaMatchesTheSpread) {
  const McCase& c = GetParam();
  MonteCarloOptions o;
  o.repetitions = Repetitions(30);
  o.seed = 7;
  o.identify.selection.prune_insignificant = false;
  o.cramer_rao = false;
  model::Truth truth = testing::CaseTruth(c.truth);
  truth.defects.noise_ar1 = c.ar1;
  const MonteCarloReport rep = RunMonteCarlo(truth, c.designs, o);
  std::cout << c.name << ", " << rep.repetitions << " repetitions\n" << text::MonteCarloTable(rep);
  EXPECT_EQ(rep.failures, 0);
  // Per cell: the true coverage of a 95% interval must be at least 90% (the band). With
  // n repetitions the observed coverage of a 90% interval falls below 0.90 − 2.33·√(0.09/n)
  // only 1% of the time: below that, σ is too small.
  // Per estimator: the RMS of (θ̂ − θ)/σ pooled over its parameters is 1 for a right σ, with a
  // standard error of about 1/√(2n) per parameter (~8% at n = 30, less when pooled); bounds
  // [0.75, 1.3] fail when σ is 30% too small (RMS 1.43) or a third too large (0.75).
  std::map<std::string, std::pair<double, int>> pooled;
  for (const CoverageCell& cell : rep.cells) {
    if (cell.estimator == "final") continue;       // the output error, counted once
    if (cell.n < 0.8 * rep.repetitions) continue;  // reported in too few repetitions
    const bool integral_ar1 = c.ar1 > 0 && cell.estimator == "integral_inertia";
    const double se = std::sqrt(0.9 * 0.1 / cell.n);
    EXPECT_GE(cell.coverage(), 0.90 - 2.33 * se)
        << cell.estimator << " " << model::DofName(cell.dof) << " " << cell.name;
    const double ms = (cell.sd * cell.sd + std::pow(cell.mean - cell.truth, 2)) /
                      (cell.mean_sigma * cell.mean_sigma);
    // Under AR(1) the integral method's σ is conservative on VSOR (sd/σ 0.64 at full size: the
    // gyro's ρ from raw − smoothed differences errs high): its coverage is scored, not its RMS.
    // The steady state's σ varies between repetitions under AR(1) (ρ pooled over 3–5 segments,
    // s² on 1 degree of freedom on VSOR): the spread over the mean σ is then not 1 even for a
    // right σ (VSOR at n = 30: 1.54–1.63 with coverage 89–100%; 0.89–0.95 at n = 200), so its
    // coverage is scored, not its RMS.
    if (integral_ar1 || (c.ar1 > 0 && cell.estimator == "steady_state")) continue;
    pooled[cell.estimator].first += ms;
    pooled[cell.estimator].second += 1;
  }
  EXPECT_GE(pooled.count("output_error"), 1u);
  EXPECT_GE(pooled.count("one_step_ls"), 1u);
  for (const auto& [estimator, acc] : pooled) {
    const double rms = std::sqrt(acc.first / acc.second);
    EXPECT_LE(rms, 1.3) << estimator << ": σ too small";
    // Every estimator, the one-step LS included: its σ is a sandwich over a fitted
    // heteroscedastic MA(1) of its residuals (docs/identification.md §4), no longer inflated
    // where the regressor errors grow with the speed (VSOR: RMS 0.6 with the homoscedastic
    // MA(1), 0.88 now; lowest on this subset 0.80, ROMEO yaw).
    EXPECT_GE(rms, 0.75) << estimator << ": σ too large";
  }
}

// The same campaigns with AR(1) sensor noise of ρ = 0.9 (the worst case): every
// estimator's σ must stay calibrated (covariance.h, docs/identification.md).
std::vector<McCase> CoverageCases() {
  std::vector<McCase> white = {{"romeo_surge", "romeo", testing::RomeoSurgeDesigns()},
                               {"romeo_heave", "romeo", testing::RomeoHeaveDesigns()},
                               {"romeo_yaw", "romeo", testing::RomeoYawDesigns()},
                               {"vsor", "vsor", testing::VsorDesigns()},
                               {"uris", "uris", testing::UrisDesigns()}};
  std::vector<McCase> all = white;
  for (McCase c : white) {
    c.name += "_ar1_09";
    c.ar1 = 0.9;
    all.push_back(c);
  }
  return all;
}

INSTANTIATE_TEST_SUITE_P(Cases, CoverageTest, ::testing::ValuesIn(CoverageCases()),
                         [](const ::testing::TestParamInfo<McCase>& info) {
                           return info.param.name;
                         });

TEST(IntegralInertiaCoverageTest, UrisYawPrbsMassIsUnbiasedAndItsSigmaMatchesTheSpread) {
  // URIS yaw alone (steps and PRBS, 12.5 Hz heading, Savitzky–Golay windows of 11 points on the
  // PRBS): the errors-in-variables correction is 22% of the inertia's information, the regime
  // where its second-order variance, the nuisance projection tr(MΣ) and a false ρ̂ of the
  // position noise matter (docs/identification.md §3). 100 seeded campaigns (~1.5 s of CPU).
  // Without those corrections: mean 1.956 for 1.910 (4.6 standard errors), RMS z 1.54,
  // coverage 82.7%; after: 1.920 (1.2 se), RMS z 1.08, coverage 94.9%.
  MonteCarloOptions o;
  o.repetitions = Repetitions(100);
  o.seed = 7;
  o.identify.selection.prune_insignificant = false;
  o.cramer_rao = false;
  const model::Truth truth = testing::CaseTruth("uris");
  const std::vector<model::TrialDesign> all = testing::UrisDesigns();
  const MonteCarloReport rep = RunMonteCarlo(truth, {all[2], all[3]}, o);
  std::cout << text::MonteCarloTable(rep);
  const CoverageCell* cell = rep.Find("integral_inertia", Dof::kYaw, "m");
  ASSERT_NE(cell, nullptr);
  ASSERT_GE(cell->n, 0.9 * rep.repetitions);  // the steady state fails in a few draws
  // Coverage: a true 90% falls below 0.90 − 2.33·√(0.09/n) 1% of the time.
  EXPECT_GE(cell->coverage(), 0.90 - 2.33 * std::sqrt(0.09 / cell->n));
  // Bias: within 3 standard errors of the mean (a correction off by 8% gave 4.6).
  EXPECT_LE(std::abs(cell->mean - cell->truth), 3.0 * cell->sd / std::sqrt(cell->n));
  // RMS of (m̂ − m)/σ: 1 for a right σ, standard error ~1/√(2n) = 7%; [0.75, 1.3] as above.
  const double rms =
      std::sqrt(cell->sd * cell->sd + std::pow(cell->mean - cell->truth, 2)) / cell->mean_sigma;
  EXPECT_LE(rms, 1.3);
  EXPECT_GE(rms, 0.75);
}

TEST(CramerRaoTest, OutputErrorSpreadIsWithin25PercentOfTheBoundOnTheRomeoSurgeSine) {
  // Ref 000 §IV-D's inertia trial (offset 35 N, amplitude 25 N, period 26 s, surge front,
  // 3.33 Hz sonar): the output-error estimates' spread over independent noise must approach
  // the Cramér–Rao bound at the truth. With n repetitions the sample sd has a relative standard
  // error 1/√(2(n − 1)) (10% at n = 50): 25% is 2.5 of them.
  MonteCarloOptions o;
  o.repetitions = Repetitions(50);
  o.seed = 11;
  o.identify.selection.prune_insignificant = false;
  const model::Truth truth = testing::CaseTruth("romeo");
  // The sine never reverses the force: no installation coefficient is excited.
  o.identify.structures[Dof::kSurge] =
      model::ModelStructure::Standard(truth.vehicle, Dof::kSurge, {}, false);
  model::TrialDesign sine = testing::RomeoSurgeDesigns()[3];
  sine.duration = 260;  // two trials' worth: ten periods
  const MonteCarloReport rep = RunMonteCarlo(truth, {sine}, o);
  std::cout << text::MonteCarloTable(rep);
  EXPECT_EQ(rep.failures, 0);
  for (const char* name : {"m", "k", "kq"}) {
    const CoverageCell* cell = rep.Find("output_error", Dof::kSurge, name);
    ASSERT_NE(cell, nullptr) << name;
    ASSERT_GT(cell->crb_sigma, 0.0) << name;
    EXPECT_NEAR(cell->sd / cell->crb_sigma, 1.0, 0.25) << name;
    // The reported σ is the bound at the estimate: within 10% of the bound at the truth.
    EXPECT_NEAR(cell->mean_sigma / cell->crb_sigma, 1.0, 0.1) << name;
  }
}

}  // namespace
}  // namespace uuvplan::ident
