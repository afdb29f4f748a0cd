// Stage 1 of identifying a DOF, prepare: which trials fit and which validate, the model
// structure they call for, and whether the logged force looks like a controller's.
#include <algorithm>
#include <cmath>

#include "identify_stages.h"
#include "uuvplan/model/util/median.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {

double CommandRoughness(const TrialData& d) {
  // The sequence of distinct consecutive command values (holds removed).
  std::vector<double> v;
  for (double f : d.force) {
    if (v.empty() || f != v.back()) v.push_back(f);
  }
  if (v.size() < 10) return 0.0;
  // A designed piecewise-constant input (steps, legs, telegraph, PRBS) revisits a few levels.
  std::vector<double> levels = v;
  std::sort(levels.begin(), levels.end());
  levels.erase(std::unique(levels.begin(), levels.end()), levels.end());
  if (levels.size() <= std::max<std::size_t>(10, v.size() / 10)) return 0.0;
  // Many levels: smooth (a sampled sine) or irregular (a controller reacting to noise). The
  // third difference of a sine sampled at ω·Δt is (ω·Δt)² times its first; of noise, ≥ 1.
  std::vector<double> d1, d3;
  for (std::size_t i = 1; i < v.size(); ++i) {
    d1.push_back(std::abs(v[i] - v[i - 1]));
    if (i >= 3) d3.push_back(std::abs(v[i] - 3 * v[i - 1] + 3 * v[i - 2] - v[i - 3]));
  }
  const double m1 = model::Median(std::move(d1));
  return m1 > 0 ? model::Median(std::move(d3)) / m1 : 0.0;
}

namespace stages {

namespace {

// The DOF's warnings about a trial's data: columns without values, many outliers.
void WarnAboutData(const TrialData& d, const OutlierOptions& outliers, DofIdentification* r) {
  for (const std::string& c : d.unusable_columns) {
    r->warnings.push_back(d.name + ": column " + c + " has no usable value (all NaN?): the " +
                          "trial is identified from its other measurement only");
  }
  const std::string pos = OutlierFinding(d.name, "position", d.position_outliers.size(),
                                         d.position.size() + d.position_outliers.size(), outliers);
  const std::string vel = OutlierFinding(d.name, "velocity", d.velocity_outliers.size(),
                                         d.velocity.size() + d.velocity_outliers.size(), outliers);
  for (const std::string& w : {pos, vel}) {
    if (!w.empty()) r->warnings.push_back(w);
  }
  if (d.force_gap_t1 > d.force_gap_t0) {
    r->warnings.push_back(d.name + ": no force value for " +
                          model::Significant(d.force_gap_t1 - d.force_gap_t0, 4) +
                          " s (t = " + model::Significant(d.force_gap_t0 + d.time_offset, 4) +
                          " to " + model::Significant(d.force_gap_t1 + d.time_offset, 4) +
                          " s of the log): the last command is held across it (zero-order "
                          "hold); if it changed there, the estimates are biased");
  }
}

}  // namespace

DofTrials SelectTrials(model::Dof dof, const std::vector<TrialData>& all,
                       const OutlierOptions& outliers, DofIdentification* r) {
  DofTrials t;
  for (const TrialData& d : all) {
    if (d.dof != dof) continue;
    if (d.use == model::TrialUse::kFit) {
      t.fit.push_back(&d);
      r->fit_trials.push_back(d.index);
      for (const auto& m : d.mappings_used) {
        if (std::find(t.mappings.begin(), t.mappings.end(), m) == t.mappings.end()) {
          t.mappings.push_back(m);
        }
      }
      t.ballast_values.insert(d.ballast_steps);
    } else {
      t.validate.push_back(&d);
      r->validate_trials.push_back(d.index);
    }
  }
  for (const TrialData& d : all) {
    if (d.dof == dof) WarnAboutData(d, outliers, r);
  }
  return t;
}

model::ModelStructure ChooseStructure(const model::Vehicle& vehicle, model::Dof dof,
                                      const DofTrials& trials, const IdentifyOptions& o) {
  if (auto it = o.structures.find(dof); it != o.structures.end()) {
    model::ModelStructure s = it->second;
    s.dof = dof;
    return s;
  }
  return model::ModelStructure::Standard(vehicle, dof, trials.mappings,
                                         trials.ballast_values.size() > 1);
}

// Closed loop when told so, or (kAuto) when most fit trials' commands are rough
// (CommandRoughness > 0.4: a sine sampled at ≥ 10 points a period is below it, tartan's
// controller commands 0.79–50).
bool SuspectClosedLoop(const std::vector<const TrialData*>& fit, ClosedLoop setting) {
  int rough = 0;
  for (const TrialData* d : fit) {
    if (CommandRoughness(*d) > 0.4) ++rough;
  }
  return setting == ClosedLoop::kYes ||
         (setting == ClosedLoop::kAuto && 2 * rough > static_cast<int>(fit.size()));
}

}  // namespace stages
}  // namespace uuvplan::ident
