#include "uuvplan/model/prior.h"

#include <cmath>

#include "uuvplan/model/parameter.h"

namespace uuvplan::model {

namespace {

// Bluff-body quadratic drag (prior.h).
double BluffBodyQuadraticDrag(const Vehicle& vehicle, Dof dof) {
  const double l = vehicle.size[0], w = vehicle.size[1], h = vehicle.size[2];
  constexpr double kRho = 1000.0, kCd = 1.0;
  switch (dof) {
    case Dof::kSurge: return 0.5 * kRho * kCd * w * h;
    case Dof::kSway: return 0.5 * kRho * kCd * l * h;
    case Dof::kHeave: return 0.5 * kRho * kCd * l * w;
    case Dof::kRoll: return kRho * kCd * l * std::pow(std::max(w, h), 4) / 64.0;
    case Dof::kPitch: return kRho * kCd * w * std::pow(std::max(l, h), 4) / 64.0;
    case Dof::kYaw: return kRho * kCd * h * std::pow(std::max(l, w), 4) / 64.0;
  }
  return 0.0;
}

// The nominal value of `name` (a standard drag parameter even when not in `values`).
double DragOrNominal(const std::map<std::string, double>& values, const APrioriDrag& drag,
                     std::string_view name) {
  if (name == param::kLinearDrag) return drag.drag.k;
  if (name == param::kQuadraticDrag) return drag.drag.kq;
  const auto it = values.find(std::string(name));
  return it == values.end() ? 0.0 : it->second;
}

}  // namespace

APrioriDrag DragOf(const Vehicle& vehicle, Dof dof, double fallback_rel_sigma) {
  const auto prior = vehicle.priors.find(dof);
  if (prior != vehicle.priors.end() && prior->second.drag) return {*prior->second.drag, true};
  const double kq = BluffBodyQuadraticDrag(vehicle, dof);
  return {{0.1 * kq, kq, fallback_rel_sigma}, false};
}

std::map<std::string, double> NominalValues(const Vehicle& vehicle, Dof dof,
                                            const std::vector<std::string>& names,
                                            double fallback_rel_sigma) {
  const auto bounds = vehicle.InertiaBounds(dof);
  const APrioriDrag drag = DragOf(vehicle, dof, fallback_rel_sigma);
  std::map<std::string, double> values;
  for (const std::string& n : names) {
    const ParameterFamily* f = FamilyOf(n);
    values[n] = f ? f->APriori() : 0.0;
  }
  const double m = 0.5 * (bounds[0] + bounds[1]);
  const std::pair<const char*, double> known[] = {{param::kMass, m > 0 ? m : 1.0},
                                                  {param::kLinearDrag, drag.drag.k},
                                                  {param::kQuadraticDrag, drag.drag.kq}};
  for (const auto& [name, value] : known) {
    if (values.count(name)) values[name] = value;
  }
  // A parameter whose file value defaults to another's starts there too (k_neg at k).
  for (auto& [name, value] : values) {
    const ParameterFamily* f = FamilyOf(name);
    if (f && !f->defaults_to.empty()) value = DragOrNominal(values, drag, f->defaults_to);
  }
  return values;
}

}  // namespace uuvplan::model
