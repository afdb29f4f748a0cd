// Points of the a priori box as vehicles (box_points.h).
#include "uuvplan/planner/design/box_points.h"

#include <algorithm>
#include <cmath>

#include "uuvplan/model/parameter.h"
#include "uuvplan/model/prior.h"

namespace uuvplan::planner {
namespace {

BoxPoint Point(double m, double drag_factor, const model::DragPrior& drag) {
  return {m, drag_factor * drag.k, drag_factor * drag.kq, drag_factor};
}

}  // namespace

std::vector<BoxPoint> VerdictPoints(const model::Vehicle& vehicle, model::Dof dof,
                                    const BoxOptions& options) {
  const auto mb = vehicle.InertiaBounds(dof);
  const model::DragPrior drag = model::DragOf(vehicle, dof, options.fallback_drag_rel_sigma).drag;
  // The drag axis of APrioriBox: k and kq together × [1 − n·rs, 1 + n·rs] (at least 0.05).
  const double half = options.drag_sigmas * drag.rel_sigma;
  const double lo = std::max(0.05, 1.0 - half), hi = 1.0 + half;
  std::vector<BoxPoint> out = {Point(0.5 * (mb[0] + mb[1]), 1.0, drag)};
  for (double m : {mb[0], mb[1]}) {
    for (double f : {lo, hi}) out.push_back(Point(m, f, drag));
  }
  return out;
}

model::Vehicle VehicleAt(const model::Vehicle& vehicle, model::Dof dof, const BoxPoint& point) {
  model::Vehicle v = vehicle;
  model::DofPrior& prior = v.priors[dof];
  const double added = point.m / v.RigidInertia(dof) - 1.0;
  prior.added_mass = std::array<double, 2>{added, added};
  prior.drag = model::DragPrior{point.k, point.kq, 0.0};
  return v;
}

model::Vehicle VehicleOfTruth(const model::Truth& truth) {
  model::Vehicle v = truth.vehicle;
  for (const auto& [dof, t] : truth.dofs) {
    const auto m = t.params.find(model::param::kMass);
    const auto k = t.params.find(model::param::kLinearDrag);
    const auto kq = t.params.find(model::param::kQuadraticDrag);
    if (m == t.params.end() || k == t.params.end() || kq == t.params.end()) continue;
    v = VehicleAt(v, dof, BoxPoint{m->second, k->second, kq->second, std::nan("")});
  }
  return v;
}

}  // namespace uuvplan::planner
