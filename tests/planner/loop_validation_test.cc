// The loop on every vehicle, CI subset of tests/validation/loop_validation.cc
// (docs/validation.md "The loop on every vehicle"): URIS in its own pool and random vehicles 1,
// 2 and 4 (tests/support/random_vehicle.h, two DOFs each). Seed 4's heave is determined but
// short of the 5% target in its pool: part, and its stuck loop is outside the hostable part.
#include "support/loop_validation.h"

#include <gtest/gtest.h>

#include <string>

#include "support/random_vehicle.h"
#include "uuvplan/io/pool_yaml.h"
#include "uuvplan/io/truth_yaml.h"

namespace uuvplan::testing {
namespace {

std::string CaseFile(const std::string& c, const std::string& file) {
  return std::string(UUVPLAN_SOURCE_DIR) + "/cases/" + c + "/" + file;
}

// The loop's claims on one case: the verdict and the loop agree; a converged loop has
// every final parameter of interest within 3σ of the truth (on this subset all are: the 95% of
// the issue is over the full-size run); otherwise a non-zero status with its reason; no design
// runs more than LoopOptions::max_repeats times without new information.
void CheckCase(const LoopCaseOutcome& c) {
  SCOPED_TRACE(CaseLine(c));
  EXPECT_TRUE(c.agree);
  if (c.status == planner::LoopStatus::kConverged) {
    EXPECT_FALSE(c.interest.empty());
    for (const auto& e : c.interest) EXPECT_TRUE(e.within3) << e.name;
  } else {
    EXPECT_FALSE(c.message.empty());
  }
  EXPECT_LE(c.most_repeats, planner::LoopOptions{}.max_repeats);
}

TEST(LoopValidation, Uris) {
  const LoopCaseOutcome c = RunLoopCase("uris", io::ReadTruth(CaseFile("uris", "truth.yaml")),
                                        io::ReadPool(CaseFile("uris", "pool.yaml")), 1);
  CheckCase(c);
  EXPECT_TRUE(c.hosted);
  EXPECT_EQ(c.status, planner::LoopStatus::kConverged);  // docs/validation.md: 9 trials
}

// The open-frame ROV most labs fly (cases/bluerov2: geometry-derived mappings, reversible
// T200s) in its 10 × 5 × 2.5 m tank, surge (the seeded subset; every DOF at full size in
// docs/validation.md, "The loop on every vehicle"): hosted, converged, and every parameter the
// last fit estimated — not only those of interest — within 3σ of the truth.
TEST(LoopValidation, BlueRov2SurgeEveryParameterWithinThreeSigma) {
  model::Truth truth = io::ReadTruth(CaseFile("bluerov2", "truth.yaml"));
  for (auto it = truth.dofs.begin(); it != truth.dofs.end();) {
    it = it->first == model::Dof::kSurge ? std::next(it) : truth.dofs.erase(it);
  }
  const LoopCaseOutcome c =
      RunLoopCase("bluerov2", truth, io::ReadPool(CaseFile("bluerov2", "pool.yaml")), 1);
  CheckCase(c);
  EXPECT_TRUE(c.hosted) << c.verdict;
  ASSERT_EQ(c.status, planner::LoopStatus::kConverged) << c.message;
  ASSERT_GE(c.every.size(), 3u);  // m, k, kq at least
  for (const auto& e : c.every) {
    EXPECT_TRUE(e.within3) << e.name << " " << e.value << " ± " << e.sigma << ", truth " << e.truth;
  }
}

TEST(LoopValidation, RandomVehicles) {
  for (std::uint64_t seed : {1, 2}) {  // 4: its own test below
    const RandomCase rc = MakeRandomCase(seed, 2);
    CheckCase(RunLoopCase(rc.vehicle.name, MakeRandomTruth(rc, seed), rc.pool, seed));
  }
}

// Vehicle 4's heave: determined over the whole box (ref 000's 51%) but not to the loop's 5%
// target everywhere (ReachTarget): the verdict says part, not all, and the loop, stuck on heave
// kq, ends infeasible "outside the part of the a priori box the pool hosts" — before the
// verdict judged at the target, "CAN host" and "stuck" contradicted each other here.
TEST(LoopValidation, PoolShortOfTheTargetIsPartAndItsStuckLoopIsOutside) {
  const RandomCase rc = MakeRandomCase(4, 2);
  const LoopCaseOutcome c = RunLoopCase(rc.vehicle.name, MakeRandomTruth(rc, 4), rc.pool, 4);
  EXPECT_EQ(c.hostability, planner::Hostability::kPart) << c.verdict;
  EXPECT_EQ(c.status, planner::LoopStatus::kInfeasible) << c.message;
  EXPECT_NE(c.message.find("outside the part"), std::string::npos) << c.message;
}

TEST(LoopValidation, RandomTruthIsSeededAndInsideThePhysicalRanges) {
  const RandomCase rc = MakeRandomCase(7, 4);
  const model::Truth a = MakeRandomTruth(rc, 7), b = MakeRandomTruth(rc, 7);
  ASSERT_EQ(a.dofs.size(), rc.dofs.size());
  for (const auto& [dof, t] : a.dofs) {
    EXPECT_EQ(t.params, b.dofs.at(dof).params);
    const auto mb = rc.vehicle.InertiaBounds(dof);
    EXPECT_GE(t.params.at("m"), mb[0]);
    EXPECT_LE(t.params.at("m"), mb[1]);
    EXPECT_GT(t.params.at("k"), 0.0);
    EXPECT_GT(t.params.at("kq"), 0.0);
  }
}

}  // namespace
}  // namespace uuvplan::testing
