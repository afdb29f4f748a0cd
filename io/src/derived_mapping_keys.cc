#include "derived_mapping_keys.h"

#include <algorithm>
#include <string>
#include <vector>

#include "uuvplan/model/configuration_matrix.h"
#include "uuvplan/model/derived_mappings.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::io {

using namespace model;  // NOLINT: the vocabulary of the vehicle file

namespace {

// The DOFs the table gives no mapping for.
std::vector<Dof> Uncovered(const Vehicle& vehicle) {
  std::vector<Dof> dofs;
  for (Dof dof : kAllDofs) {
    if (vehicle.MappingsOf(dof).empty()) dofs.push_back(dof);
  }
  return dofs;
}

// Geometry is given for every thruster or for none: a thruster without it cannot take part in
// an allocation, and silently leaving it out would change what each mapping means.
void CheckGeometryOfEveryThruster(const MapValue& root, const Vehicle& vehicle) {
  const std::vector<Value> items = List(root.Required("thrusters"), "a list of thrusters");
  for (std::size_t i = 0; i < vehicle.thrusters.size() && i < items.size(); ++i) {
    if (vehicle.thrusters[i].geometry) continue;
    items[i].Fail(
        "missing position and direction: other thrusters give theirs, and the "
        "mappings derived from the geometry need every thruster's (give all or none)");
  }
}

}  // namespace

MappingDerivationOptions ParseMappingDerivation(const MapValue& root) {
  MappingDerivationOptions options;
  if (const Value c = root.Optional("jet_clearance"); !c.absent()) {
    options.jet_clearance = Positive(c);
  }
  if (const Value r = root.Optional("restoring"); !r.absent()) {
    for (const Value& item :
         List(r, "a list of DOFs held by hydrostatic restoring (roll, pitch)")) {
      const Dof dof = DofValue(item);
      if (dof != Dof::kRoll && dof != Dof::kPitch) {
        item.Expected("roll or pitch (only they have a hydrostatic restoring moment)");
      }
      if (std::find(options.restoring.begin(), options.restoring.end(), dof) !=
          options.restoring.end()) {
        item.Fail("'" + std::string(DofName(dof)) + "' is listed twice");
      }
      options.restoring.push_back(dof);
    }
  }
  return options;
}

void AddDerivedMappings(const MapValue& root, Vehicle* vehicle) {
  const bool any_geometry = std::any_of(vehicle->thrusters.begin(), vehicle->thrusters.end(),
                                        [](const Thruster& t) { return t.geometry.has_value(); });
  if (!any_geometry) {
    if (vehicle->mappings.empty()) root.Required("mappings");  // the error it always was
    return;
  }
  CheckGeometryOfEveryThruster(root, *vehicle);
  const DerivedMappings derived = DeriveMappings(vehicle->thrusters, vehicle->size,
                                                 vehicle->mapping_derivation, Uncovered(*vehicle));
  for (const ThrustMapping& m : derived.mappings) {
    if (vehicle->MappingIndex(m.name) < 0) vehicle->mappings.push_back(m);
  }
  if (vehicle->mappings.empty()) {
    root.self().Fail(
        "no mapping: the file has no mappings table and no DOF is driven alone by "
        "the thrusters' geometry (" +
        Join(derived.unreachable, "; ") + ")");
  }
}

}  // namespace uuvplan::io
