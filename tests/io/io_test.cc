// Readers of vehicle, pool and truth files (docs/formats.md): the fixtures of tests/data/io
// read whole, and one test per malformed input asserting the file, the line or key path, and
// the expectation named in the message.
#include "uuvplan/io/io.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "io_test_util.h"
#include "support/real_data.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/virtual_pool.h"

namespace uuvplan::model {
namespace {

using io::ReadPool;
using io::ReadTruth;
using io::ReadVehicle;

using ::testing::AllOf;
using testing::At;
using testing::ErrorOf;
using ::testing::HasSubstr;
using testing::ScratchDir;
using uuvplan::testing::RealDataPath;

// ---------------------------------------------------------------------------------------------
// Vehicle: the fixture.

TEST(ReadVehicleTest, ReadsEveryKeyOfTheFixture) {
  const Vehicle v = ReadVehicle(testing::SourcePath("tests/data/io/vehicle.yaml"));
  EXPECT_EQ(v.name, "romeo");
  EXPECT_EQ(v.mass, 450);
  EXPECT_EQ(v.size, (std::array<double, 3>{1.3, 0.9, 1.0}));
  ASSERT_EQ(v.inertia.size(), 1u);
  EXPECT_EQ(v.inertia.at(Dof::kYaw), 93.75);
  EXPECT_EQ(v.added_mass, (std::array<double, 2>{0.1, 1.0}));
  EXPECT_EQ(v.min_thrust, 2.0);

  ASSERT_EQ(v.thrusters.size(), 4u);
  EXPECT_EQ(v.thrusters[0].name, "HFL");
  EXPECT_EQ(v.thrusters[0].model.kind, ThrustModel::Kind::kSquare);
  EXPECT_EQ(v.thrusters[0].model.c_pos, 1.02);
  EXPECT_EQ(v.thrusters[0].model.c_neg, 1.09);
  EXPECT_EQ(v.thrusters[0].model.deduction, 0.0);
  EXPECT_EQ(v.thrusters[0].command_min, -10);
  EXPECT_EQ(v.thrusters[0].command_max, 10);
  EXPECT_EQ(v.thrusters[1].model.deduction, 0.1);
  EXPECT_EQ(v.thrusters[2].model.kind, ThrustModel::Kind::kPoly2);
  EXPECT_EQ(v.thrusters[2].model.a, 10.84);
  EXPECT_EQ(v.thrusters[2].model.b, -5.019);
  EXPECT_EQ(v.thrusters[3].model.a, 11.5);  // block-style thrust map

  ASSERT_EQ(v.mappings.size(), 4u);
  EXPECT_EQ(v.mappings[0].name, "surge-front");
  EXPECT_EQ(v.mappings[0].dof, Dof::kSurge);
  EXPECT_EQ(v.mappings[0].shares, (std::vector<std::pair<int, double>>{{0, 0.5}, {1, 0.5}}));
  EXPECT_EQ(v.mappings[0].open_water, OpenWater::kPositive);
  EXPECT_EQ(v.mappings[1].open_water, OpenWater::kBoth);  // the default
  EXPECT_EQ(v.mappings[1].shares, (std::vector<std::pair<int, double>>{{0, 1.0}, {1, -1.0}}));
  EXPECT_EQ(v.mappings[2].open_water, OpenWater::kNone);
  EXPECT_EQ(v.mappings[3].open_water, OpenWater::kNegative);

  ASSERT_TRUE(v.priors.at(Dof::kSurge).drag);
  EXPECT_EQ(v.priors.at(Dof::kSurge).drag->k, 46.9);
  EXPECT_EQ(v.priors.at(Dof::kSurge).drag->kq, 306.2);
  EXPECT_EQ(v.priors.at(Dof::kSurge).drag->rel_sigma, 0.2);
  EXPECT_EQ(v.priors.at(Dof::kHeave).drag->rel_sigma, 0.3);  // the default
  EXPECT_EQ(v.AddedMassBounds(Dof::kSurge), (std::array<double, 2>{0.2, 0.8}));
  EXPECT_EQ(v.AddedMassBounds(Dof::kHeave), (std::array<double, 2>{0.1, 1.0}));

  ASSERT_EQ(v.sensors.size(), 3u);
  EXPECT_EQ(v.sensors.at(Dof::kSurge).position->rate_hz, 3.33);
  EXPECT_EQ(v.sensors.at(Dof::kSurge).position->sigma, 0.02);
  EXPECT_FALSE(v.sensors.at(Dof::kSurge).velocity);
  EXPECT_EQ(v.sensors.at(Dof::kHeave).velocity->rate_hz, 5);
}

TEST(ReadVehicleTest, DefaultsOfOptionalKeys) {
  ScratchDir dir;
  const std::string path = dir.Write("minimal.yaml", R"(name: box
mass: 10
size: [1, 1, 1]
thrusters:
  - {name: T, thrust: {model: square, c_pos: 1, c_neg: 1}, command: [-1, 1]}
mappings:
  m: {dof: surge, shares: {T: 1}}
)");
  const Vehicle v = ReadVehicle(path);
  EXPECT_TRUE(v.inertia.empty());
  EXPECT_EQ(v.added_mass, (std::array<double, 2>{0.1, 1.0}));
  EXPECT_EQ(v.min_thrust, 0.0);
  EXPECT_EQ(v.mappings[0].open_water, OpenWater::kBoth);
  EXPECT_TRUE(v.priors.empty());
  EXPECT_TRUE(v.sensors.empty());
}

TEST(ReadVehicleTest, ReadsTheSharedRealVehicles) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("bluerov-yaw-2016", "tartan-pool-2022");
  const Vehicle bluerov = ReadVehicle(RealDataPath("bluerov-yaw-2016/vehicle.yaml"));
  EXPECT_EQ(bluerov.name, "bluerov-liu-2016");
  EXPECT_EQ(bluerov.thrusters.size(), 6u);
  EXPECT_EQ(bluerov.mappings.at(0).shares.size(), 2u);
  EXPECT_EQ(bluerov.AddedMassBounds(Dof::kYaw), (std::array<double, 2>{0.5, 8.0}));
  EXPECT_EQ(bluerov.sensors.at(Dof::kYaw).velocity->rate_hz, 125);

