// Measure stage: the gain of an extension is the free-run velocity MAE (seed 002 eq. 37) it
// saves on data it was not fitted to.
#include <cmath>

#include "diagnosis_internal.h"
#include "uuvplan/ident/validation.h"

namespace uuvplan::ident::diagnosis {

namespace {

// Velocity MAE of the free-run simulations of `trials` (pooled over samples).
double PooledMae(const model::DofModel& model, const Eigen::VectorXd& theta, const Trials& trials,
                 double step_s) {
  ValidationOptions vo;
  vo.step_s = step_s;
  double sum = 0.0;
  int n = 0;
  for (const TrialData* t : trials) {
    const TrialFit fit = ValidateTrial(model, theta, *t, vo);
    sum += fit.velocity_mae * fit.velocity_samples;
    n += fit.velocity_samples;
  }
  return n ? sum / n : std::nan("");
}

// 2-fold cross-validation across the fit trials: fit on one half, score on the other, both ways.
void CrossValidate(const model::Vehicle& vehicle, const StructureFit& before,
                   const StructureFit& after, const Trials& fit, const OutputErrorOptions& oe,
                   DiagnosisGain* g) {
  Trials folds[2];
  for (std::size_t k = 0; k < fit.size(); ++k) folds[k % 2].push_back(fit[k]);
  double sum_b = 0, sum_a = 0;
  int parts = 0;
  for (int k = 0; k < 2; ++k) {
    if (folds[k].empty() || folds[1 - k].empty()) continue;
    const StructureFit fb =
        FitStructure(vehicle, before.structure, folds[1 - k], before.values, before.dropped, oe);
    const StructureFit fa =
        FitStructure(vehicle, after.structure, folds[1 - k], after.values, after.dropped, oe);
    sum_b += PooledMae(*fb.model, fb.oe.theta, folds[k], oe.step_s);
    sum_a += PooledMae(*fa.model, fa.oe.theta, folds[k], oe.step_s);
    ++parts;
  }
  g->before = parts ? sum_b / parts : std::nan("");
  g->after = parts ? sum_a / parts : std::nan("");
}

}  // namespace

// On the validate trials, or by 2-fold cross-validation when none is marked (issue #5 step 4).
DiagnosisGain HeldOutGain(const model::Vehicle& vehicle, const StructureFit& before,
                          const StructureFit& after, const Trials& fit, const Trials& validate,
                          const OutputErrorOptions& oe) {
  DiagnosisGain g;
  if (!validate.empty()) {
    g.on = "validate";
    g.before = PooledMae(*before.model, before.oe.theta, validate, oe.step_s);
    g.after = PooledMae(*after.model, after.oe.theta, validate, oe.step_s);
  } else {
    g.on = "cross-validation";
    CrossValidate(vehicle, before, after, fit, oe, &g);
  }
  g.relative = g.before > 0 ? (g.before - g.after) / g.before : 0.0;
  return g;
}

}  // namespace uuvplan::ident::diagnosis
