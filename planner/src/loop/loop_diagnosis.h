// The diagnosis step of `loop --diagnose` (LoopOptions::diagnose): diagnose a DOF's trials and
// make the model the loop identifies the one the diagnosis found. Internal to the planner
// library.
#pragma once

#include <map>
#include <set>
#include <string>
#include <vector>

#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/model/campaign.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/loop/design_loop.h"

namespace uuvplan::planner::internal {

/// The model the loop identifies: the vehicle file's, with per DOF the effects the latest
/// diagnosis accepted (model::Vehicle::models, which identify's written-model stage fits).
struct WorkingModel {
  model::Vehicle vehicle;
  std::map<model::Dof, std::set<std::string>> effects;  ///< effect (and detail) per DOF
  /// Per DOF, why the latest diagnosis has not settled its model: an accepted effect leads
  /// another significant candidate of its round by less than LoopOptions::settled_aic_gap in
  /// AIC, so its estimates are not trusted yet (one line each).
  std::map<model::Dof, std::vector<std::string>> doubts;
};

/// What a diagnosis changed in a DOF's model.
struct ModelChange {
  std::vector<EffectEntered> entered;
  std::vector<std::string> left;  ///< effects no longer found on the trials so far
  std::string note;               ///< why the diagnosis changed nothing, when it could not run
  bool changed() const { return !entered.empty() || !left.empty(); }
};

/// Diagnoses `dof` on its trials in `campaign` (from the standard model, whatever `working`
/// holds) and, when the effects it accepts differ from those `working` has, makes its extended
/// model the DOF's model in `working`: the diagnosis of every trial so far is the best-informed
/// judge. An effect in the model leaves when a later diagnosis no longer finds it significant
/// on top of its final model (the likelihood ratio of its last round); while it does, the
/// effect stays at its values although its held-out gain fell short. installation_loss is not
/// counted: identification's standard structure estimates η already. Nothing changes when the DOF
/// has fewer than two fit trials (a finding needs held-out data), or, with `note` saying why, when
/// the diagnosis refused the trials or its model is not admissible. Sets the DOF's doubts in
/// `working` (WorkingModel::doubts) whenever the diagnosis ran.
ModelChange AdoptFindings(const model::Campaign& campaign, model::Dof dof,
                          const ident::DiagnoseOptions& options, double settled_aic_gap,
                          WorkingModel* working);

}  // namespace uuvplan::planner::internal
