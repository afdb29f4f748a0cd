// The written-model stage of identify (identify_stages.h): the vehicle file's model of a DOF
// (dofs.<dof>.params with effects, as `diagnose --write-vehicle` writes it) refitted on this
// campaign, so that what a diagnosis found is estimated again rather than dropped.
#include <string>
#include <vector>

#include "estimators/structure_fit.h"
#include "identify_stages.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident::stages {

std::shared_ptr<const model::DofModel> FitWrittenModel(const StageInputs& c, DofIdentification* r) {
  const auto written = c.vehicle.models.find(r->dof);
  // A standard model that fits only with non-physical values misses an effect: the file's
  // model may hold it (diagnosis refits such a DOF too).
  const bool fitted = r->status != IdentifyStatus::kFailed || r->failed_only_non_physical;
  if (written == c.vehicle.models.end() || !fitted || r->theta.size() == 0) return nullptr;
  std::vector<std::string> added;
  const model::ModelStructure structure =
      model::WithWrittenEffects(r->structure, written->second, &added);
  if (added.empty()) return nullptr;
  // Two starts, the lower cost kept: the file's model as written (its m, drag and bias belong
  // with its effects), and its effects with the standard fit's estimates of the rest. When the
  // standard model is badly wrong (the effects are large) its estimates lead the fit to another
  // optimum: on a thrust map with a lag the loop's estimates moved by 50σ between trials.
  Values with_standard = written->second.params;
  for (std::size_t i = 0; i < r->parameter_names.size(); ++i) {
    with_standard[r->parameter_names[i]] = r->theta[static_cast<Eigen::Index>(i)];
  }
  Values as_written = with_standard;  // the file's values where it has them (η: the campaign's)
  for (const auto& [name, value] : written->second.params) as_written[name] = value;
  const std::string list = model::Join(added, ", ");
  StructureFit fit = FitPhysical(c.vehicle, structure, c.trials.fit, with_standard, {},
                                 c.output_error, with_standard);
  StructureFit other =
      FitPhysical(c.vehicle, structure, c.trials.fit, as_written, {}, c.output_error, as_written);
  if (other.oe.ok() && (!fit.oe.ok() || other.oe.cost < fit.oe.cost)) fit = std::move(other);
  if (!fit.oe.ok()) {
    r->warnings.push_back("the vehicle file's model (with " + list +
                          ") could not be fitted on this campaign: " + fit.oe.message +
                          "; the standard model's estimates are reported");
    return nullptr;
  }
  if (r->status == IdentifyStatus::kFailed) {
    r->notes.push_back("the standard model alone fits only with non-physical values (" +
                       r->message + ")");
    r->status = IdentifyStatus::kOk;  // ValidateStage states it for the file's model
    r->failed_only_non_physical = false;
  }
  *r = WithStructureFit(*r, fit);
  r->output_error = fit.oe;
  r->notes.push_back("fitted in the vehicle file's model: " + list +
                     " added to the standard model and estimated by output error from the "
                     "file's values, within the admissible ranges");
  return fit.model;
}

}  // namespace uuvplan::ident::stages
