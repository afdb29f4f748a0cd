// What is known of a DOF before any trial: one policy for the nominal parameter vector, used
// by identification (its starting point and fallback) and by planning (the centre of the
// robust box).
#pragma once

#include <array>
#include <map>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

enum class DragSource { kVehicleFile, kThrustRange, kBluffBody };

/// A priori drag of a DOF and where it comes from.
struct APrioriDrag {
  DragPrior drag;
  DragSource source = DragSource::kVehicleFile;
  double thrust = 0.0;  ///< kThrustRange: the largest thrust along the DOF (N or N·m)
  bool from_vehicle_file() const { return source == DragSource::kVehicleFile; }
};

/// Terminal speed assumed at the largest thrust when the vehicle file gives no drag: CHOSEN
/// 1 m/s for a translation and 1 rad/s for a rotation — a pool vehicle's thrusters are sized
/// for about that (ROMEO's surge truth gives 0.9 m/s at 350 N, URIS's yaw 3.8 rad/s at its
/// 8 N·m with a linear drag only, ref 004 Table 4).
inline double TerminalSpeed(Dof /*dof*/) { return 1.0; }

/// The quadratic drag of a bluff box of `size` (length, width, height): ½·ρ·C_D·A for a
/// translation (ρ = 1000 kg/m³, C_D = 1, A the frontal area across the DOF), ρ·C_D·h·l⁴/64 for
/// a rotation (h along the axis, l the longer side across it), in N·s²/m² or N·m·s²/rad².
double BluffBodyQuadraticDrag(const std::array<double, 3>& size, Dof dof);

/// The vehicle file's drag fit (dofs.<dof>.drag); else the drag that holds the vehicle at
/// TerminalSpeed v_t under the largest thrust F_max of its mappings along the DOF, with a
/// linear part a tenth of the quadratic there: kq = F_max/(1.1·v_t²), k = 0.1·kq·v_t — it
/// scales with the vehicle (a 59 kg sphere and a 450 kg frame get drags in proportion to
/// their thrusters); else (no thruster on the DOF) a bluff body of `size`: kq = ½·ρ·C_D·A for
/// a translation (ρ = 1000 kg/m³, C_D = 1, A the frontal area), ρ·C_D·h·l⁴/64 for a rotation,
/// k = 0.1·kq. Fallbacks carry relative uncertainty `fallback_rel_sigma`.
APrioriDrag DragOf(const Vehicle& vehicle, Dof dof, double fallback_rel_sigma);

/// The assumption behind DragOf's answer in one sentence, with the numbers and units: what a
/// note prints beside a design or an estimate that rests on it.
std::string DragAssumption(Dof dof, const APrioriDrag& drag);

/// The nominal value of each of `names`: m at the middle of the vehicle's inertia bounds, k and
/// kq from DragOf, every other parameter at its family's a priori value (parameter.h: η = 1,
/// most effects 0).
std::map<std::string, double> NominalValues(const Vehicle& vehicle, Dof dof,
                                            const std::vector<std::string>& names,
                                            double fallback_rel_sigma = 0.5);

}  // namespace uuvplan::model
