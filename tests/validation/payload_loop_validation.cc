// Full-size validation of a payload on a known vehicle (docs/validation.md "A payload on a
// known vehicle"): per loop seed, payload60 from scratch (cases/payload60/truth.yaml) and as its
// skid on the frame `loop` identified (on-frame-truth.yaml), in the same pool, through the pool
// verdict and planner::RunLoop. Claims: the known-frame loop converges on every seed, with
// fewer trials and less pool time than from scratch (than the scratch loop took to converge, or
// where it did not converge), and ≥ 95% of its final parameters of interest within 3σ of the
// truth. Exit status 1 when a claim fails.
//
//   payload_loop_validation [N=8] [first_seed=1]
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <string>

#include "support/loop_validation.h"
#include "uuvplan/io/pool_yaml.h"
#include "uuvplan/io/truth_yaml.h"

namespace {

std::string Payload60(const std::string& file) {
  return std::string(UUVPLAN_SOURCE_DIR) + "/cases/payload60/" + file;
}

}  // namespace

int main(int argc, char** argv) {
  namespace t = uuvplan::testing;
  const int n = argc > 1 ? std::atoi(argv[1]) : 8;
  const std::uint64_t first = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  const auto pool = uuvplan::io::ReadPool(Payload60("pool.yaml"));
  const auto scratch_truth = uuvplan::io::ReadTruth(Payload60("truth.yaml"));
  const auto known_truth = uuvplan::io::ReadTruth(Payload60("on-frame-truth.yaml"));
  int fewer = 0, shorter = 0, converged = 0, interest = 0, within3 = 0, scratch_failed = 0;
  double scratch_time = 0, known_time = 0;
  for (std::uint64_t seed = first; seed < first + static_cast<std::uint64_t>(n); ++seed) {
    const t::LoopCaseOutcome s = t::RunLoopCase("scratch", scratch_truth, pool, seed);
    const t::LoopCaseOutcome k = t::RunLoopCase("on frame", known_truth, pool, seed);
    std::cout << "seed " << seed << "\n  " << t::CaseLine(s) << "\n  " << t::CaseLine(k)
              << std::endl;
    fewer += k.trials < s.trials;
    // Less pool time than the scratch loop took to converge, or a scratch loop that did not.
    const bool scratch_converged = s.status == uuvplan::planner::LoopStatus::kConverged;
    shorter += k.pool_time_s < s.pool_time_s || !scratch_converged;
    scratch_failed += !scratch_converged;
    scratch_time += s.pool_time_s;
    known_time += k.pool_time_s;
    if (k.status != uuvplan::planner::LoopStatus::kConverged) continue;
    ++converged;
    for (const auto& e : k.interest) {
      ++interest;
      within3 += e.within3;
    }
  }
  std::cout << "\non its frame against from scratch, " << n << " seeds: converged " << converged
            << "/" << n << "; fewer trials " << fewer << "/" << n << "; less pool time " << shorter
            << "/" << n << " (scratch not converged on " << scratch_failed << "; mean "
            << scratch_time / n / 60 << " → " << known_time / n / 60 << " min); within 3σ "
            << within3 << "/" << interest << std::endl;
  const bool pass = converged == n && fewer == n && shorter == n && within3 >= 0.95 * interest;
  return pass ? 0 : 1;
}
