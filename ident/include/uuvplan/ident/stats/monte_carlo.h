// Monte Carlo checks of the reported uncertainties: the same virtual campaign (truth + trial
// designs) is run with independent seeds, identified, and for every estimator that reports σ
// the fraction of repetitions whose interval θ̂ ± z·σ (z = 1.96 at 95%) covers the truth is
// counted, together with the spread of the estimates against the mean reported σ and, for the
// output-error fit, against the Cramér–Rao bound at the truth.
//
// Full size: tests/validation/identify_validation.cc (200 repetitions per case, figures in
// docs/validation.md); the CI runs a seeded subset (tests/ident/ident_coverage_test.cc).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "uuvplan/ident/identify.h"
#include "uuvplan/model/campaign.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/truth.h"

namespace uuvplan::ident {

/// model::BuildVirtualCampaign with these options (a shorthand for tests and Monte Carlo):
/// trial i is design i run on the truth with seed model::StreamSeed(seed, i), from rest, the
/// campaign clock advancing by the trial's duration + pause_s; `uses` (may be shorter) marks
/// trials validate, default fit.
model::Campaign VirtualCampaign(const model::Truth& truth,
                                const std::vector<model::TrialDesign>& designs, std::uint64_t seed,
                                const std::vector<model::TrialUse>& uses = {},
                                double pause_s = 60.0, double command_rate_hz = 20.0);

/// The true parameter of a DOF by name (standard-model defaults: η = 1, others 0).
double TrueParameter(const model::Truth& truth, model::Dof dof, const std::string& name);

struct MonteCarloOptions {
  int repetitions = 200;
  std::uint64_t seed = 1;
  double z = 1.959963984540054;  ///< interval half-width in σ (95%)
  IdentifyOptions identify;
  std::vector<model::TrialUse> uses;
  double pause_s = 60.0;
  bool cramer_rao = true;  ///< compute the output-error CRB at the truth (first repetition)
  /// Threads for the repetitions (0: one per core). Each repetition draws from its own seed
  /// and is tallied in order: the report does not depend on it.
  int threads = 0;
  bool IsValid(std::string* error) const;
};

struct CoverageCell {
  std::string estimator;  ///< steady_state, integral_inertia, one_step_ls, output_error, final
  model::Dof dof = model::Dof::kSurge;
  std::string name;
  double truth = 0.0;
  int n = 0;  ///< repetitions where the estimator reported this parameter with σ
  int covered = 0;
  int within3 = 0;          ///< |θ̂ − θ| <= 3σ
  double mean = 0.0;        ///< of the estimates
  double sd = 0.0;          ///< spread of the estimates
  double mean_sigma = 0.0;  ///< mean reported σ
  double crb_sigma = 0.0;   ///< output error: √CRB at the truth (0 if not computed)
  double coverage() const { return n > 0 ? static_cast<double>(covered) / n : 0.0; }
};

struct MonteCarloReport {
  int repetitions = 0;
  int failures = 0;  ///< repetitions where Identify threw or a DOF got no estimate
  std::vector<CoverageCell> cells;
  std::vector<std::string> notes;
  const CoverageCell* Find(const std::string& estimator, model::Dof dof,
                           const std::string& name) const;
};

MonteCarloReport RunMonteCarlo(const model::Truth& truth,
                               const std::vector<model::TrialDesign>& designs,
                               const MonteCarloOptions& options);

}  // namespace uuvplan::ident
