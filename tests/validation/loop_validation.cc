// Full-size validation of the loop (docs/validation.md "The loop on every vehicle"):
// ROMEO, VSOR, URIS, payload60 (the 60 kg payload) and BlueROV2 in their own pools and N seeded
// random vehicles (tests/support/random_vehicle.h, truth MakeRandomTruth) through the pool verdict
// and planner::RunLoop; tallies of tests/support/loop_validation.h. Exit status 1 when a claim
// fails.
//
//   loop_validation [N=20] [first_seed=1] [max_dofs=2] [cases=1]
//
// Random vehicle i (first_seed ≤ i < first_seed + N) is MakeRandomCase(i, max_dofs) with
// MakeRandomTruth(case, i), its loop seeded with i; the seed cases use loop seed 1 (the CLI's).
#include "support/loop_validation.h"

#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

#include "support/random_vehicle.h"
#include "uuvplan/io/pool_yaml.h"
#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/model/util/text.h"

namespace {

using uuvplan::testing::LoopCaseOutcome;

std::string CasePath(const std::string& c, const std::string& file) {
  return std::string(UUVPLAN_SOURCE_DIR) + "/cases/" + c + "/" + file;
}

}  // namespace

int main(int argc, char** argv) {
  namespace t = uuvplan::testing;
  const int n = argc > 1 ? std::atoi(argv[1]) : 20;
  const std::uint64_t first = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  const int max_dofs = argc > 3 ? std::atoi(argv[3]) : 2;
  const bool seed_cases = argc > 4 ? std::atoi(argv[4]) != 0 : true;
  const int max_repeats = uuvplan::planner::LoopOptions{}.max_repeats;
  t::LoopTally tally;
  auto report = [&](const LoopCaseOutcome& c) {
    tally.Add(c, max_repeats);
    std::cout << t::CaseLine(c) << std::endl;
  };
  if (seed_cases) {
    for (const char* c : {"romeo", "vsor", "uris", "payload60", "bluerov2"}) {
      report(t::RunLoopCase(c, uuvplan::io::ReadTruth(CasePath(c, "truth.yaml")),
                            uuvplan::io::ReadPool(CasePath(c, "pool.yaml")), 1));
    }
  }
  for (std::uint64_t seed = first; seed < first + static_cast<std::uint64_t>(n); ++seed) {
    const t::RandomCase rc = t::MakeRandomCase(seed, max_dofs);
    const t::LoopCaseOutcome c =
        t::RunLoopCase(rc.vehicle.name + " (" + uuvplan::model::Significant(rc.vehicle.mass, 3) +
                           " kg, pool " + uuvplan::model::Significant(rc.pool.length, 3) + " × " +
                           uuvplan::model::Significant(rc.pool.width, 3) + " × " +
                           uuvplan::model::Significant(rc.pool.depth, 3) + " m)",
                       t::MakeRandomTruth(rc, seed), rc.pool, seed);
    report(c);
  }
  std::cout << "\n" << t::TallyText(tally) << std::endl;
  return tally.Pass() ? 0 : 1;
}
