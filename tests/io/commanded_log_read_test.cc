// Trial logs of thruster commands (cmd_<thruster> columns) read through the vehicle
// (io::ReadTrialOf, model::ForceFromCommands): the nominal force of the row's mapping from each
// thruster's thrust model (PWM about its neutral, the dead band), the generalised force on the
// other DOFs from the geometry, and each fault named with the file, column and row.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "io/io_test_util.h"
#include "uuvplan/io/trial_log_csv.h"
#include "uuvplan/io/vehicle_yaml.h"

namespace uuvplan::model {
namespace {

using testing::ErrorOf;
using ::testing::HasSubstr;
using testing::ScratchDir;

// Two PWM thrusters on the beam (y = ±0.2 m) pushing forward, one vertical at the centre:
// thrust 1e-4·V|V| N for V µs from 1500, none within 25 µs of it.
constexpr const char* kPwmVehicle =
    "name: pwm\nmass: 20\nsize: [1.0, 0.6, 0.4]\nthrusters:\n"
    "  - {name: L, thrust: {model: square, c_pos: 1.0e-4, c_neg: 1.0e-4, dead_band: 25},\n"
    "     command: [1100, 1900], neutral: 1500, position: [-0.3, -0.2, 0], direction: [1, 0, 0],\n"
    "     reversible: true}\n"
    "  - {name: R, thrust: {model: square, c_pos: 1.0e-4, c_neg: 1.0e-4, dead_band: 25},\n"
    "     command: [1100, 1900], neutral: 1500, position: [-0.3, 0.2, 0], direction: [1, 0, 0],\n"
    "     reversible: true}\n"
    "  - {name: V, thrust: {model: square, c_pos: 1.0e-4, c_neg: 1.0e-4}, command: [1100, 1900],\n"
    "     neutral: 1500, position: [0, 0, 0], direction: [0, 0, 1], reversible: true}\n";

TEST(ReadCommandedLog, ForceOfTheMappingAndOfTheGeometry) {
  ScratchDir dir;
  const Vehicle v = io::ReadVehicle(dir.Write("v.yaml", kPwmVehicle));
  ASSERT_EQ(v.mappings.front().name, "surge-all");
  // Row 1: both at 1700 µs (4 N each); row 2: 1700 and 1600 µs (4 and 1 N: a yaw moment);
  // row 3: 1510 µs, inside the dead band (no thrust); row 4: an empty cell.
  const TrialLog log = io::ReadTrialOf(dir.Write("log.csv",
                                                 "t,cmd_L,cmd_R,cmd_V,pos_surge\n"
                                                 "0,1700,1700,1500,0\n"
                                                 "1,1700,1600,1500,0.1\n"
                                                 "2,1510,1510,1500,0.2\n"
                                                 "3,,1700,1500,0.3\n"),
                                       v, Dof::kSurge, "surge-all");
  const auto& surge = log.force[Index(Dof::kSurge)];
  ASSERT_EQ(surge.size(), 4u);
  // surge-all shares 0.5 each: phi = (0.5·tau_L + 0.5·tau_R)/0.5 = tau_L + tau_R.
  EXPECT_NEAR(surge[0], 8.0, 1e-12);
  EXPECT_NEAR(surge[1], 5.0, 1e-12);
  EXPECT_EQ(surge[2], 0.0);
  EXPECT_TRUE(std::isnan(surge[3]));
  // Yaw from the geometry: r × F, the port thruster (y = -0.2) pushing forward turns it to
  // starboard: N = -y·X = 0.2·tau_L - 0.2·tau_R.
  const auto& yaw = log.force[Index(Dof::kYaw)];
  ASSERT_EQ(yaw.size(), 4u);
  EXPECT_NEAR(yaw[0], 0.0, 1e-12);
  EXPECT_NEAR(yaw[1], 0.2 * 4.0 - 0.2 * 1.0, 1e-12);
  EXPECT_TRUE(log.commands.empty());
  // A log that gives the force keeps it: its cmd_ columns, thrusters or not, are other columns.
  const TrialLog forced = io::ReadTrialOf(dir.Write("forced.csv",
                                                    "t,force_surge,cmd_L,cmd_depth,pos_surge\n"
                                                    "0,3,1700,7,0\n"),
                                          v, Dof::kSurge, "surge-all");
  EXPECT_EQ(forced.force[Index(Dof::kSurge)], std::vector<double>{3.0});
  EXPECT_FALSE(forced.HasForce(Dof::kYaw));
  EXPECT_THAT(forced.notes, ::testing::Contains("ignored column 'cmd_depth' (the log gives force_ "
                                                "columns)"));
}

// Rows at rest: a thruster outside the mapping trimming by a hair is no other mapping, and an
// empty cell of it blanks no force it does not act on.
TEST(ReadCommandedLog, IdleRowsAndEmptyCellsOfOtherThrusters) {
  ScratchDir dir;
  Vehicle v = io::ReadVehicle(dir.Write("v.yaml", kPwmVehicle));
  v.min_thrust = 0.5;  // N: the floor a working thruster keeps
  const TrialLog log = io::ReadTrialOf(dir.Write("rest.csv",
                                                 "t,cmd_L,cmd_R,cmd_V,pos_surge\n"
                                                 "0,1500,1500,1501,0\n"
                                                 "1,1700,1700,,0\n"),
                                       v, Dof::kSurge, "surge-all");
  EXPECT_EQ(log.force[Index(Dof::kSurge)], (std::vector<double>{0.0, 8.0}));
  EXPECT_NEAR(log.force[Index(Dof::kYaw)][1], 0.0, 1e-12);  // V at the centre: no yaw
}

TEST(ReadCommandedLog, FaultsNameTheColumnAndTheRow) {
  ScratchDir dir;
  const Vehicle v = io::ReadVehicle(dir.Write("v.yaml", kPwmVehicle));
  auto read = [&](const std::string& text) {
    return ErrorOf(
        [&] { io::ReadTrialOf(dir.Write("log.csv", text), v, Dof::kSurge, "surge-all"); });
  };
  EXPECT_THAT(read("t,cmd_L,cmd_R,cmd_X,cmd_V,pos_surge\n0,1500,1500,1500,1500,0\n"),
              HasSubstr("log.csv: column 'cmd_X': expected a thruster of vehicle 'pwm' (L, R, V)"));
  EXPECT_THAT(read("t,cmd_L,cmd_R,pos_surge\n0,1500,1500,0\n"),
              HasSubstr("no column 'cmd_V': a log of commands gives every thruster's"));
  // 0.5 is a −1…1 setpoint, not µs of PWM.
  EXPECT_THAT(read("t,cmd_L,cmd_R,cmd_V,pos_surge\n0,1500,1500,1500,0\n1,0.5,1500,1500,0\n"),
              HasSubstr("column 'cmd_L' at t = 1 s (data row 2): expected a command within "
                        "[1100, 1900] (thruster L), got 0.5"));
  // V pushes 4 N in a surge row: not a row of surge-all.
  EXPECT_THAT(read("t,cmd_L,cmd_R,cmd_V,pos_surge\n0,1700,1700,1700,0\n"),
              HasSubstr("column 'cmd_V' at t = 0 s (data row 1): thruster V pushes 4 N in a row "
                        "of mapping 'surge-all', which does not use it"));
}

// The dead band is where the thrust model gives nothing: its edge bounds a working thruster.
TEST(ReadCommandedLog, DeadBandEdgeIsTheWorkingFloor) {
  ScratchDir dir;
  Vehicle v = io::ReadVehicle(dir.Write("v.yaml", kPwmVehicle));
  EXPECT_EQ(v.thrusters[0].Thrust(1524.9), 0.0);
  EXPECT_NEAR(v.thrusters[0].Thrust(1525), 1e-4 * 25 * 25, 1e-15);
  EXPECT_NEAR(v.thrusters[0].model.EdgeThrust(-1), 0.0625, 1e-15);
  v.min_thrust = 0.01;  // below the edge's 0.0625 N: the edge binds
  EXPECT_NEAR(v.WorkingThrustFloor(), 0.0625, 1e-15);
  v.min_thrust = 1.0;
  EXPECT_EQ(v.WorkingThrustFloor(), 1.0);
}

}  // namespace
}  // namespace uuvplan::model
