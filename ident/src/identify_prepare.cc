// Stage 1 of identifying a DOF, prepare: which trials fit and which validate, the model
// structure they call for, and whether the logged force looks like a controller's.
#include <algorithm>
#include <cmath>
#include <unordered_set>
#include <vector>

#include "identify_stages.h"
#include "uuvplan/model/util/median.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {

namespace {

// Calls `visit` on each command of the force rows, holds removed (a row repeating the previous
// row's value is the same command), in order.
template <class Visit>
void ForEachCommand(const std::vector<double>& force, const Visit& visit) {
  for (std::size_t i = 0; i < force.size(); ++i) {
    if (i == 0 || force[i] != force[i - 1]) visit(force[i]);
  }
}

// Whether the commands take at most `limit` distinct values (counted until past the limit: a
// force that changes at every row keeps limit + 1 values, not a sorted copy of every row).
bool AtMostLevels(const std::vector<double>& force, std::size_t limit) {
  std::unordered_set<double> levels;
  bool few = true;
  ForEachCommand(force, [&](double f) {
    if (few) few = levels.insert(f).second ? levels.size() <= limit : few;
  });
  return few;
}

// The median of |Δ^order φ| over the commands (order 1 or 3).
double MedianDifference(const std::vector<double>& force, std::size_t commands, int order) {
  std::vector<double> diff;
  diff.reserve(commands);
  double c[4] = {0, 0, 0, 0};  // the last four commands, newest first
  std::size_t seen = 0;
  ForEachCommand(force, [&](double f) {
    c[3] = c[2], c[2] = c[1], c[1] = c[0], c[0] = f;
    if (++seen <= static_cast<std::size_t>(order)) return;
    diff.push_back(std::abs(order == 1 ? c[0] - c[1] : c[0] - 3 * c[1] + 3 * c[2] - c[3]));
  });
  return model::Median(std::move(diff));
}

}  // namespace

double CommandRoughness(const TrialData& d) {
  // The sequence of distinct consecutive command values (holds removed), read in place.
  std::size_t n = 0;
  ForEachCommand(d.force, [&n](double) { ++n; });
  if (n < 10) return 0.0;
  // A designed piecewise-constant input (steps, legs, telegraph, PRBS) revisits a few levels.
  if (AtMostLevels(d.force, std::max<std::size_t>(10, n / 10))) return 0.0;
  // Many levels: smooth (a sampled sine) or irregular (a controller reacting to noise). The
  // third difference of a sine sampled at ω·Δt is (ω·Δt)² times its first; of noise, ≥ 1.
  const double m1 = MedianDifference(d.force, n, 1);
  return m1 > 0 ? MedianDifference(d.force, n, 3) / m1 : 0.0;
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
