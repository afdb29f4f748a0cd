// The stages of identifying one DOF (docs/identification.md), each a function of its own file:
//
//   prepare   (identify_prepare.cc)   the DOF's trials, model structure, start values,
//                                      closed-loop check
//   estimate  (identify_estimate.cc)  steady state + integral method (ref 000 eqs. 7–12,
//                                      16–19) or one-step least squares (refs 002/004)
//   refine    (identify_refine.cc)    output-error refinement from the least-squares answer
//   validate  (identify_validate.cc)  the reported estimates, plausibility warnings, free runs
//
// IdentifyDof (identify.cc) runs them in order and times each.
#pragma once

#include <Eigen/Dense>
#include <set>
#include <string>
#include <vector>

#include "uuvplan/ident/identify.h"

namespace uuvplan::ident::stages {

/// The trials of one DOF, split by use.
struct DofTrials {
  std::vector<const TrialData*> fit, validate;
  std::vector<std::string> mappings;  ///< mappings seen in the fit trials, in order
  std::set<int> ballast_values;       ///< ballast_steps of the fit trials
};

/// Everything the later stages share: the trials, the model, the start values and the
/// estimators' options with the identify-level pruning switch applied.
struct StageInputs {
  const model::Vehicle& vehicle;
  const DofTrials& trials;
  const model::DofModel& model;
  Eigen::VectorXd prior;  ///< PriorTheta
  SteadyStateOptions steady;
  OutputErrorOptions output_error;
  int mass_index = -1;  ///< index of m in theta
};

/// θ with its covariance and the state of each parameter (theta layout).
struct StageEstimate {
  Eigen::VectorXd theta;
  Eigen::MatrixXd covariance;
  std::vector<ParameterState> state;
};

/// The least-squares answer handed to the refinement.
struct LeastSquaresAnswer {
  StageEstimate estimate;
  bool steady_ok = false;  ///< the steady-state fit succeeded
  std::set<std::string> not_excited_steady;
  std::set<std::string> not_excited;  ///< by the fit trials (kept at their start value)
};

// prepare
/// The DOF's trials; unusable columns and an outlier fraction above
/// OutlierOptions::finding_fraction are the DOF's warnings.
DofTrials SelectTrials(model::Dof dof, const std::vector<TrialData>& all,
                       const OutlierOptions& outliers, DofIdentification* r);
model::ModelStructure ChooseStructure(const model::Vehicle& vehicle, model::Dof dof,
                                      const DofTrials& trials, const IdentifyOptions& o);
bool SuspectClosedLoop(const std::vector<const TrialData*>& fit, ClosedLoop setting);

// estimate
/// Throws model::InputError when the method cannot run on the DOF's fit trials (ls and integral
/// without a constant-force leg long enough for a steady state, nor a --steady window).
void CheckMethodFits(model::Dof dof, const std::vector<TrialData>& trials,
                     const IdentifyOptions& o);
/// The least-squares answer of the chain, or the single method's estimate
/// (IdentifyOptions::method).
LeastSquaresAnswer EstimateStage(const StageInputs& c, const IdentifyOptions& o,
                                 DofIdentification* r);

// refine
StageEstimate RefineStage(const StageInputs& c, const LeastSquaresAnswer& ls,
                          const IdentifyOptions& o, DofIdentification* r);

// validate
void ReportEstimates(const StageInputs& c, const LeastSquaresAnswer& ls,
                     const StageEstimate& final_estimate, DofIdentification* r);
void ValidateStage(const StageInputs& c, const ValidationOptions& o, DofIdentification* r);

}  // namespace uuvplan::ident::stages
