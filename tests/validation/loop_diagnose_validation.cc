// Full-size validation of `loop --diagnose` (docs/validation.md "The loop finds hidden
// effects"): on a truth whose thrusters lag the command by 0.15 s and whose delivered force is
// ∝ |force|^0.7 where the vehicle file says ∝ |force| (support/diagnosed_loop.h), for N seeds
// per case: the loop converges, names exactly those two effects, and ends with every
// parameter within 3σ of the truth. Exit status 1 when a case passes in fewer than 95% of
// its seeds.
//
//   loop_diagnose_validation [N=20] [first_seed=1] [case...]
//
// Cases: uris (surge, thrust reference 10 N), bluerov2 (surge, 20 N), vsor (yaw, 30 N·m).
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "support/diagnosed_loop.h"
#include "uuvplan/io/pool_yaml.h"
#include "uuvplan/io/truth_yaml.h"

namespace {

namespace t = uuvplan::testing;
using uuvplan::model::Dof;

struct Case {
  Dof dof;
  double reference;  ///< of the hidden thrust map (N or N·m)
};

const std::map<std::string, Case>& Cases() {
  static const std::map<std::string, Case> cases = {{"uris", {Dof::kSurge, 10.0}},
                                                    {"bluerov2", {Dof::kSurge, 20.0}},
                                                    {"vsor", {Dof::kYaw, 30.0}}};
  return cases;
}

std::string CasePath(const std::string& c, const std::string& file) {
  return std::string(UUVPLAN_SOURCE_DIR) + "/cases/" + c + "/" + file;
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 20;
  const std::uint64_t first = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  std::vector<std::string> names;
  for (int i = 3; i < argc; ++i) names.push_back(argv[i]);
  if (names.empty()) {
    for (const auto& [name, c] : Cases()) names.push_back(name);
  }
  bool ok = true;
  for (const std::string& name : names) {
    const auto c = Cases().find(name);
    if (c == Cases().end()) {
      std::cerr << "unknown case " << name << " (uris, bluerov2, vsor)\n";
      return 2;
    }
    const auto truth = t::WithLagAndThrustMap(uuvplan::io::ReadTruth(CasePath(name, "truth.yaml")),
                                              c->second.dof, 0.15, -0.3, c->second.reference);
    const auto pool = uuvplan::io::ReadPool(CasePath(name, "pool.yaml"));
    int pass = 0;
    for (std::uint64_t seed = first; seed < first + static_cast<std::uint64_t>(n); ++seed) {
      const t::DiagnosedLoopOutcome out = t::RunDiagnosedLoop(truth, pool, c->second.dof, seed);
      const bool passed = out.Pass({"thruster_lag", "thrust_map"});
      pass += passed;
      std::cout << name << " seed " << seed << ": " << (passed ? "pass" : "FAIL") << ": "
                << out.Line() << std::endl;
    }
    std::cout << name << ": " << pass << "/" << n << " pass\n" << std::endl;
    ok = ok && pass >= 0.95 * n;
  }
  return ok ? 0 : 1;
}