  const Vehicle tartan = ReadVehicle(RealDataPath("tartan-pool-2022/vehicle.yaml"));
  EXPECT_EQ(tartan.thrusters.size(), 8u);
  EXPECT_EQ(tartan.thrusters[4].command_min, -60);
  EXPECT_EQ(tartan.thrusters[0].model.a, 0.0);
  EXPECT_EQ(tartan.thrusters[0].model.b, 1.0);
  EXPECT_EQ(tartan.mappings.size(), 4u);
  EXPECT_EQ(tartan.sensors.size(), 4u);
}

// ---------------------------------------------------------------------------------------------
// Vehicle: files that are not YAML maps.

TEST(ReadVehicleTest, MissingFile) {
  ScratchDir dir;
  EXPECT_THAT(
      ErrorOf([&] { ReadVehicle(dir.Path("nothing.yaml")); }),
      AllOf(HasSubstr("nothing.yaml: cannot open file"), HasSubstr("No such file or directory")));
}

TEST(ReadVehicleTest, DirectoryInsteadOfFile) {
  ScratchDir dir;
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("trials")); }),
              HasSubstr("trials: cannot open file: it is a directory"));
}

TEST(ReadVehicleTest, EmptyFile) {
  ScratchDir dir;
  const std::string path = dir.Write("empty.yaml", "");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(path); }),
              HasSubstr("empty.yaml: empty file: expected a vehicle (name, mass, size"));
}

TEST(ReadVehicleTest, CommentsOnlyFileIsEmpty) {
  ScratchDir dir;
  const std::string path = dir.Write("comments.yaml", "# nothing yet\n\n");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(path); }), HasSubstr("comments.yaml: empty file"));
}

TEST(ReadVehicleTest, InvalidYamlNamesTheLine) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "size: [1.3, 0.9, 1.0]", "size: [1.3, 0.9, 1.0");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              AllOf(HasSubstr("vehicle.yaml:"), HasSubstr("not valid YAML")));
  EXPECT_GT(line, 0);
}

TEST(ReadVehicleTest, TopLevelListInsteadOfMap) {
  ScratchDir dir;
  const std::string path = dir.Write("list.yaml", "- name: romeo\n- mass: 450\n");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(path); }),
              HasSubstr("list.yaml: expected a map of vehicle keys, got a list"));
}

// ---------------------------------------------------------------------------------------------
// Vehicle: keys.

TEST(ReadVehicleTest, MissingRequiredTopLevelKey) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "mass: 450\n", "");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("vehicle.yaml: missing required key 'mass'"));
}

TEST(ReadVehicleTest, MissingRequiredNestedKeyNamesTheMapAndLine) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "c_pos: 1.02, ", "");
  EXPECT_THAT(
      ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
      HasSubstr(At("vehicle.yaml", line) + " thrusters[0].thrust: missing required key 'c_pos'"));
}

TEST(ReadVehicleTest, MissingThrusters) {
  ScratchDir dir;
  const std::string path = dir.Write("v.yaml", "name: a\nmass: 1\nsize: [1, 1, 1]\n");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(path); }),
              HasSubstr("v.yaml: missing required key 'thrusters'"));
}

