// A payload on a known vehicle (docs/planning.md "A payload on a known vehicle"): the
// vehicle the base file describes — usually identified by `identify`, `loop` or `diagnose
// --write-vehicle` — with a body of known mass, displacement, size and place added. What the
// payload changes is bounded by rules from its geometry; what it does not change (thrusters,
// their lag and thrust map, the sensors) is kept as the base gives it. The combined vehicle's
// model is then an a priori box about the base's estimates: the planner plans only what the
// payload made uncertain.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

struct Payload {
  double mass = 0.0;                              ///< kg in air
  double volume = 0.0;                            ///< m³ of water displaced
  std::array<double, 3> size = {0, 0, 0};         ///< m: length, width, height of its box
  std::array<double, 3> cg = {0, 0, 0};           ///< m: its centre from the base's (x fwd, z down)
  std::array<double, 2> added_mass = {0.1, 1.0};  ///< fraction of its rigid inertia [lo, hi]
  /// Installation coefficients "<mapping>.<pos|neg>" whose jets the payload may obstruct: the
  /// direction stops being open water and its η is unknown again.
  std::vector<std::string> blocks;
};

/// Water density of the payload's buoyancy: CHOSEN fresh water (a pool), kg/m³.
inline constexpr double kPoolWaterDensity = 1000.0;
/// Standard gravity, m/s².
inline constexpr double kGravity = 9.80665;

/// The size of the box holding the base (centred on its origin) and the payload's box.
std::array<double, 3> CombinedSize(const std::array<double, 3>& base, const Payload& payload);

/// The payload's rigid-body inertia along `dof` about the base's origin: its mass for a
/// translation; for a rotation its box's inertia about its own centre plus the parallel-axis
/// term m·d² (d: the distance of its centre from the axis).
double PayloadRigidInertia(const Payload& payload, Dof dof);

/// The range [1, R] of the factor on the base's drag: R is the bluff-body drag of the combined
/// box over the base's (model::BluffBodyQuadraticDrag: the frontal area for a translation). 1:
/// the payload sits in the base's wake; R: it adds its whole frontal area.
std::array<double, 2> DragFactorRange(const std::array<double, 3>& base_size,
                                      const std::array<double, 3>& combined_size, Dof dof);

/// The change of a DOF's constant force (the bias): in heave the payload's weight less its
/// buoyancy, (m − ρ·V)·g (z down); 0 in the other DOFs.
double PayloadBiasChange(const Payload& payload, Dof dof);

/// The combined vehicle called `name`: the base's thrusters, mappings (the blocked directions no
/// longer open water), sensors and limits; mass, size and rotational rigid inertia with the
/// payload's added; every DOF model of the base that carries σ restated as a box about the
/// base's estimates (the rules above, DofParameters::origin = `origin`), and every a priori drag
/// scaled by DragFactorRange.
Vehicle WithPayload(const Vehicle& base, const Payload& payload, const std::string& name,
                    const std::string& origin);

}  // namespace uuvplan::model
