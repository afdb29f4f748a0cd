#include "uuvplan/model/prior.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "uuvplan/model/parameter.h"

namespace uuvplan::model {

double BluffBodyQuadraticDrag(const std::array<double, 3>& size, Dof dof) {
  const double l = size[0], w = size[1], h = size[2];
  constexpr double kRho = 1000.0, kCd = 1.0;
  switch (dof) {
    case Dof::kSurge:
      return 0.5 * kRho * kCd * w * h;
    case Dof::kSway:
      return 0.5 * kRho * kCd * l * h;
    case Dof::kHeave:
      return 0.5 * kRho * kCd * l * w;
    case Dof::kRoll:
      return kRho * kCd * l * std::pow(std::max(w, h), 4) / 64.0;
    case Dof::kPitch:
      return kRho * kCd * w * std::pow(std::max(l, h), 4) / 64.0;
    case Dof::kYaw:
      return kRho * kCd * h * std::pow(std::max(l, w), 4) / 64.0;
  }
  return 0.0;
}

namespace {

// The largest generalised force (N or N·m) the thrusters give along `dof`: over its mappings
// and both directions, the force at which the first working thruster reaches its limit. 0 when
// no mapping acts on the DOF.
double LargestThrust(const Vehicle& vehicle, Dof dof) {
  double best = 0.0;
  for (int mi : vehicle.MappingsOf(dof)) {
    for (int sign : {+1, -1}) {
      double limit = std::numeric_limits<double>::infinity();
      for (const auto& [ti, share] : vehicle.mappings[mi].shares) {
        if (share == 0.0) continue;
        const Thruster& th = vehicle.thrusters.at(ti);
        const double t = share * sign > 0 ? th.MaxForwardThrust() : th.MaxReverseThrust();
        limit = std::min(limit, t / std::abs(share));
      }
      if (std::isfinite(limit)) best = std::max(best, limit);
    }
  }
  return best;
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
  if (prior != vehicle.priors.end() && prior->second.drag) {
    return {*prior->second.drag, DragSource::kVehicleFile, 0.0};
  }
  const double thrust = LargestThrust(vehicle, dof);
  if (thrust > 0) {
    // k·v_t + kq·v_t² = F_max with k = 0.1·kq·v_t (prior.h).
    const double v = TerminalSpeed(dof);
    const double kq = thrust / (1.1 * v * v);
    return {{0.1 * kq * v, kq, fallback_rel_sigma}, DragSource::kThrustRange, thrust};
  }
  const double kq = BluffBodyQuadraticDrag(vehicle.size, dof);
  return {{0.1 * kq, kq, fallback_rel_sigma}, DragSource::kBluffBody, 0.0};
}

std::string DragAssumption(Dof dof, const APrioriDrag& drag) {
  std::ostringstream s;
  const std::string name(DofName(dof));
  const bool rot = IsRotational(dof);
  s.precision(4);
  switch (drag.source) {
    case DragSource::kVehicleFile:
      s << name << ": a priori drag from the vehicle file (dofs." << name << ".drag)";
      break;
    case DragSource::kThrustRange:
      s << name << ": no a priori drag (dofs." << name << ".drag in the vehicle file); assumed "
        << "that the largest thrust, " << drag.thrust << " " << ForceUnit(dof)
        << ", holds the vehicle at " << TerminalSpeed(dof) << (rot ? " rad/s" : " m/s")
        << ": k = " << drag.drag.k << " " << Unit(param::kLinearDrag, dof)
        << ", kq = " << drag.drag.kq << " " << Unit(param::kQuadraticDrag, dof)
        << " (k·v = 0.1·kq·v² there), ±" << 100 * drag.drag.rel_sigma << "%";
      break;
    case DragSource::kBluffBody:
      s << name << ": no a priori drag and no thruster on " << name << "; a bluff body of `size` "
        << "(C_D = 1): k = " << drag.drag.k << ", kq = " << drag.drag.kq << ", ±"
        << 100 * drag.drag.rel_sigma << "%";
      break;
  }
  return s.str();
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