TEST(ReadVehicleTest, UnknownTopLevelKeyListsTheAllowedKeys) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "mass: 450", "mas: 450");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr(At("vehicle.yaml", line) +
                        " unknown key 'mas' (allowed: name, mass, size, inertia, added_mass, "
                        "thrusters, min_thrust, mappings, jet_clearance, restoring, "
                        "max_translation_speed, max_rotation_rate, dofs, sensors)"));
}

TEST(ReadVehicleTest, UnknownNestedKeyListsTheAllowedKeysOfItsModel) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "c_neg: 1.09", "cneg: 1.09");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr(At("vehicle.yaml", line) +
                        " thrusters[0].thrust: unknown key 'cneg' (allowed: model, c_pos, c_neg, "
                        "deduction, dead_band)"));
}

TEST(ReadVehicleTest, Poly2CoefficientInSquareModel) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "c_neg: 1.09}", "c_neg: 1.09, a: 3}");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("thrusters[0].thrust: unknown key 'a' (allowed: model, c_pos, c_neg"));
}

TEST(ReadVehicleTest, RepeatedKey) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "mass: 450\n", "mass: 450\nmass: 460\n");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr(At("vehicle.yaml", line + 1) + " key 'mass' appears twice (also at line " +
                        std::to_string(line) + ")"));
}

// A vehicle file may hold a model (`diagnose --write-vehicle`): its keys are
// checked as a truth file's, by every reader of the vehicle.
TEST(ReadVehicleTest, ModelParamsAreChecked) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "    drag: {k: 10, kq: 200}", "    params: {m: 800}");
  EXPECT_NO_THROW(ReadVehicle(dir.Path("vehicle.yaml")));
  dir.Edit("vehicle.yaml", "    params: {m: 800}", "    params: {m: -800}");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("dofs.heave.params.m: expected a positive number, got '-800'"));
  dir.Edit("vehicle.yaml", "    params: {m: -800}", "    paramz: {m: 800}");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("dofs.heave: unknown key 'paramz' (allowed: drag, added_mass, params, "
                        "effects, sigma, origin)"));
}

TEST(ReadVehicleTest, UnknownDofKey) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "  heave:\n    drag", "  heav:\n    drag");
  EXPECT_THAT(
      ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
      HasSubstr(At("vehicle.yaml", line) +
                " dofs: expected a DOF (surge, sway, heave, roll, pitch, yaw), got 'heav'"));
}

// ---------------------------------------------------------------------------------------------
// Vehicle: types.

TEST(ReadVehicleTest, StringWhereNumber) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "c_pos: 1.02", "c_pos: abc");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr(At("vehicle.yaml", line) +
                        " thrusters[0].thrust.c_pos: expected a positive number, got 'abc'"));
}

TEST(ReadVehicleTest, NumberWithTrailingText) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "mass: 450", "mass: 450kg");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("mass: expected a positive number, got '450kg'"));
}

TEST(ReadVehicleTest, YamlNanIsNotANumber) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "mass: 450", "mass: .nan");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("mass: expected a positive number, got '.nan'"));
}

TEST(ReadVehicleTest, EmptyValueIsNotTheDefault) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "min_thrust: 2.0", "min_thrust:");
  EXPECT_THAT(
      ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
      HasSubstr(At("vehicle.yaml", line) + " min_thrust: expected a number >= 0, got nothing"));
}

TEST(ReadVehicleTest, MapWhereList) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "size: [1.3, 0.9, 1.0]", "size: {l: 1.3}");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("size: expected [length, width, height] in m, got a map"));
}

TEST(ReadVehicleTest, ListWhereMap) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "shares: {VF: 1.0}", "shares: [VF, 1.0]");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr(At("vehicle.yaml", line) +
                        " mappings.vertical-front.shares: expected a map {thruster: share}, "
                        "got [VF, 1.0]"));
}

TEST(ReadVehicleTest, ThrustersAsMapInsteadOfList) {
  ScratchDir dir;
  const std::string path = dir.Write("v.yaml", R"(name: a
mass: 1
size: [1, 1, 1]
thrusters: {T: {thrust: {model: square, c_pos: 1, c_neg: 1}, command: [-1, 1]}}
mappings: {m: {dof: surge, shares: {T: 1}}}
)");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(path); }),
              HasSubstr(At("v.yaml", 4) + " thrusters: expected a list of at least one thruster "
                                          "{name, thrust, command}, got a map"));
}

TEST(ReadVehicleTest, SizeNeedsThreeSides) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "size: [1.3, 0.9, 1.0]", "size: [1.3, 0.9]");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("size: expected [length, width, height] in m, got [1.3, 0.9]"));
}

// ---------------------------------------------------------------------------------------------
// Vehicle: values out of range.

TEST(ReadVehicleTest, NegativeMass) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "mass: 450", "mass: -450");
  EXPECT_THAT(
      ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
      HasSubstr(At("vehicle.yaml", line) + " mass: expected a positive number, got '-450'"));
}

