// Full-size validation of `diagnose`: for each effect (and none), draw N random
// cases with the effect hidden, run them through the virtual pool and diagnose them. Prints the
// rate of correct diagnoses (exactly the hidden effect named; nothing on clean data) and how
// often the hidden parameter lies within 3σ of its true value.
// Run: build/tests/diagnose_validation [draws per effect = 200] [first seed = 1] [effect name]
// UUVPLAN_GAINS=1 prints every finding's held-out gain; UUVPLAN_VERBOSE=1 the tests of failures.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "support/hidden_effect.h"
#include "uuvplan/ident/diagnosis/diagnosis.h"

using namespace uuvplan;

int main(int argc, char** argv) {
  const int draws = argc > 1 ? std::atoi(argv[1]) : 200;
  const std::uint64_t first = argc > 2 ? std::strtoull(argv[2], nullptr, 10) : 1;
  const std::string only = argc > 3 ? argv[3] : "";
  std::vector<std::optional<std::string>> effects = {std::nullopt};
  for (const std::string& e : model::Effects().Diagnosable()) effects.push_back(e);
  const bool known = only.empty() || only == "none" || model::Effects().Find(only);
  if (draws <= 0 || first == 0 || !known || argc > 4) {
    std::fprintf(stderr,
                 "usage: diagnose_validation [draws per effect > 0, default 200] [first seed > 0, "
                 "default 1] [effect: none or one of the contract's effect names]\n");
    return 2;
  }
  int exit_code = 0;
  for (const auto& effect : effects) {
    const std::string name = effect.value_or("none");
    if (!only.empty() && only != name) continue;
    int correct = 0, within = 0;
    const auto t0 = std::chrono::steady_clock::now();
    for (int i = 0; i < draws; ++i) {
      const std::uint64_t seed = first + i;
      const testing::HiddenEffectCase c = testing::DrawHiddenEffectCase(effect, seed);
      const model::Campaign campaign = testing::RunHiddenEffectCase(c, seed);
      const ident::DiagnosisResult r = ident::Diagnose(campaign, testing::DiagnoseOptionsFor(c));
      const testing::Verdict v = testing::Judge(c, r);
      const bool ok = v.correct;
      const std::string got = v.found;
      within += v.within_3_sigma;
      correct += ok;
      if (!ok && std::getenv("UUVPLAN_VERBOSE")) {
        for (const auto& t : r.tests) {
          std::printf("    round %d %-20s %-4s D=%9.2f dp=%d p=%.2e z=%6.2f %s gain %.4f%s\n",
                      t.round, t.effect.c_str(), t.detail.c_str(), t.statistic, t.added_parameters,
                      t.p_value, t.max_z, t.significant ? "SIGNIFICANT" : "", t.gain,
                      t.accepted ? " ACCEPTED" : "");
        }
        for (const auto& d : r.nominal.dofs) {
          for (const auto& p : d.params)
            std::printf("    nominal %s = %g ± %g\n", p.name.c_str(), p.value, p.sigma);
        }
        for (const auto& [pn, pv] : c.truth.dofs.at(c.dof).params)
          std::printf("    truth %s = %g\n", pn.c_str(), pv);
      }
      if (std::getenv("UUVPLAN_GAINS")) {
        for (const auto& f : r.findings) {
          std::printf("  gain %s seed %llu %s %s %.4f D=%.1f\n", name.c_str(),
                      static_cast<unsigned long long>(seed), ok ? "ok" : "BAD", f.effect.c_str(),
                      f.gain.relative, f.statistic);
        }
      }
      if (ok && effect && !v.within_3_sigma) {
        std::printf("  %s seed %llu (%s): parameter beyond 3σ\n", name.c_str(),
                    static_cast<unsigned long long>(seed),
                    std::string(model::DofName(c.dof)).c_str());
      }
      if (!ok)
        std::printf("  %s seed %llu (%s): found [%s]\n", name.c_str(),
                    static_cast<unsigned long long>(seed),
                    std::string(model::DofName(c.dof)).c_str(), got.c_str());
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    std::printf("diagnose %-20s correct %3d/%d (%.1f%%)  param within 3σ %d/%d  %.1f s\n",
                name.c_str(), correct, draws, 100.0 * correct / draws, within, correct, s);
    std::fflush(stdout);
    const double rate = static_cast<double>(correct) / draws;
    if (effect ? rate < 0.95 : rate < 0.95) exit_code = 1;
  }
  return exit_code;
}
