// Full-size validation of the identification's uncertainties (docs/validation.md):
//
//  1. Coverage: for cases/romeo (surge forward/backward with three mappings and the §IV-D sine;
//     heave with five ballast steps and η = 0.56; yaw with three mappings and the sine),
//     cases/vsor and cases/uris, the same virtual campaign is identified with R independent
//     seeds; for every estimator that reports σ and every parameter, the fraction of 95%
//     intervals θ̂ ± 1.96σ that cover the truth must lie in [90%, 99%], and the fraction within
//     3σ is printed.
//  2. Cramér–Rao: the output-error estimates' spread over R repetitions of the ROMEO surge sine
//     (offset 35 N, amplitude 25 N, period 26 s, 260 s) must lie within 25% of the bound at the
//     truth.
//
//  3. A mild unmodelled effect: with a fifth argument "lag=T" every DOF of
//     the truth gets a first-order thrust lag of time constant T s (model/effects.h
//     thruster_lag), which the fitted standard model does not contain. T = 0.05 s is mild:
//     the force error T·dφ/dt is 0.05·ω·A, under 1% of the force on the papers' sines
//     (ROMEO surge: 0.05·0.24·25 N = 0.3 N on 35 ± 25 N) and a 0.05 s rounding of each
//     command step. The coverage of the standard parameters must stay in the band.
//     "asym=A" instead makes the quadratic drag asymmetric, kq_neg = (1 + A)·kq (asymmetric_drag),
//     fitted symmetric: a shape error of the drag that shows in the residuals of the legs of
//     each sign (A = 0.1: a hull a little blunter astern).
//
// Run: build/tests/identify_validation [repetitions = 200] [case = all] [AR(1) ρ = 0]
//                                      [unmodelled effect: none, lag=T or asym=A]
//      (case: romeo_surge, romeo_heave, romeo_yaw, vsor, uris, crb)
// Exit status 1 when a claim fails. Model selection is off (fixed structures): coverage is a
// property of an estimator of a given model. The CI subset is tests/ident/ident_coverage_test.cc.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "ident/ident_cases.h"
#include "uuvplan/ident/stats/monte_carlo.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/text/monte_carlo_table.h"

using namespace uuvplan;
using model::Dof;

namespace {

struct Case {
  std::string name, truth;
  std::vector<model::TrialDesign> designs;
};

double Seconds(std::chrono::steady_clock::time_point a) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - a).count();
}

}  // namespace

