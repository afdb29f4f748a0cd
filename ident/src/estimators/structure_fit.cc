#include "estimators/structure_fit.h"

#include <algorithm>
#include <cmath>

#include "uuvplan/ident/estimate.h"
#include "uuvplan/ident/validation.h"
#include "uuvplan/model/parameter.h"

namespace uuvplan::ident {

// Every parameter starts at `start` where given, else at its null value ("no effect"); those in
// `fixed` are held at their value there.
StructureFit FitStructure(const model::Vehicle& vehicle, const model::ModelStructure& structure,
                          const std::vector<const TrialData*>& trials, const Values& start,
                          const std::set<std::string>& dropped, const OutputErrorOptions& options,
                          const Values& fixed) {
  StructureFit f;
  f.structure = structure;
  f.model = std::make_shared<model::DofModel>(vehicle, structure);
  f.dropped = dropped;
  f.held = fixed;
  const int np = f.model->num_parameters();
  Eigen::VectorXd theta0(np);
  std::vector<ParameterState> state(np, ParameterState::kEstimated);
  for (int i = 0; i < np; ++i) {
    const std::string& n = f.model->parameter_names()[i];
    const auto it = start.find(n);
    theta0[i] = it != start.end() ? it->second : model::NullValue(n);
    if (dropped.count(n)) {
      state[i] = ParameterState::kDropped;
      theta0[i] = 0.0;
    } else if (const auto held = fixed.find(n); held != fixed.end()) {
      state[i] = ParameterState::kFixed;
      theta0[i] = held->second;
    }
  }
  OutputErrorOptions o = options;
  o.selection.prune_insignificant = false;  // structures are compared as given
  f.oe = OutputErrorFit(*f.model, trials, theta0, state, o);
  for (int i = 0; i < np; ++i) f.values[f.model->parameter_names()[i]] = f.oe.theta[i];
  for (const auto& s : f.oe.state) f.free_parameters += s == ParameterState::kEstimated;
  for (const auto& init : f.oe.initial) {
    f.free_parameters += init.chi0_estimated + init.xi0_estimated;
  }
  return f;
}

}  // namespace uuvplan::ident

namespace uuvplan::ident {

// The parameters of `f` outside their family's admissible range that `base` had inside it (or
// did not have), with the bound each is held at; `blocked` when one cannot be held (an open
// bound such as η > 0 or T > 0, or none finite).
Values OutOfRange(const StructureFit& f, const Values& base, bool* blocked) {
  Values out;
  for (const ParameterEstimate& e : f.oe.estimates) {
    const model::ParameterFamily* family = model::FamilyOf(e.name);
    if (!family || family->Admissible(e.value)) continue;
    const auto b = base.find(e.name);
    if (b != base.end() && !family->Admissible(b->second)) continue;
    const bool low = e.value < family->lower;
    const double bound = low ? family->lower : family->upper;
    if (!std::isfinite(bound) || (low && family->lower_open)) {
      *blocked = true;
      continue;
    }
    out[e.name] = bound;
  }
  return out;
}

// Maximum likelihood within the admissible ranges by an active set: a parameter the free fit
// puts outside its range is held at the bound it crossed, and the rest refitted.
StructureFit FitPhysical(const model::Vehicle& vehicle, const model::ModelStructure& structure,
                         const std::vector<const TrialData*>& trials, const Values& start,
                         const std::set<std::string>& dropped, const OutputErrorOptions& options,
                         const Values& base, Values held) {
  StructureFit f = FitStructure(vehicle, structure, trials, start, dropped, options, held);
  for (int pass = 0; pass < 3 && f.oe.ok(); ++pass) {
    bool blocked = false;
    const Values out = OutOfRange(f, base, &blocked);
    if (out.empty() || blocked) break;
    for (const auto& [name, bound] : out) {
      f.held_at_bound.insert(name);
      held[name] = bound;
    }
    const std::set<std::string> at_bound = f.held_at_bound;
    f = FitStructure(vehicle, structure, trials, start, dropped, options, held);
    f.held_at_bound = at_bound;
  }
  return f;
}

DofIdentification WithStructureFit(const DofIdentification& nominal, const StructureFit& f) {
  DofIdentification ext = nominal;
  ext.structure = f.structure;
  ext.parameter_names = f.model->parameter_names();
  ext.theta = f.oe.theta;
  ext.covariance = f.oe.covariance;
  ext.params = f.oe.estimates;
  for (const auto& [name, value] : f.held) {
    if (FindEstimate(ext.params, name) < 0) {
      ext.params.push_back({name, value, 0.0, ParameterState::kFixed});
    }
  }
  ext.estimator = FinalEstimator::kOutputError;
  return ext;
}

DofIdentification AsIdentification(const DofIdentification& nominal, const StructureFit& f,
                                   const std::vector<const TrialData*>& trials, double step_s) {
  DofIdentification ext = WithStructureFit(nominal, f);
  ValidationOptions vo;
  vo.step_s = step_s;
  std::vector<TrialFit> fits;
  for (const TrialData* t : trials) {
    const Eigen::VectorXd x0 = FittedMovingStart(f.oe, t->index);
    fits.push_back(ValidateTrial(*f.model, f.oe.theta, *t, vo, x0.size() ? &x0 : nullptr));
  }
  std::sort(fits.begin(), fits.end(),
            [](const TrialFit& a, const TrialFit& b) { return a.trial < b.trial; });
  ext.fit = Summarize(std::move(fits));
  return ext;
}

}  // namespace uuvplan::ident
