// What is known of a DOF before any trial: one policy for the nominal parameter vector, used
// by identification (its starting point and fallback) and by planning (the centre of the
// robust box).
#pragma once

#include <map>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

/// A priori drag of a DOF and where it comes from.
struct APrioriDrag {
  DragPrior drag;
  bool from_vehicle_file = false;  ///< false: the bluff-body estimate below
};

/// The vehicle file's drag fit (dofs.<dof>.drag); else a bluff body of the vehicle's `size`:
/// kq = ½·ρ·C_D·A for a translation (ρ = 1000 kg/m³, C_D = 1 for an open frame, A the frontal
/// area), ρ·C_D·h·l⁴/64 for a rotation (a plate of length l and height h about its centre),
/// k = 0.1·kq, with relative uncertainty `fallback_rel_sigma`.
APrioriDrag DragOf(const Vehicle& vehicle, Dof dof, double fallback_rel_sigma);

/// The nominal value of each of `names`: m at the middle of the vehicle's inertia bounds, k and
/// kq from DragOf, every other parameter at its family's a priori value (parameter.h: η = 1,
/// most effects 0).
std::map<std::string, double> NominalValues(const Vehicle& vehicle, Dof dof,
                                            const std::vector<std::string>& names,
                                            double fallback_rel_sigma = 0.5);

}  // namespace uuvplan::model
