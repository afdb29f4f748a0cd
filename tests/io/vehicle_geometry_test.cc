// The thruster geometry keys of the vehicle file (docs/formats.md): position, direction,
// reversible, thrust.dead_band, jet_clearance, restoring; mappings derived when the file has no
// table; each fault named with its file, line and key.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <string>

#include "io/io_test_util.h"
#include "uuvplan/io/vehicle_yaml.h"

namespace uuvplan::model {
namespace {

using testing::ErrorOf;
using ::testing::HasSubstr;
using testing::ScratchDir;

// Two thrusters on the beam (y = ±0.2 m) pushing forward, one vertical at the centre.
std::string Vehicle3(const std::string& first_direction = "[1, 0, 0]",
                     const std::string& extra = "") {
  return "name: geo\nmass: 20\nsize: [1.0, 0.6, 0.4]\nthrusters:\n"
         "  - {name: L, thrust: {model: square, c_pos: 20, c_neg: 15, dead_band: 0.05},\n"
         "     command: [-1, 1], position: [-0.3, -0.2, 0], direction: " +
         first_direction +
         ", reversible: true}\n"
         "  - {name: R, thrust: {model: square, c_pos: 20, c_neg: 15}, command: [-1, 1],\n"
         "     position: [-0.3, 0.2, 0], direction: [1, 0, 0]}\n"
         "  - {name: V, thrust: {model: square, c_pos: 20, c_neg: 15}, command: [-1, 1],\n"
         "     position: [0, 0, 0], direction: [0, 0, 1]}\n" +
         extra;
}

TEST(VehicleGeometry, GeometryOnlyVehicleGetsDerivedMappings) {
  ScratchDir dir;
  const Vehicle v = io::ReadVehicle(dir.Write("geo.yaml", Vehicle3()));
  ASSERT_TRUE(v.thrusters[0].geometry);
  EXPECT_EQ(v.thrusters[0].geometry->position, (std::array<double, 3>{-0.3, -0.2, 0}));
  EXPECT_TRUE(v.thrusters[0].reversible);
  EXPECT_FALSE(v.thrusters[1].reversible);  // the papers' rule by default
  EXPECT_EQ(v.thrusters[0].model.dead_band, 0.05);
  std::vector<std::string> names;
  for (const auto& m : v.mappings) names.push_back(m.name);
  EXPECT_EQ(names, (std::vector<std::string>{"surge-all", "heave-all", "yaw-all"}));
}

// The table wins for the DOFs it gives; the geometry fills the others.
TEST(VehicleGeometry, TableWinsWhereItGivesADof) {
  ScratchDir dir;
  const Vehicle v = io::ReadVehicle(dir.Write(
      "geo.yaml", Vehicle3("[1, 0, 0]", "mappings:\n  push: {dof: surge, shares: {L: 1}}\n")));
  std::vector<std::string> names;
  for (const auto& m : v.mappings) names.push_back(m.name);
  EXPECT_EQ(names, (std::vector<std::string>{"push", "heave-all", "yaw-all"}));
}

TEST(VehicleGeometry, FaultsNameTheKey) {
  ScratchDir dir;
  // [1, 1, 0] has norm 1.414: refused, not normalised.
  EXPECT_THAT(ErrorOf([&] { io::ReadVehicle(dir.Write("a.yaml", Vehicle3("[1, 1, 0]"))); }),
              HasSubstr("thrusters[0].direction: expected a unit vector [x, y, z] of positive "
                        "thrust (body frame), norm within 1e-3 of 1, got norm 1.41421"));
  // A unit vector written with 4 digits is normalised.
  const Vehicle v = io::ReadVehicle(dir.Write("b.yaml", Vehicle3("[0.7071, 0.7071, 0]")));
  EXPECT_NEAR(v.thrusters[0].geometry->direction[0], std::sqrt(0.5), 1e-15);
  std::string only_position = Vehicle3();
  only_position.replace(only_position.find(", direction: [0, 0, 1]"), 22, "");
  EXPECT_THAT(ErrorOf([&] { io::ReadVehicle(dir.Write("c.yaml", only_position)); }),
              HasSubstr("thrusters[2]: expected both position and direction (or neither), got "
                        "only position"));
  EXPECT_THAT(ErrorOf([&] {
                io::ReadVehicle(dir.Write("d.yaml", Vehicle3("[1, 0, 0]", "restoring: [yaw]\n")));
              }),
              HasSubstr("restoring[0]: expected roll or pitch"));
  std::string in_mm = Vehicle3();
  in_mm.replace(in_mm.find("[-0.3, 0.2, 0]"), 14, "[-300, 200, 0]");
  EXPECT_THAT(ErrorOf([&] { io::ReadVehicle(dir.Write("e.yaml", in_mm)); }),
              HasSubstr("thrusters[1].position: expected a position [x, y, z] in m"));
}

}  // namespace
}  // namespace uuvplan::model