TEST(ReadVehicleTest, ZeroMass) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "mass: 450", "mass: 0");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("mass: expected a positive number, got '0'"));
}

TEST(ReadVehicleTest, NonPositiveSize) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "size: [1.3, 0.9, 1.0]", "size: [1.3, 0, 1.0]");
  EXPECT_THAT(
      ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
      HasSubstr(At("vehicle.yaml", line) + " size[1]: expected a positive number, got '0'"));
}

TEST(ReadVehicleTest, NonPositiveInertia) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "inertia: {yaw: 93.75}", "inertia: {yaw: -93.75}");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("inertia.yaw: expected a positive number, got '-93.75'"));
}

TEST(ReadVehicleTest, InertiaOfATranslation) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "inertia: {yaw: 93.75}", "inertia: {surge: 93.75}");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("inertia: inertia is given for rotational DOFs only (roll, pitch, yaw), "
                        "got 'surge'"));
}

TEST(ReadVehicleTest, ZeroSensorRate) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "rate: 3.33", "rate: 0");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr(At("vehicle.yaml", line) +
                        " sensors.surge.position.rate: expected a positive number, got '0'"));
}

TEST(ReadVehicleTest, NegativeSensorSigma) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "sigma: 0.005}}\n  yaw", "sigma: -0.005}}\n  yaw");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("sensors.heave.velocity.sigma: expected a positive number, got '-0.005'"));
}

TEST(ReadVehicleTest, SensorWithoutSignal) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "yaw: {position: {rate: 10, sigma: 0.005}}", "yaw: {}");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("sensors.yaw: expected a position and/or a velocity sensor, got a map"));
}

TEST(ReadVehicleTest, SensorMissingSigma) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "{position: {rate: 3.33, sigma: 0.02}}", "{position: {rate: 3.33}}");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("sensors.surge.position: missing required key 'sigma'"));
}

TEST(ReadVehicleTest, AddedMassBoundsReversed) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "added_mass: [0.1, 1.0]", "added_mass: [1.0, 0.1]");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr(At("vehicle.yaml", line) +
                        " added_mass: expected [lo, hi] with 0 <= lo <= hi (fractions of the "
                        "rigid-body value), got [1.0, 0.1]"));
}

TEST(ReadVehicleTest, AddedMassBoundNegative) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "added_mass: [0.2, 0.8]", "added_mass: [-0.2, 0.8]");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("dofs.surge.added_mass: expected [lo, hi] with 0 <= lo <= hi"));
}

TEST(ReadVehicleTest, CommandRangeReversed) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "command: [-10, 10]\n  - name: HFR",
                            "command: [10, -10]\n  - name: HFR");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr(At("vehicle.yaml", line) +
                        " thrusters[0].command: expected a command range [lo, hi] with lo < hi, "
                        "got [10, -10]"));
}

TEST(ReadVehicleTest, CommandRangeEmpty) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "command: [-10, 10]\n  - name: HFR", "command: [3, 3]\n  - name: HFR");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("thrusters[0].command: expected a command range [lo, hi] with lo < hi"));
}

TEST(ReadVehicleTest, DeductionOutOfRange) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "deduction: 0.1", "deduction: 1");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("thrusters[1].thrust.deduction: expected a thrust deduction in [0, 1), "
                        "got '1'"));
}

TEST(ReadVehicleTest, UnknownThrustModel) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "model: square, c_pos: 1.02", "model: cubic, c_pos: 1.02");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("thrusters[0].thrust.model: expected a thrust model (square, poly2), "
                        "got 'cubic'"));
}

TEST(ReadVehicleTest, Poly2WithoutThrust) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "a: 10.84, b: -5.019", "a: 0, b: -1");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("thrusters[2].thrust: poly2 thrust must grow with the command"));
}

TEST(ReadVehicleTest, NoThrusters) {
  ScratchDir dir;
  const std::string path =
      dir.Write("v.yaml", "name: a\nmass: 1\nsize: [1, 1, 1]\nthrusters: []\n");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(path); }),
              HasSubstr("thrusters: expected a list of at least one thruster"));
}

TEST(ReadVehicleTest, ThrusterDefinedTwice) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "name: HFR", "name: HFL");
  EXPECT_THAT(
      ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
      HasSubstr(At("vehicle.yaml", line) + " thrusters[1].name: thruster 'HFL' is defined twice"));
}

// ---------------------------------------------------------------------------------------------
// Vehicle: mappings.

TEST(ReadVehicleTest, MappingNamesUnknownThruster) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "shares: {VF: 1.0}", "shares: {VX: 1.0}");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr(At("vehicle.yaml", line) +
                        " mappings.vertical-front.shares: unknown thruster 'VX' (thrusters: HFL, "
                        "HFR, VF, VR)"));
}

