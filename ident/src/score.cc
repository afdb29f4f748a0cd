#include "uuvplan/ident/score.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "uuvplan/ident/identify.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/numbers.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/model/virtual_pool.h"

namespace uuvplan::ident {

namespace {

using model::kNaN;

// Velocity MAE pooled over the samples of `fits` (those of use `use` when given).
double PoolMae(const std::vector<TrialFit>& fits, std::string* why, int* samples,
               const model::TrialUse* use = nullptr) {
  double sum = 0.0;
  int n = 0;
  for (const TrialFit& fit : fits) {
    if ((use && fit.use != *use) || fit.velocity_samples == 0) continue;
    if (!std::isfinite(fit.velocity_mae)) {
      *why = "the free run of " + fit.name + " cannot be simulated";
      return kNaN;
    }
    sum += fit.velocity_mae * fit.velocity_samples;
    n += fit.velocity_samples;
  }
  if (n == 0) *why = "no velocity sample to score";
  if (samples) *samples = n;
  return n ? sum / n : kNaN;
}

}  // namespace

double PooledVelocityMae(const model::DofModel& model, const Eigen::VectorXd& theta,
                         const std::vector<const TrialData*>& trials, double step_s,
                         std::string* why, int* samples) {
  ValidationOptions vo;
  vo.step_s = step_s;
  std::vector<TrialFit> fits;
  for (const TrialData* t : trials) fits.push_back(ValidateTrial(model, theta, *t, vo));
  return PoolMae(fits, why, samples);
}

model::DofTruth ModelOf(const DofIdentification& identification) {
  model::DofTruth m;
  for (std::size_t i = 0; i < identification.parameter_names.size(); ++i) {
    const std::string& name = identification.parameter_names[i];
    m.params[name] = identification.theta[static_cast<Eigen::Index>(i)];
    const ParameterEstimate* e = identification.Param(name);
    m.sigma[name] =
        e && e->state == ParameterState::kEstimated && std::isfinite(e->sigma) ? e->sigma : 0.0;
  }
  m.settings = identification.structure.settings;
  return m;
}

model::Vehicle WithIdentifiedModels(model::Vehicle vehicle, const IdentifyResult& result) {
  for (const DofIdentification& d : result.dofs) {
    if (d.status == IdentifyStatus::kFailed) continue;
    const model::DofTruth m = ModelOf(d);
    if (Inadmissible(m).empty()) vehicle.models[d.dof] = m;
  }
  return vehicle;
}

std::string Inadmissible(const model::DofParameters& m) {
  for (const auto& [name, value] : m.params) {
    const model::ParameterFamily* family = model::FamilyOf(name);
    if (family && !family->Admissible(value)) {
      return name + " = " + model::Significant(value, 4) + " (expected " + family->Expected() + ")";
    }
  }
  return "";
}

bool ScoreOptions::IsValid(std::string* error) const {
  if (!(step_s > 0)) {
    if (error) *error = "ScoreOptions::step_s must be > 0";
    return false;
  }
  return data.IsValid(error);
}

namespace {

// The pooled scores of one DOF's trial fits by use.
DofScore PoolDof(model::Dof dof, const std::vector<TrialFit>& fits) {
  DofScore s;
  s.dof = dof;
  const model::TrialUse fit = model::TrialUse::kFit, validate = model::TrialUse::kValidate;
  std::string why_fit, why_validate, why_all;
  s.velocity_mae_fit = PoolMae(fits, &why_fit, &s.samples_fit, &fit);
  s.velocity_mae_validate = PoolMae(fits, &why_validate, &s.samples_validate, &validate);
  s.velocity_mae_all = PoolMae(fits, &why_all, nullptr);
  if (!why_all.empty()) s.problem = why_all;
  return s;
}

}  // namespace

ScoreResult ScoreCampaign(const model::Campaign& campaign, const model::Truth& given,
                          const ScoreOptions& options) {
  std::string error;
  if (!options.IsValid(&error)) throw model::InputError("score", error);
  ScoreResult result;
  std::map<model::Dof, std::vector<TrialData>> prepared;
  for (std::size_t i = 0; i < campaign.trials.size(); ++i) {
    const model::Dof dof = campaign.trials[i].dof;
    const bool asked = options.dofs.empty() || std::find(options.dofs.begin(), options.dofs.end(),
                                                         dof) != options.dofs.end();
    if (!asked) continue;
    if (!given.dofs.count(dof)) {
      result.notes.push_back({ScoreNoteKind::kNoModelForDof, campaign.trials[i].file, dof});
      continue;
    }
    prepared[dof].push_back(
        PrepareTrial(campaign.trials[i], static_cast<int>(i), given.vehicle, options.data));
  }
  for (auto& [dof, trials] : prepared) {
    const model::DofModel dof_model(given.vehicle, model::TruthStructure(given, dof));
    // Parameters the file does not name take the standard model's neutral values (as the
    // virtual pool does): no bias, no drag term.
    const std::map<std::string, double> neutral = {{model::param::kBias, 0.0},
                                                   {model::param::kQuadraticDrag, 0.0},
                                                   {model::param::kLinearDrag, 0.0},
                                                   {model::param::kBiasStep, 0.0}};
    const Eigen::VectorXd theta = dof_model.Theta(given.dofs.at(dof).params, &neutral);
    ValidationOptions vo;
    vo.step_s = options.step_s;
    vo.curve_points = options.curve_points;
    std::vector<TrialFit> fits;
    for (const TrialData& t : trials) fits.push_back(ValidateTrial(dof_model, theta, t, vo));
    result.dofs.push_back(PoolDof(dof, fits));
    for (const TrialFit& f : fits) result.trials.push_back({dof, f});
  }
  std::sort(result.trials.begin(), result.trials.end(),
            [](const TrialScore& a, const TrialScore& b) { return a.fit.trial < b.fit.trial; });
  return result;
}

}  // namespace uuvplan::ident
