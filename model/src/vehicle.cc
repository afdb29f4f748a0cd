#include "uuvplan/model/vehicle.h"

#include <algorithm>

namespace uuvplan::model {

double Vehicle::RigidInertia(Dof dof) const {
  if (!IsRotational(dof)) return mass;
  if (auto it = inertia.find(dof); it != inertia.end()) return it->second;
  // Uniform box (ref 000 §IV-D): I = m·(a² + b²)/12 over the two sides normal to the axis.
  const double l = size[0], w = size[1], h = size[2];
  switch (dof) {
    case Dof::kRoll:
      return mass * (w * w + h * h) / 12.0;
    case Dof::kPitch:
      return mass * (l * l + h * h) / 12.0;
    default:
      return mass * (l * l + w * w) / 12.0;  // yaw
  }
}

std::array<double, 2> Vehicle::AddedMassBounds(Dof dof) const {
  if (auto it = priors.find(dof); it != priors.end() && it->second.added_mass) {
    return *it->second.added_mass;
  }
  return added_mass;
}

std::array<double, 2> Vehicle::InertiaBounds(Dof dof) const {
  const double rigid = RigidInertia(dof);
  const auto b = AddedMassBounds(dof);
  return {rigid * (1.0 + b[0]), rigid * (1.0 + b[1])};
}

int Vehicle::MappingIndex(const std::string& n) const {
  for (std::size_t i = 0; i < mappings.size(); ++i) {
    if (mappings[i].name == n) return static_cast<int>(i);
  }
  return -1;
}

int Vehicle::ThrusterIndex(const std::string& n) const {
  for (std::size_t i = 0; i < thrusters.size(); ++i) {
    if (thrusters[i].name == n) return static_cast<int>(i);
  }
  return -1;
}

std::vector<int> Vehicle::MappingsOf(Dof dof) const {
  std::vector<int> out;
  for (std::size_t i = 0; i < mappings.size(); ++i) {
    if (mappings[i].dof == dof) out.push_back(static_cast<int>(i));
  }
  return out;
}

bool Vehicle::Reverses(int mapping) const {
  bool working = false;
  for (const auto& [thruster, share] : mappings.at(mapping).shares) {
    if (share == 0.0) continue;
    if (!thrusters.at(thruster).reversible) return false;
    working = true;
  }
  return working;
}

double Vehicle::WorkingThrustFloor() const {
  double floor = min_thrust;
  for (const Thruster& t : thrusters) {
    floor = std::max({floor, t.model.EdgeThrust(+1), t.model.EdgeThrust(-1)});
  }
  return floor;
}

}  // namespace uuvplan::model