TEST(ReadVehicleTest, MappingWithUnknownDof) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "dof: yaw", "dof: yaww");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr(At("vehicle.yaml", line) +
                        " mappings.yaw-diff.dof: expected a DOF (surge, sway, heave, roll, pitch, "
                        "yaw), got 'yaww'"));
}

TEST(ReadVehicleTest, MappingWithBadOpenWater) {
  ScratchDir dir;
  const int line = dir.Edit("vehicle.yaml", "open_water: positive", "open_water: forward");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr(At("vehicle.yaml", line) +
                        " mappings.surge-front.open_water: expected the direction of open-water "
                        "thrust (positive, negative, both, none), got 'forward'"));
}

TEST(ReadVehicleTest, MappingWithZeroShare) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "shares: {VF: 1.0}", "shares: {VF: 0}");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("mappings.vertical-front.shares.VF: expected a non-zero share"));
}

TEST(ReadVehicleTest, NoMappings) {
  ScratchDir dir;
  const std::string path = dir.Write("v.yaml", R"(name: a
mass: 1
size: [1, 1, 1]
thrusters: [{name: T, thrust: {model: square, c_pos: 1, c_neg: 1}, command: [-1, 1]}]
mappings: {}
)");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(path); }),
              HasSubstr(At("v.yaml", 5) + " mappings: expected at least one mapping, got a map"));
}

TEST(ReadVehicleTest, DragPriorMustNotBeNegative) {
  ScratchDir dir;
  dir.Edit("vehicle.yaml", "drag: {k: 10, kq: 200}", "drag: {k: -10, kq: 200}");
  EXPECT_THAT(ErrorOf([&] { ReadVehicle(dir.Path("vehicle.yaml")); }),
              HasSubstr("dofs.heave.drag.k: expected a number >= 0, got '-10'"));
}

TEST(ReadVehicleTest, BadFixtureOfTestsDataBad) {
  EXPECT_THAT(
      ErrorOf([] { ReadVehicle(testing::SourcePath("tests/data/bad/vehicle_bad_number.yaml")); }),
      HasSubstr("vehicle_bad_number.yaml:10: thrusters[0].thrust.c_pos: expected a "
                "positive number, got 'abc'"));
}

// ---------------------------------------------------------------------------------------------
// Pool.

TEST(ReadPoolTest, ReadsTheFixture) {
  const Pool pool = ReadPool(testing::SourcePath("tests/data/io/pool.yaml"));
  EXPECT_EQ(pool.name, "genoa-pool");
  EXPECT_EQ(pool.length, 25);
  EXPECT_EQ(pool.width, 12);
  EXPECT_EQ(pool.depth, 4);
  EXPECT_EQ(pool.margin, 1.5);
}

TEST(ReadPoolTest, NameDefaultsToTheFileStemAndMarginToZero) {
  ScratchDir dir;
  const Pool pool = ReadPool(dir.Write("tank.yaml", "length: 5\nwidth: 3\ndepth: 2\n"));
  EXPECT_EQ(pool.name, "tank");
  EXPECT_EQ(pool.margin, 0.0);
  EXPECT_EQ(pool.max_turns, Pool::kDefaultMaxTurns);  // the documented default, 3 turns
}

TEST(ReadPoolTest, MaxTurnsIsReadAndMustBePositive) {
  ScratchDir dir;
  EXPECT_EQ(
      ReadPool(dir.Write("t.yaml", "length: 5\nwidth: 3\ndepth: 2\nmax_turns: 1.5\n")).max_turns,
      1.5);
  EXPECT_THAT(ErrorOf([&] {
                ReadPool(dir.Write("u.yaml", "length: 5\nwidth: 3\ndepth: 2\nmax_turns: 0\n"));
              }),
              HasSubstr("max_turns: expected a positive number, got '0'"));
}

TEST(ReadPoolTest, MissingDepth) {
  ScratchDir dir;
  dir.Edit("pool.yaml", "depth: 4        # m\n", "");
  EXPECT_THAT(ErrorOf([&] { ReadPool(dir.Path("pool.yaml")); }),
              HasSubstr("pool.yaml: missing required key 'depth'"));
}

TEST(ReadPoolTest, NegativeLength) {
  ScratchDir dir;
  const int line = dir.Edit("pool.yaml", "length: 25", "length: -25");
  EXPECT_THAT(ErrorOf([&] { ReadPool(dir.Path("pool.yaml")); }),
              HasSubstr(At("pool.yaml", line) + " length: expected a positive number, got '-25'"));
}

