// `uuvplan import`: recordings written here in every container the reader takes (ROS 1 bags
// stored, bz2 and lz4; MCAP chunked with lz4 or zstd and unchunked; support/recording_writer.h,
// written from the format specifications independently of the reader) import to the same trials,
// whose values follow from the known signals; the real 2016 BlueROV bags import to a campaign whose
// identification agrees with the hand-converted one within σ (skipped without ../shared).
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cli/cli_test_util.h"
#include "support/real_data.h"
#include "support/recording_writer.h"
#include "uuvplan/io/trial_log_csv.h"

namespace uuvplan::cli_test {
namespace {

using testing::BagCompression;
using testing::McapCompression;
using testing::RealDataPath;
using testing::TestMessage;
using testing::TestTopic;

constexpr double kStart = 1.7e9;  // s since 1970: an epoch-sized recorder clock
constexpr double kSpan = 12.0;    // s of commands

// The vehicle's yaw rate r(t) (rad/s) and sway speed v(t) (m/s): smooth, known signals.
double YawRate(double t) { return 0.4 * std::sin(1.3 * t) + 0.1; }
double SwaySpeed(double t) { return 0.2 * std::cos(0.7 * t); }
// PWM (µs) of two thrusters in command message k (5 Hz): a telegraph switching every fourth
// message (0.8 s), the second thruster opposing the first.
std::uint16_t Pwm(int thruster, int k) {
  const bool high = (k / 4) % 2 == 0;
  return (high == (thruster == 0)) ? 1700 : 1340;
}
// The device's own clock (ms): 3 s ahead, 0.05 % fast; samples arrive 0–30 ms late.
double DeviceMillis(double t) { return 1000.0 * (3.0 + (t - kStart) * 1.0005); }
double ArrivalDelay(int i) { return 0.030 * double((i * 7919) % 31) / 30.0; }

struct Synthetic {
  std::vector<TestTopic> topics;
  std::vector<TestMessage> messages;
};

// Commands at 5 Hz (0..kSpan), the gyro at 50 Hz stamped by the device clock, a DVL-like
// TwistStamped at 10 Hz in ROS body axes (FLU), from 1 s before the first command to 1 s after.
// Its frame_id of 9 characters leaves the CDR twist misaligned unless padded to 8 bytes.
Synthetic MakeRecording() {
  Synthetic s;
  s.topics = {testing::UInt16MultiArrayTopic("/vehicle/thrusters"),
              testing::Float32MultiArrayTopic("/imu/raw"), testing::TwistStampedTopic("/dvl/twist"),
              testing::Float32MultiArrayTopic("/unused")};
  for (int i = 0; i <= 50 * (kSpan + 2); ++i) {
    const double t = kStart - 1.0 + i / 50.0;
    if (i % 5 == 0) {
      s.messages.push_back(testing::TwistStampedMessage(
          2, t + 0.004, t, "base_link", {0.1, -SwaySpeed(t), 0.0}, {0.0, 0.0, -YawRate(t)}));
    }
    s.messages.push_back(testing::Float32MultiArrayMessage(
        1, t + ArrivalDelay(i), {float(DeviceMillis(t)), float(YawRate(t)), 9.81f}));
    const int k = (i - 50) / 10;  // command message k at kStart + 0.2 k
    if (i % 10 == 0 && k >= 0 && k <= 5 * kSpan) {
      s.messages.push_back(testing::UInt16MultiArrayMessage(0, t, {Pwm(0, k), Pwm(1, k), 1500}));
    }
  }
  return s;
}

// Thrust (N) of u in the table the map names: 40 u |u| tabulated every 0.1.
double TableThrust(double u) { return 40.0 * u * std::abs(u); }

std::string WriteMap(const TempDir& dir) {
  std::ofstream table(dir / "thrust.txt");
  table << "# u  thrust (N)\n";
  for (int k = -10; k <= 10; ++k) table << k / 10.0 << " " << TableThrust(k / 10.0) << "\n";
  table.close();
  std::ofstream(dir / "vehicle.yaml") << ReadText(kRomeoCase + "vehicle.yaml");
  return dir.Write("map.yaml", R"(vehicle: vehicle.yaml
dof: yaw
mapping: yaw-fl-rr
commands:
  topic: /vehicle/thrusters
  unit: pwm_us
  thrusters: {A: "data[0]", B: "data[1]"}
thrust_table: {file: thrust.txt}
forces:
  yaw: {A: 0.2, B: -0.2}
measured:
  vel_yaw: {topic: /imu/raw, field: "data[1]"}
  vel_sway: {topic: /dvl/twist, field: twist.linear.y, frame: flu}
clocks:
  /imu/raw: {field: "data[0]", scale: 0.001}
  /dvl/twist: {field: header.stamp, align: none}
)");
}

// Writes the recording as `name` in `dir`, imports it, returns its one trial's log.
model::TrialLog Imported(const TempDir& dir, const std::string& name, const std::string& map) {
  const ToolRun r = RunTool(
      "import '" + (dir / name) + "' --map '" + map + "' --out '" + (dir / ("out-" + name)) + "'",
      dir);
  EXPECT_EQ(r.status, 0) << name << ": " << r.err;
  const std::string stem = name.substr(0, name.find('.'));
  return io::ReadTrialLog(dir / ("out-" + name + "/trials/" + stem + ".csv"));
}

// Equal columns, a missing sample (NaN) equal to a missing sample.
bool SameColumns(const model::TrialLog::DofColumns& a, const model::TrialLog::DofColumns& b) {
  for (std::size_t d = 0; d < a.size(); ++d) {
    if (a[d].size() != b[d].size()) return false;
    for (std::size_t i = 0; i < a[d].size(); ++i) {
      if (a[d][i] != b[d][i] && !(std::isnan(a[d][i]) && std::isnan(b[d][i]))) return false;
    }
  }
  return true;
}

class ImportFormats : public ::testing::Test {
 protected:
  void SetUp() override {
    recording_ = MakeRecording();
    map_ = WriteMap(dir_);
  }
  TempDir dir_;
  Synthetic recording_;
  std::string map_;
};

TEST_F(ImportFormats, EveryContainerGivesTheSameTrial) {
  const auto& [topics, messages] = recording_;
  testing::WriteRos1Bag(dir_ / "stored.bag", topics, messages, BagCompression::kNone, 4096);
  testing::WriteRos1Bag(dir_ / "bz2.bag", topics, messages, BagCompression::kBz2, 4096);
  testing::WriteRos1Bag(dir_ / "lz4.bag", topics, messages, BagCompression::kLz4, 4096);
  testing::WriteMcap(dir_ / "chunked.mcap", topics, messages, true, McapCompression::kLz4);
  testing::WriteMcap(dir_ / "flat.mcap", topics, messages, false, McapCompression::kNone);
  testing::WriteMcap(dir_ / "zstd.mcap", topics, messages, true, McapCompression::kZstd);
  const model::TrialLog reference = Imported(dir_, "stored.bag", map_);
  ASSERT_GT(reference.size(), 600u);  // 12 s of 50 Hz and 10 Hz samples
  for (const char* name : {"bz2.bag", "lz4.bag", "chunked.mcap", "flat.mcap", "zstd.mcap"}) {
    const model::TrialLog log = Imported(dir_, name, map_);
    ASSERT_EQ(log.size(), reference.size()) << name;
    for (std::size_t i = 0; i < log.size(); ++i) {
      // 1 µs: the recorder time is sec + nsec (bag) or ns (MCAP), one rounding apart.
      ASSERT_NEAR(log.t[i], reference.t[i], 1e-6) << name << " row " << i;
    }
    EXPECT_TRUE(SameColumns(log.force, reference.force)) << name;
    EXPECT_TRUE(SameColumns(log.velocity, reference.velocity)) << name;
  }
}

TEST_F(ImportFormats, ValuesFollowFromTheRecordedSignals) {
  testing::WriteMcap(dir_ / "run.mcap", recording_.topics, recording_.messages, true,
                     McapCompression::kLz4);
  const model::TrialLog log = Imported(dir_, "run.mcap", map_);
  const std::vector<double>& yaw = log.velocity[model::Index(model::Dof::kYaw)];
  const std::vector<double>& sway = log.velocity[model::Index(model::Dof::kSway)];
  const std::vector<double>& torque = log.force[model::Index(model::Dof::kYaw)];
  int gyro_rows = 0, dvl_rows = 0;
  for (std::size_t i = 0; i < log.size(); ++i) {
    const double t = log.t[i];  // s after the first command message
    // The command held from the last message at or before the row; a gyro row within 3 ms
    // of a message may lie on either side of it (its clock is mapped to within 2 ms).
    const int k = int(std::floor(t / 0.2 + 1e-6));
    const double u_a = (Pwm(0, k) - 1500) / 400.0, u_b = (Pwm(1, k) - 1500) / 400.0;
    if (std::abs(t - 0.2 * std::round(t / 0.2)) > 0.003) {
      EXPECT_NEAR(torque[i], 0.2 * TableThrust(u_a) - 0.2 * TableThrust(u_b), 1e-9) << t;
    }
    if (std::isfinite(yaw[i])) {
      ++gyro_rows;
      // The device clock mapped through the earliest arrivals: within 2 ms of the true time
      // (arrival delays are multiples of 1 ms, the least is 0); r changes ≤ 0.52 rad/s², so
      // 2 ms is ≤ 1.1e-3 rad/s, plus float32 rounding.
      EXPECT_NEAR(yaw[i], YawRate(kStart + t), 1.2e-3) << t;
    }
    if (std::isfinite(sway[i])) {
      ++dvl_rows;
      EXPECT_NEAR(sway[i], SwaySpeed(kStart + t), 1e-9) << t;  // FLU y = -FRD y; header time
    }
  }
  EXPECT_NEAR(gyro_rows, 601, 1);  // 50 Hz over [0, 12] s; the end samples lie within 2 ms
  EXPECT_EQ(dvl_rows, 121);        // 10 Hz over [0, 12] s
}

TEST_F(ImportFormats, AFaultNamesTheFileAndWhatWasExpected) {
  testing::WriteRos1Bag(dir_ / "good.bag", recording_.topics, recording_.messages,
                        BagCompression::kNone);
  const std::string bag = ReadText(dir_ / "good.bag");
  dir_.Write("cut.bag", bag.substr(0, bag.size() / 2));
  ToolRun r = RunTool(
      "import '" + (dir_ / "cut.bag") + "' --map '" + map_ + "' --out '" + (dir_ / "o1") + "'",
      dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("cut.bag: byte "), std::string::npos) << r.err;

  std::string map = ReadText(map_);
  map.replace(map.find("twist.linear.y"), 14, "twist.lineal.y");
  dir_.Write("typo.yaml", map);
  r = RunTool("import '" + (dir_ / "good.bag") + "' --map '" + (dir_ / "typo.yaml") + "' --out '" +
                  (dir_ / "o2") + "'",
              dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.err.find("geometry_msgs/Twist has no field 'lineal'"), std::string::npos) << r.err;
  EXPECT_NE(r.err.find("twist.linear.x"), std::string::npos) << r.err;  // what it has
  EXPECT_FALSE(std::filesystem::exists(dir_ / "o2"));                   // nothing half-written
}

// The same run exported by `rostopic echo -p` (one CSV per topic: %time in ns, fields flattened,
// header.stamp in ns) imports to the trial the bag gives, within the CSV's printed digits.
TEST_F(ImportFormats, RostopicCsvExportsGiveTheBagsTrial) {
  const auto& [topics, messages] = recording_;
  testing::WriteRos1Bag(dir_ / "run.bag", topics, messages, BagCompression::kNone);
  std::filesystem::create_directories(dir_ / "runs/run");
  std::filesystem::copy_file(dir_ / "thrust.txt", dir_ / "runs/thrust.txt");  // beside the runs
  std::ofstream thrusters(dir_ / "runs/run/thrusters.csv"), imu(dir_ / "runs/run/imu.csv"),
      dvl(dir_ / "runs/run/dvl.csv");
  thrusters << "%time,field.layout.data_offset,field.data0,field.data1,field.data2\n";
  imu << "%time,field.layout.data_offset,field.data0,field.data1,field.data2\n";
  dvl << "%time,field.header.seq,field.header.stamp,field.header.frame_id,field.twist.linear.x,"
         "field.twist.linear.y,field.twist.linear.z,field.twist.angular.x,"
         "field.twist.angular.y,field.twist.angular.z\n";
  auto ns = [](double t) { return std::to_string(std::llround(t * 1e9)); };
  char cells[256];
  for (int i = 0; i <= 50 * (kSpan + 2); ++i) {
    const double t = kStart - 1.0 + i / 50.0;
    if (i % 5 == 0) {
      std::snprintf(cells, sizeof cells, ",0,%s,base_link,0.1,%.17g,0,0,0,%.17g\n", ns(t).c_str(),
                    -SwaySpeed(t), -YawRate(t));
      dvl << ns(t + 0.004) << cells;
    }
    std::snprintf(cells, sizeof cells, ",0,%.9g,%.9g,9.81\n", float(DeviceMillis(t)),
                  float(YawRate(t)));
    imu << ns(t + ArrivalDelay(i)) << cells;
    const int k = (i - 50) / 10;
    if (i % 10 == 0 && k >= 0 && k <= 5 * kSpan) {
      thrusters << ns(t) << ",0," << Pwm(0, k) << "," << Pwm(1, k) << ",1500\n";
    }
  }
  thrusters.close(), imu.close(), dvl.close();
  std::string map = ReadText(map_);
  dir_.Write("csv.yaml", map +
                             "csv_topics: {/vehicle/thrusters: thrusters.csv, /imu/raw: imu.csv, "
                             "/dvl/twist: dvl.csv}\n");
  const ToolRun r =
      RunTool("import '" + (dir_ / "runs") + "' --map '" + (dir_ / "csv.yaml") + "' --out '" +
                  (dir_ / "o") + "' --vehicle '" + (dir_ / "vehicle.yaml") + "'",
              dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  const model::TrialLog csv = io::ReadTrialLog(dir_ / "o/trials/run.csv");
  const model::TrialLog bag = Imported(dir_, "run.bag", map_);
  ASSERT_EQ(csv.size(), bag.size());
  for (std::size_t i = 0; i < csv.size(); ++i) {
    ASSERT_NEAR(csv.t[i], bag.t[i], 1e-6) << i;  // ns in both; a float32 clock printed in 9 digits
    for (model::Dof d : {model::Dof::kSway, model::Dof::kYaw}) {
      const double a = csv.velocity[model::Index(d)][i], b = bag.velocity[model::Index(d)][i];
      EXPECT_TRUE(std::isnan(a) ? std::isnan(b) : std::abs(a - b) < 1e-7) << i;
    }
    EXPECT_EQ(csv.force[model::Index(model::Dof::kYaw)][i],
              bag.force[model::Index(model::Dof::kYaw)][i]);
  }
}

// `cut: activity`: thrusters active for 3 s, at rest for 4 s, active for 3 s make two trials,
// each from its first active command to the first command at rest after it.
TEST_F(ImportFormats, ActivityCutsOneTrialPerSpanOfThrusterActivity) {
  std::vector<TestMessage> messages;
  for (int i = 0; i <= 500; ++i) {  // 10 s at 50 Hz
    const double t = kStart + i / 50.0;
    messages.push_back(testing::Float32MultiArrayMessage(1, t, {float(1000 * i / 50.0), 0.1f}));
    const bool active = t - kStart < 3.0 || t - kStart >= 7.0;
    const std::uint16_t pwm = active ? 1700 : 1500;
    if (i % 10 == 0) messages.push_back(testing::UInt16MultiArrayMessage(0, t, {pwm, pwm, 1500}));
  }
  testing::WriteRos1Bag(dir_ / "run.bag", recording_.topics, messages, BagCompression::kLz4);
  std::string map = ReadText(map_);
  map.replace(map.find("  vel_sway:"), map.find("clocks:") - map.find("  vel_sway:"), "");
  map.replace(map.find("  /dvl/twist:"), std::string::npos, "cut: activity\nquiet: 2\n");
  dir_.Write("activity.yaml", map);
  const ToolRun r = RunTool("import '" + (dir_ / "run.bag") + "' --map '" +
                                (dir_ / "activity.yaml") + "' --out '" + (dir_ / "o") + "'",
                            dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  const model::TrialLog first = io::ReadTrialLog(dir_ / "o/trials/run_1.csv");
  const model::TrialLog second = io::ReadTrialLog(dir_ / "o/trials/run_2.csv");
  EXPECT_NEAR(first.t.back(), 3.0, 0.02) << "active from 0 s, at rest from 3 s (50 Hz rows)";
  EXPECT_NEAR(second.t.back(), 3.0, 0.02) << "active from 7 s to the last command at 10 s";
  EXPECT_FALSE(std::filesystem::exists(dir_ / "o/trials/run_3.csv"));
}

// `cut: ranges`: the map's time ranges (s after the first command message) are the trials.
TEST_F(ImportFormats, RangesCutTheTrialsTheMapNames) {
  testing::WriteRos1Bag(dir_ / "run.bag", recording_.topics, recording_.messages,
                        BagCompression::kBz2);
  dir_.Write("ranges.yaml", ReadText(map_) + "cut: ranges\nranges: {run: [[1, 4], [5, 9.5]]}\n");
  ToolRun r = RunTool("import '" + (dir_ / "run.bag") + "' --map '" + (dir_ / "ranges.yaml") +
                          "' --out '" + (dir_ / "o") + "'",
                      dir_);
  ASSERT_EQ(r.status, 0) << r.err;
  const model::TrialLog first = io::ReadTrialLog(dir_ / "o/trials/run_1.csv");
  const model::TrialLog second = io::ReadTrialLog(dir_ / "o/trials/run_2.csv");
  EXPECT_NEAR(first.t.back(), 3.0, 0.021) << "rows at 50 Hz up to 3 s after the range's start";
  EXPECT_NEAR(second.t.back(), 4.5, 0.021);
  dir_.Write("late.yaml", ReadText(map_) + "cut: ranges\nranges: {run: [[1, 40]]}\n");
  r = RunTool("import '" + (dir_ / "run.bag") + "' --map '" + (dir_ / "late.yaml") + "' --out '" +
                  (dir_ / "o2") + "'",
              dir_);
  EXPECT_EQ(r.status, 2);
  EXPECT_THAT(r.err, ::testing::HasSubstr("late.yaml: ranges.run: expected ranges within the "
                                          "commands' span [0, 12.000000] s"));
}

// The five real BlueROV yaw bags (../shared/data/bluerov-yaw-2016/bags) through
// cases/bluerov-2016/import.yaml identify as the hand-converted campaign does: each estimate within
// the reference's σ (the two differ only in how the gyro's clock was mapped, ≈ 1 ms).
TEST(ImportRealBags, BlueRovYawAgreesWithTheConvertedCampaignWithinSigma) {
  UUVPLAN_SKIP_WITHOUT_REAL_DATA("bluerov-yaw-2016");
  TempDir dir;
  const std::string source = std::string(UUVPLAN_SOURCE_DIR);
  ToolRun r = RunTool("import '" + RealDataPath("bluerov-yaw-2016/bags") + "' --map '" + source +
                          "/cases/bluerov-2016/import.yaml' --out '" + (dir / "c") + "'",
                      dir);
  ASSERT_EQ(r.status, 0) << r.err;
  RunTool("identify '" + (dir / "c") + "' --json '" + (dir / "imported.json") + "'", dir);
  RunTool("identify '" + RealDataPath("bluerov-yaw-2016/campaign.yaml") + "' --json '" +
              (dir / "converted.json") + "'",
          dir);
  const auto imported = nlohmann::json::parse(ReadText(dir / "imported.json"))["dofs"]["yaw"];
  const auto converted = nlohmann::json::parse(ReadText(dir / "converted.json"))["dofs"]["yaw"];
  EXPECT_EQ(imported["status"], converted["status"]);
  for (const char* p : {"m", "k", "kq", "bias"}) {
    const double a = imported["params"][p]["value"], b = converted["params"][p]["value"];
    EXPECT_LT(std::abs(a - b), double(converted["params"][p]["sigma"])) << p;
  }
}

}  // namespace
}  // namespace uuvplan::cli_test
