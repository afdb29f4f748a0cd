// Thrust mappings derived from the thrusters' geometry: ref 000 Table I found automatically.
//
// With B the configuration matrix (configuration_matrix.h), a mapping of DOF k is an allocation
// tau = s·phi with B·s = e_k: a unit force (moment) on k and none on the other DOFs, each within
// MappingDerivationOptions::purity_tolerance of it (moments read as forces at
// DerivationLength(size); the `restoring` DOFs exempt). For each DOF, in this order:
//   <dof>-all        the minimum-norm allocation over every thruster, s = B⁺·e_k (Table I's
//                    "horizontal all", min ½·τᵀτ), thrusters with a zero share left out;
//   <dof>-<T>-<T>…   every minimal subset of thrusters (B restricted to it has full column rank)
//                    whose unique allocation gives k alone with every thruster working: Table I's
//                    surge front / rear, sway left / right and the yaw pairs. Ordered by size,
//                    then by the thrusters' order in the file; a subset equal to <dof>-all is
//                    not repeated.
// A trial keeps the sign of phi, so no thruster of a mapping reverses during it. Each mapping's
// open_water is jet_clearance.h's rule applied to its thrusters for each sign of phi.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"
#include "uuvplan/model/mapping.h"
#include "uuvplan/model/mapping_derivation_options.h"
#include "uuvplan/model/thruster.h"

namespace uuvplan::model {

struct DerivedMappings {
  std::vector<ThrustMapping> mappings;  ///< shares index the `thrusters` given
  /// One sentence per requested DOF that no allocation drives alone, with the largest residual.
  std::vector<std::string> unreachable;
};

/// Mappings of `dofs` (in kAllDofs order) for thrusters that all have geometry; a thruster
/// without geometry takes no part. `size` is the vehicle's [length, width, height] (m).
DerivedMappings DeriveMappings(const std::vector<Thruster>& thrusters,
                               const std::array<double, 3>& size,
                               const MappingDerivationOptions& options,
                               const std::vector<Dof>& dofs = {kAllDofs.begin(), kAllDofs.end()});

}  // namespace uuvplan::model