TEST(ReadPoolTest, MarginLeavesNoRoom) {
  ScratchDir dir;
  dir.Edit("pool.yaml", "margin: 1.5", "margin: 2");
  EXPECT_THAT(ErrorOf([&] { ReadPool(dir.Path("pool.yaml")); }),
              HasSubstr("margin: expected a margin that leaves room to move (2·margin < length, "
                        "width and depth), got '2'"));
}

// The explorer's case: a 25 × 12 × 5 m pool with a 1.5 m margin, written in cm. Each number is
// a valid length, but no pool is 500 m deep and no margin 150 m: the depth is refused first,
// and the message names the likely unit (docs/formats.md, "Plausibility").
TEST(ReadPoolTest, APoolInCentimetresIsRefusedNamingTheUnit) {
  ScratchDir dir;
  const std::string cm =
      dir.Write("p_cm.yaml", "name: p\nlength: 2500\nwidth: 1200\ndepth: 500\nmargin: 150\n");
  EXPECT_THAT(
      ErrorOf([&] { ReadPool(cm); }),
      HasSubstr(At("p_cm.yaml", 4) + " depth: implausible: expected a pool depth in [0.1, 100] m, "
                                     "got 500: is it in cm? 5 m would be plausible"));
  const std::string margin = dir.Write("m.yaml", "length: 25\nwidth: 12\ndepth: 5\nmargin: 150\n");
  EXPECT_THAT(
      ErrorOf([&] { ReadPool(margin); }),
      HasSubstr("margin: implausible: expected a pool margin in [0, 20] m, got 150: is it in "
                "cm? 1.5 m would be plausible"));
  // The cases' pools (4.5 m tank to a 25 m pool, margins 0.4–2 m) stay well inside.
  EXPECT_EQ(ReadPool(dir.Write("ok.yaml", "length: 25\nwidth: 12\ndepth: 5\nmargin: 2\n")).depth,
            5);
}

// The explorer's next try: depth fixed to m, length and width still in cm (8 × 4 × 2.5 m). Each
// is a plausible length alone (a harbour can be 800 m long); a floor 160 times wider than deep
// is not a pool. A towing tank (575 × 15 × 6.7 m, long and narrow) and an Olympic pool pass.
TEST(ReadPoolTest, AFloorInCentimetresOverADepthInMetresIsRefused) {
  ScratchDir dir;
  const std::string cm = dir.Write("floor_cm.yaml", "length: 800\nwidth: 400\ndepth: 2.5\n");
  EXPECT_THAT(ErrorOf([&] { ReadPool(cm); }),
              HasSubstr(At("floor_cm.yaml", 2) +
                        " width: implausible: a pool 800 × 400 m and 2.5 m deep is 160 times "
                        "wider than deep: are length and width in cm? 8 × 4 m would be a pool"));
  EXPECT_EQ(ReadPool(dir.Write("tow.yaml", "length: 575\nwidth: 15\ndepth: 6.7\n")).width, 15);
  EXPECT_EQ(ReadPool(dir.Write("olympic.yaml", "length: 50\nwidth: 25\ndepth: 2\n")).width, 25);
}

TEST(ReadPoolTest, UnknownKey) {
  ScratchDir dir;
  dir.Edit("pool.yaml", "width: 12", "breadth: 12");
  EXPECT_THAT(ErrorOf([&] { ReadPool(dir.Path("pool.yaml")); }),
              HasSubstr("unknown key 'breadth' (allowed: name, length, width, depth, margin, "
                        "max_turns)"));
}

// ---------------------------------------------------------------------------------------------
// Truth.

