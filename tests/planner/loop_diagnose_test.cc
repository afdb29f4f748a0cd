// `loop --diagnose` (planner::LoopOptions::diagnose) on a truth whose thrusters lag the command
// by 0.15 s and whose delivered force is wrong in shape (∝ |force|^0.7 where the vehicle file
// says ∝ |force|): the loop on the standard model cannot converge on it; with diagnosis it names
// both effects, adds them to the model it identifies, and ends with every parameter — the
// effects' included — within 3σ of the truth. Seeded subset of tests/validation/
// loop_diagnose_validation.cc (full size in docs/validation.md).
#include <gtest/gtest.h>

#include <cstdint>
#include <map>
#include <set>
#include <string>

#include "planner/planner_test_util.h"
#include "support/diagnosed_loop.h"
#include "uuvplan/io/io.h"

namespace uuvplan::planner {
namespace {

using model::Dof;

model::Truth UrisWithLagAndThrustMap() {
  return uuvplan::testing::WithLagAndThrustMap(
      io::ReadTruth(testing::CasePath("uris", "truth.yaml")), Dof::kSurge, 0.15, -0.3, 10.0);
}

// `loop --diagnose` on URIS surge with the two hidden effects, one run per seed for every test.
const uuvplan::testing::DiagnosedLoopOutcome& UrisDiagnosedLoop(std::uint64_t seed) {
  static std::map<std::uint64_t, uuvplan::testing::DiagnosedLoopOutcome> runs;
  auto it = runs.find(seed);
  if (it == runs.end()) {
    it = runs.emplace(seed,
                      uuvplan::testing::RunDiagnosedLoop(
                          UrisWithLagAndThrustMap(),
                          io::ReadPool(testing::CasePath("uris", "pool.yaml")), Dof::kSurge, seed))
             .first;
  }
  return it->second;
}

// URIS surge (seed 004, 59 kg, time constant m/k 3 s) with the two hidden effects; the thrust
// map's reference 10 N is above every force the loop plans, so the diagnosis states it at its
// own (the check compares at the estimate's reference). The full-size run (docs/validation.md)
// passes in fewer than 95% of seeds, so seeds 1 and 6 check the method working, not its rate.
// ~3–5 s per seed.
TEST(LoopDiagnoseTest, UrisSurgeNamesLagAndThrustMapAndEndsWithinThreeSigma) {
  for (std::uint64_t seed : {1, 6}) {
    const uuvplan::testing::DiagnosedLoopOutcome& out = UrisDiagnosedLoop(seed);
    SCOPED_TRACE("seed " + std::to_string(seed) + ": " + out.Line());
    EXPECT_TRUE(out.result.converged) << out.result.message;
    EXPECT_EQ(out.effects, (std::set<std::string>{"thruster_lag", "thrust_map"}));
    ASSERT_FALSE(out.params.empty());
    for (const auto& p : out.params) {
      // 3σ: the loop's σ are calibrated (docs/validation.md), so a parameter off by more is a
      // wrong model, not chance (0.27% per parameter).
      EXPECT_LE(std::abs(p.Sigmas()), 3.0)
          << p.name << " " << p.value << " ± " << p.sigma << ", truth " << p.truth;
    }
  }
}

// What entered is in the final identification's structure, and each effect entered with the
// held-out gain a finding needs (DiagnoseOptions::min_gain) and its parameters (seed 1's run
// of the test above).
TEST(LoopDiagnoseTest, TheEffectsEnterTheIdentificationWithTheirGain) {
  const uuvplan::testing::DiagnosedLoopOutcome& out = UrisDiagnosedLoop(1);
  const ident::DofIdentification* id = out.result.estimates.Find(Dof::kSurge);
  ASSERT_NE(id, nullptr);
  EXPECT_TRUE(id->structure.Has(model::param::kLag));
  EXPECT_TRUE(id->structure.Has(model::param::kThrustExponent));
  int entered = 0;
  for (const auto& it : out.result.iterations) {
    for (const auto& e : it.effects_entered) {
      ++entered;
      EXPECT_TRUE(e.gain.scored) << e.effect;
      EXPECT_GT(e.gain.relative, 0.005) << e.effect << ": DiagnoseOptions::min_gain";
      EXPECT_FALSE(e.params.empty()) << e.effect;
    }
  }
  EXPECT_GE(entered, 2);
}

// The same loop on the standard model cannot explain the trials: it must not claim convergence
// (it refuses: the output-error residuals stay correlated, "the model misses an effect"). ~2 s.
TEST(LoopDiagnoseTest, WithoutDiagnosisTheLoopRefusesTheStandardModel) {
  LoopOptions o;
  o.step.dofs = {Dof::kSurge};
  const LoopResult r =
      RunLoop(UrisWithLagAndThrustMap(), io::ReadPool(testing::CasePath("uris", "pool.yaml")), o);
  EXPECT_FALSE(r.converged) << r.message;
  EXPECT_EQ(r.status, LoopStatus::kRefused) << r.message;
}

}  // namespace
}  // namespace uuvplan::planner
