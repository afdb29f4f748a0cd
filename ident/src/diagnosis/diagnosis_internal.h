// The stages of diagnosis (diagnosis.h), shared by the files of ident/src/diagnosis/:
//   screen  (breakdown.cc)    where the standard model's free run goes wrong;
//   test    (candidates.cc)   each effect of the table proposed as an extension, fitted by
//                             output error and tested by likelihood ratio;
//   extend  (diagnosis.cc)    the greedy forward selection;
//   measure (held_out_gain.cc, input_noise.cc)  the gain on held-out data, and the σ.
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "estimators/structure_fit.h"
#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/ident/estimators/output_error.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/effects.h"

namespace uuvplan::ident::diagnosis {

using Values = std::map<std::string, double>;
using Trials = std::vector<const TrialData*>;

/// A candidate extension of the current structure: an effect's proposal applied to it.
struct Candidate {
  const model::EffectEntry* effect = nullptr;
  model::Proposal proposal;
  model::ModelStructure structure;
  std::vector<std::string> added;  ///< names of the new parameters
};

/// Every candidate the effect `name` proposes for `base` on the fit trials.
std::vector<Candidate> CandidatesFor(const std::string& name, const model::Vehicle& vehicle,
                                     const StructureFit& base, const Trials& trials,
                                     bool campaign_clock);

/// The likelihood-ratio test of `ext` against `base` (diagnosis.h, step 3).
CandidateTest Test(const Candidate& c, const StructureFit& base, const StructureFit& ext,
                   int round);

/// Where the free run of `theta` goes wrong on `trials` (step 2).
ErrorBreakdown Breakdown(const model::Vehicle& vehicle, const model::DofModel& model,
                         const Eigen::VectorXd& theta, const Trials& trials, double step_s,
                         bool campaign_clock);

/// The held-out gain of going from `before` to `after` (step 4): on `validate`, else by
/// cross-validation across `fit` (its folds fitted on up to `threads` threads).
DiagnosisGain HeldOutGain(const model::Vehicle& vehicle, const StructureFit& before,
                          const StructureFit& after, const Trials& fit, const Trials& validate,
                          const OutputErrorOptions& oe, int threads);

/// Per-trial free-run velocity MAE of `f` on `trials` (NaN when not simulated) and its samples.
std::vector<std::pair<double, int>> PerTrialMae(const StructureFit& f, const Trials& trials,
                                                double step_s);

/// The MAE `a` minus `b`, paired by held-out unit (validate trial or fold; (MAE, samples) each,
/// both on the same units): δ = Σ w_t (a_t − b_t) and σ = √(T/(T−1)·Σ w_t²(d_t − δ)²), w_t the
/// unit's share of samples. δ NaN when the units do not match; σ NaN with fewer than 2.
void PairedDifference(const std::vector<std::pair<double, int>>& a,
                      const std::vector<std::pair<double, int>>& b, double* delta, double* sigma);

/// Adds the errors-in-variables covariance of coupling terms to `f` (input_noise.cc).
void AddInputNoiseCovariance(const model::Campaign& campaign, const Trials& fit,
                             const TrialDataOptions& data, const OutputErrorOptions& oe,
                             int replicates, std::uint64_t seed, int threads, StructureFit* f,
                             std::vector<DiagnosisNote>* notes);

/// The corrected static thrust map of each mapping of `trials` that `f`'s thrust_map effect
/// implies (diagnosis.h CorrectedThrustMap); empty without one.
std::vector<CorrectedThrustMap> CorrectedThrustMaps(const model::Vehicle& vehicle,
                                                    const StructureFit& f, const Trials& trials);

/// The static map (linear, dead-band, asymmetric) that replaces `current`'s power law, each
/// fitted on `fit` and scored on `validate`; the lowest AIC of the physical ones is chosen
/// (static_map_choice.cc). Fills finding->static_maps, chosen_map and each table's chosen_force.
void ChooseStaticMap(const model::Campaign& campaign, const TrialDataOptions& data,
                     const StructureFit& current, const Trials& fit, const Trials& validate,
                     const OutputErrorOptions& oe, Finding* finding);

/// "" when every parameter of `ext` lies in its family's admissible range, else which does not.
std::string NonPhysical(const StructureFit& base, const StructureFit& ext);

/// Largest |φⁿ| over the trials.
double MaxForce(const Trials& trials);

}  // namespace uuvplan::ident::diagnosis