int main(int argc, char** argv) {
  const int reps = argc > 1 ? std::atoi(argv[1]) : 200;
  const std::string only = argc > 2 && std::string(argv[2]) != "all" ? argv[2] : "";
  const double ar1 = argc > 3 ? std::atof(argv[3]) : 0.0;
  const std::string effect = argc > 4 ? argv[4] : "none";
  const double lag = effect.rfind("lag=", 0) == 0 ? std::atof(effect.c_str() + 4) : 0.0;
  const double asym = effect.rfind("asym=", 0) == 0 ? std::atof(effect.c_str() + 5) : 0.0;
  namespace t = ident::testing;
  const std::vector<Case> cases = {{"romeo_surge", "romeo", t::RomeoSurgeDesigns()},
                                   {"romeo_heave", "romeo", t::RomeoHeaveDesigns()},
                                   {"romeo_yaw", "romeo", t::RomeoYawDesigns()},
                                   {"vsor", "vsor", t::VsorDesigns()},
                                   {"uris", "uris", t::UrisDesigns()}};
  bool known = only.empty() || only == "crb";
  for (const Case& c : cases) known = known || only == c.name;
  if (reps <= 1 || !known || argc > 5 || !(std::abs(ar1) < 1) ||
      !(effect == "none" || lag > 0 || asym != 0)) {
    std::fprintf(stderr,
                 "usage: identify_validation [repetitions > 1, default 200] [case: romeo_surge, "
                 "romeo_heave, romeo_yaw, vsor, uris, crb or all] [sensor noise AR(1) ρ in "
                 "(-1, 1), default 0] [unmodelled effect: none, lag=T with T > 0 s, or asym=A: "
                 "kq_neg = (1 + A)·kq]\n");
    return 2;
  }
  int exit_code = 0;
  int cells = 0, in_band = 0;
  for (const Case& c : cases) {
    if (!only.empty() && only != c.name) continue;
    ident::MonteCarloOptions o;
    o.repetitions = reps;
    o.seed = 7;  // the CI subset uses the same seed: its repetitions are the first ones here
    o.identify.selection.prune_insignificant = false;
    o.cramer_rao = false;
    const auto t0 = std::chrono::steady_clock::now();
    model::Truth truth = t::CaseTruth(c.truth);
    truth.defects.noise_ar1 = ar1;
    // Identification fits the standard structure of the data (identify_prepare.cc
    // ChooseStructure): the lag in the truth is unmodelled.
    for (const model::TrialDesign& d : c.designs) {
      if (lag > 0) truth.dofs[d.dof].params[model::param::kLag] = lag;
      if (asym != 0) {
        auto& params = truth.dofs[d.dof].params;
        params[model::param::kLinearDragNeg] = params[model::param::kLinearDrag];
        params[model::param::kQuadraticDragNeg] =
            (1.0 + asym) * params[model::param::kQuadraticDrag];
      }
    }
    const ident::MonteCarloReport r = ident::RunMonteCarlo(truth, c.designs, o);
    std::printf("== %s: %d repetitions, %d failures, %.0f s\n%s", c.name.c_str(), r.repetitions,
                r.failures, Seconds(t0), text::MonteCarloTable(r).c_str());
    if (r.failures > 0) exit_code = 1;
    for (const ident::CoverageCell& cell : r.cells) {
      if (cell.estimator == "final") continue;  // the output error (or LS fallback), counted once
      const double cov = cell.coverage();
      if (cell.n < 0.8 * r.repetitions) {
        // The estimator declined in most repetitions (e.g. too few steady segments detected):
        // no coverage claim for it here; listed so that it is seen.
        std::printf("  (rarely reported: %s %s %s in %d of %d repetitions)\n",
                    cell.estimator.c_str(), std::string(model::DofName(cell.dof)).c_str(),
                    cell.name.c_str(), cell.n, r.repetitions);
        continue;
      }
      ++cells;
      // The band for a 95% interval: [90%, 99%] of the repetitions.
      const bool ok = cov >= 0.90 && cov <= 0.99;
      in_band += ok;
      if (!ok) {
        exit_code = 1;
        std::printf("  OUT OF BAND: %s %s %s coverage %.1f%% (n = %d), sd/σ = %.2f\n",
                    cell.estimator.c_str(), std::string(model::DofName(cell.dof)).c_str(),
                    cell.name.c_str(), 100 * cov, cell.n, cell.sd / cell.mean_sigma);
      }
    }
    std::fflush(stdout);
  }
  if ((only.empty() && lag == 0 && asym == 0) || only == "crb") {
    const model::Truth truth = t::CaseTruth("romeo");
    ident::MonteCarloOptions o;
    o.repetitions = reps;
    o.seed = 11;
    o.identify.selection.prune_insignificant = false;
    // The sine never reverses the force: no installation coefficient is excited.
    o.identify.structures[Dof::kSurge] =
        model::ModelStructure::Standard(truth.vehicle, Dof::kSurge, {}, false);
    model::TrialDesign sine = t::RomeoSurgeDesigns()[3];
    sine.duration = 260;  // ten periods
    const auto t0 = std::chrono::steady_clock::now();
    const ident::MonteCarloReport r = ident::RunMonteCarlo(truth, {sine}, o);
    std::printf("== crb (ROMEO surge sine, 260 s): %d repetitions, %d failures, %.0f s\n%s",
                r.repetitions, r.failures, Seconds(t0), text::MonteCarloTable(r).c_str());
    if (r.failures > 0) exit_code = 1;
    for (const char* name : {"m", "k", "kq", "bias"}) {
      const ident::CoverageCell* cell = r.Find("output_error", Dof::kSurge, name);
      const double ratio = cell && cell->crb_sigma > 0 ? cell->sd / cell->crb_sigma : NAN;
      // The claim: the Monte Carlo spread within 25% of the Cramér–Rao bound.
      const bool ok = std::abs(ratio - 1.0) <= 0.25;
      std::printf("  output-error sd / √CRB for %-4s = %.3f  %s\n", name, ratio,
                  ok ? "ok" : "FAIL");
      if (!ok) exit_code = 1;
    }
  }
  if (cells > 0) {
    std::printf("coverage in [90%%, 99%%]: %d of %d estimator×parameter cells\n", in_band, cells);
  }
  std::printf("%s\n", exit_code == 0 ? "all claims hold" : "SOME CLAIMS FAIL");
  return exit_code;
}