TEST(ReadTruthTest, ReadsParamsEffectsAndVirtualPool) {
  const Truth truth = ReadTruth(testing::SourcePath("tests/data/io/truth.yaml"));
  EXPECT_EQ(truth.vehicle.name, "romeo");
  EXPECT_EQ(truth.vehicle.priors.at(Dof::kSway).drag->kq, 400);
  ASSERT_EQ(truth.dofs.size(), 3u);  // sway has priors but no params

  const auto& surge = truth.dofs.at(Dof::kSurge).params;
  EXPECT_EQ(surge.at("m"), 890);
  EXPECT_EQ(surge.at("k"), 46.9);
  EXPECT_EQ(surge.at("kq"), 306.2);
  EXPECT_EQ(surge.at("bias"), 1.5);
  EXPECT_EQ(surge.at("bias_step"), 0.0);  // default
  EXPECT_EQ(surge.at("eta.surge-front.neg"), 0.8);
  EXPECT_EQ(surge.at(param::kLinearDragNeg), 46.9);  // defaults to k
  EXPECT_EQ(surge.at(param::kQuadraticDragNeg), 400);
  EXPECT_EQ(surge.at(param::kLag), 0.3);
  EXPECT_EQ(surge.at(param::kDeadzone), 2.5);
  EXPECT_EQ(surge.at(param::kAdvanceLoss), 4);
  EXPECT_EQ(surge.at("coupling.vr"), 300);
  EXPECT_EQ(surge.at("coupling.rr"), -20);
  EXPECT_EQ(surge.at(param::kSensorDelay), 0.2);
  EXPECT_EQ(surge.at(param::kDrift), -1.0e-5);
  EXPECT_EQ(surge.size(), 15u);

  const auto& aux = truth.dofs.at(Dof::kSurge).aux_motion;
  ASSERT_EQ(aux.size(), 2u);
  EXPECT_EQ(aux.at('r').amplitude, 0.1);
  EXPECT_EQ(aux.at('r').omega, 0.5);
  EXPECT_EQ(aux.at('v').offset, 0.05);
  EXPECT_EQ(aux.at('v').amplitude, 0.0);

  const auto& heave = truth.dofs.at(Dof::kHeave).params;
  EXPECT_EQ(heave.at("bias_step"), 4.9);
  EXPECT_EQ(heave.at("eta.vertical-all.neg"), 0.57);
  EXPECT_EQ(heave.at("eta.vertical-all.pos"), 0.9);
  EXPECT_EQ(truth.dofs.at(Dof::kYaw).params.size(), 5u);

  EXPECT_EQ(truth.integration_step_s, 0.005);
  EXPECT_EQ(truth.defects.dropout_probability, 0.05);
  EXPECT_EQ(truth.defects.outlier_probability, 0.01);
  EXPECT_EQ(truth.defects.outlier_size, 0.5);
}

TEST(ReadTruthTest, VirtualPoolDefaults) {
  ScratchDir dir;
  dir.Edit("truth.yaml",
           "virtual_pool: {step: 0.005, dropout_probability: 0.05, outlier_probability: 0.01, "
           "outlier_size: 0.5}\n",
           "");
  const Truth truth = ReadTruth(dir.Path("truth.yaml"));
  EXPECT_EQ(truth.integration_step_s, 0.01);
  EXPECT_EQ(truth.defects.dropout_probability, 0.0);
}

TEST(ReadTruthTest, AVehicleFileHasNoTruth) {
  EXPECT_THAT(ErrorOf([] { ReadTruth(testing::SourcePath("tests/data/io/vehicle.yaml")); }),
              HasSubstr("vehicle.yaml: expected dofs.<dof>.params for at least one DOF"));
}

TEST(ReadTruthTest, ParamsNeedMass) {
  ScratchDir dir;
  const int line = dir.Edit("truth.yaml", "{m: 150, k: 30, kq: 80}", "{k: 30, kq: 80}");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr(At("truth.yaml", line) + " dofs.yaw.params: missing required key 'm'"));
}

TEST(ReadTruthTest, NegativeDrag) {
  ScratchDir dir;
  dir.Edit("truth.yaml", "{m: 150, k: 30, kq: 80}", "{m: 150, k: 30, kq: -80}");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr("dofs.yaw.params.kq: expected a number >= 0, got '-80'"));
}

TEST(ReadTruthTest, EtaOfUnknownMapping) {
  ScratchDir dir;
  const int line =
      dir.Edit("truth.yaml", "eta: {surge-front.neg: 0.8}", "eta: {surge-back.neg: 0.8}");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr(At("truth.yaml", line) +
                        " dofs.surge.params.eta: expected '<mapping>.pos' or '<mapping>.neg' with "
                        "a surge mapping of the vehicle (surge-front), got 'surge-back.neg'"));
}

TEST(ReadTruthTest, EtaOfAMappingOfAnotherDof) {
  ScratchDir dir;
  dir.Edit("truth.yaml", "eta: {surge-front.neg: 0.8}", "eta: {yaw-diff.neg: 0.8}");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr("a surge mapping of the vehicle (surge-front), got 'yaw-diff.neg'"));
}

TEST(ReadTruthTest, EtaWithoutDirection) {
  ScratchDir dir;
  dir.Edit("truth.yaml", "eta: {surge-front.neg: 0.8}", "eta: {surge-front: 0.8}");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr("expected '<mapping>.pos' or '<mapping>.neg'"));
}

TEST(ReadTruthTest, EtaOutOfRange) {
  ScratchDir dir;
  dir.Edit("truth.yaml", "vertical-all.neg: 0.57", "vertical-all.neg: 0");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr("dofs.heave.effects.installation_loss.eta.vertical-all.neg: expected an "
                        "installation coefficient in (0, 2], got '0'"));
}

TEST(ReadTruthTest, EtaGivenTwice) {
  ScratchDir dir;
  dir.Edit("truth.yaml", "bias_step: 4.9}", "bias_step: 4.9, eta: {vertical-all.neg: 0.6}}");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr("parameter 'eta.vertical-all.neg' is given twice"));
}

