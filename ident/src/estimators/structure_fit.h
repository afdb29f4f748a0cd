// A DOF's model in a given structure (model_structure.h) fitted by output error on its fit
// trials: what diagnosis compares candidate effects with, and what identify fits when the
// vehicle file gives a model with effects (`identify`/`diagnose --write-vehicle`).
#pragma once

#include <map>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "uuvplan/ident/estimators/output_error.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/model_structure.h"

namespace uuvplan::ident {

using Values = std::map<std::string, double>;  ///< by parameter name

/// A structure fitted by output error on the fit trials.
struct StructureFit {
  model::ModelStructure structure;
  std::shared_ptr<model::DofModel> model;
  OutputErrorResult oe;
  Values values;  ///< by parameter name
  std::set<std::string> dropped;
  int free_parameters = 0;  ///< model parameters + nuisance initial states
  Values held;              ///< parameters held at a value (FitPhysical: at an admissible bound)
  std::set<std::string> held_at_bound;  ///< those the free fit put outside their range
};

StructureFit FitStructure(const model::Vehicle& vehicle, const model::ModelStructure& structure,
                          const std::vector<const TrialData*>& trials, const Values& start,
                          const std::set<std::string>& dropped, const OutputErrorOptions& options,
                          const Values& fixed = {});

/// FitStructure within the families' admissible ranges (model/parameter.h): a parameter the fit
/// puts outside its range (and `base` had inside) is held at the bound and the rest refitted;
/// one that cannot be held (an open bound) is left for the test to call non-physical.
StructureFit FitPhysical(const model::Vehicle& vehicle, const model::ModelStructure& structure,
                         const std::vector<const TrialData*>& trials, const Values& start,
                         const std::set<std::string>& dropped, const OutputErrorOptions& options,
                         const Values& base, Values held = {});

/// `nominal` with `f`'s structure and output-error estimate (parameters held at a bound listed
/// as fixed); its free runs not yet scored.
DofIdentification WithStructureFit(const DofIdentification& nominal, const StructureFit& f);

/// WithStructureFit and the free run of every trial in `trials` with it (validation.h, the
/// scores of `uuvplan score`).
DofIdentification AsIdentification(const DofIdentification& nominal, const StructureFit& f,
                                   const std::vector<const TrialData*>& trials, double step_s);

}  // namespace uuvplan::ident