TEST(ReadTruthTest, UnknownEffect) {
  ScratchDir dir;
  const int line =
      dir.Edit("truth.yaml", "deadzone: {deadzone: 2.5}", "dead_band: {deadzone: 2.5}");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr(At("truth.yaml", line) +
                        " dofs.surge.effects: expected an effect (installation_loss, "
                        "asymmetric_drag, thruster_lag, deadzone, advance_speed_loss, coupling, "
                        "sensor_delay, parameter_drift, thrust_map), got 'dead_band'"));
}

TEST(ReadTruthTest, ThrustMapNeedsAMonotoneExponentAndAReference) {
  {
    ScratchDir dir;
    dir.Edit("truth.yaml", "deadzone: {deadzone: 2.5}",
             "thrust_map: {thrust_exponent: -0.4, reference: 60}");
    const Truth truth = ReadTruth(dir.Path("truth.yaml"));
    const ModelStructure s = TruthStructure(truth, Dof::kSurge);
    EXPECT_TRUE(s.HasEffect("thrust_map"));
    EXPECT_EQ(s.Setting("thrust_reference", 0.0), 60.0);
    EXPECT_EQ(truth.dofs.at(Dof::kSurge).params.at("thrust_exponent"), -0.4);
  }
  {
    ScratchDir dir;
    const int line = dir.Edit("truth.yaml", "deadzone: {deadzone: 2.5}",
                              "thrust_map: {thrust_exponent: -1.2, reference: 60}");
    EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
                HasSubstr(At("truth.yaml", line) +
                          " dofs.surge.effects.thrust_map.thrust_exponent: "
                          "expected a number > -1 (the delivered force must grow with the "
                          "command), got '-1.2'"));
  }
  {
    ScratchDir dir;
    dir.Edit("truth.yaml", "deadzone: {deadzone: 2.5}", "thrust_map: {thrust_exponent: 0.3}");
    EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
                HasSubstr("dofs.surge.effects.thrust_map: missing required key 'reference'"));
  }
}

TEST(ReadTruthTest, UnknownEffectSetting) {
  ScratchDir dir;
  dir.Edit("truth.yaml", "thruster_lag: {lag: 0.3}", "thruster_lag: {tau: 0.3}");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr("dofs.surge.effects.thruster_lag: unknown key 'tau' (allowed: lag)"));
}

TEST(ReadTruthTest, LagMustBePositive) {
  ScratchDir dir;
  dir.Edit("truth.yaml", "thruster_lag: {lag: 0.3}", "thruster_lag: {lag: 0}");
  EXPECT_THAT(
      ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
      HasSubstr("dofs.surge.effects.thruster_lag.lag: expected a positive number, got '0'"));
}

TEST(ReadTruthTest, NegativeSensorDelay) {
  ScratchDir dir;
  dir.Edit("truth.yaml", "sensor_delay: {sensor_delay: 0.2}", "sensor_delay: {sensor_delay: -0.2}");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr("effects.sensor_delay.sensor_delay: expected a number >= 0, got '-0.2'"));
}

TEST(ReadTruthTest, CouplingWithBadLetters) {
  ScratchDir dir;
  const int line = dir.Edit("truth.yaml", "{vr: 300, rr: -20}", "{vx: 300, rr: -20}");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr(At("truth.yaml", line) +
                        " dofs.surge.effects.coupling.coefficients: expected two velocity letters "
                        "of u v w p q r (e.g. 'vr'), got 'vx'"));
}

TEST(ReadTruthTest, CouplingMotionOfItsOwnDof) {
  ScratchDir dir;
  dir.Edit("truth.yaml", "sway: {offset: 0.05}", "surge: {offset: 0.05}");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr("coupling.motion: motion of 'surge' itself comes from the simulation"));
}

TEST(ReadTruthTest, EffectsNeedParams) {
  ScratchDir dir;
  const int line = dir.Edit(
      "truth.yaml", "    params: {m: 800, k: 20, kq: 250, bias: -12, bias_step: 4.9}\n", "");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr(At("truth.yaml", line - 1) + " dofs.heave: missing required key 'params'"));
}

TEST(ReadTruthTest, ProbabilityOutOfRange) {
  ScratchDir dir;
  dir.Edit("truth.yaml", "dropout_probability: 0.05", "dropout_probability: 1");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr("virtual_pool.dropout_probability: expected a probability in [0, 1), "
                        "got '1'"));
}

TEST(ReadTruthTest, ZeroIntegrationStep) {
  ScratchDir dir;
  dir.Edit("truth.yaml", "step: 0.005", "step: 0");
  EXPECT_THAT(ErrorOf([&] { ReadTruth(dir.Path("truth.yaml")); }),
              HasSubstr("virtual_pool.step: expected a positive number, got '0'"));
}

}  // namespace
}  // namespace uuvplan::model
