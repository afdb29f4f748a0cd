// The virtual pool: deterministic per seed, sensors at their rates with the stated noise,
// drop-outs and outliers at their rates, commands logged exactly as the truth vehicle saw them,
// campaigns written whole, and the vehicle written back readable.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>

#include "uuvplan/io/io.h"
#include "uuvplan/io/virtual_campaign.h"
#include "uuvplan/model/campaign_builder.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/simulator.h"
#include "uuvplan/model/util/seed.h"
#include "uuvplan/model/virtual_pool.h"

namespace uuvplan::model {
namespace {

using io::ReadCampaign;
using io::ReadVehicle;
using io::SimulateCampaign;
using io::WriteVehicleYaml;

Truth RomeoSurgeTruth() {
  Truth truth;
  Vehicle& v = truth.vehicle;
  v.name = "romeo-test";
  v.mass = 450;
  v.size = {1.3, 0.9, 1.0};
  Thruster t;
  t.name = "HFL";
  t.command_min = -10;
  t.command_max = 10;
  v.thrusters = {t};
  v.mappings = {{"surge-front", Dof::kSurge, {{0, 0.5}}, OpenWater::kPositive},
                {"yaw-a", Dof::kYaw, {{0, 0.5}}, OpenWater::kBoth}};
  v.sensors[Dof::kSurge].position = SensorSpec{3.33, 0.02};  // ref 000: 3.33 Hz sonar
  v.sensors[Dof::kYaw].position = SensorSpec{10.0, 0.005};   // 10 Hz compass
  truth.dofs[Dof::kSurge].params = {{"m", 890}, {"k", 46.9}, {"kq", 306.2}, {"bias", 0.0}};
  truth.dofs[Dof::kYaw].params = {{"m", 84}, {"k", 28.6}, {"kq", 0.0}, {"bias", 0.0}};
  return truth;
}

TrialDesign PaperSurgeSine() {  // ref 000 §IV-D: 35 N offset, 25 N amplitude, 26 s period
  TrialDesign d;
  d.id = "surge_sine";
  d.dof = Dof::kSurge;
  d.kind = TrialKind::kSine;
  d.mapping = "surge-front";
  d.offset = 35;
  d.amplitude = 25;
  d.omega = 2 * M_PI / 26;
  d.duration = 78;
  return d;
}

std::vector<double> Column(const TrialLog& log, const std::vector<double>& col,
                           std::vector<double>* t) {
  std::vector<double> v;
  for (std::size_t i = 0; i < col.size(); ++i) {
    if (std::isnan(col[i])) continue;
    v.push_back(col[i]);
    if (t) t->push_back(log.t[i]);
  }
  return v;
}

TEST(VirtualPoolTest, DeterministicForASeed) {
  const Truth truth = RomeoSurgeTruth();
  VirtualPoolOptions o;
  o.seed = 7;
  const TrialLog a = RunVirtualTrial(truth, PaperSurgeSine(), 0.0, o);
  const TrialLog b = RunVirtualTrial(truth, PaperSurgeSine(), 0.0, o);
  o.seed = 8;
  const TrialLog c = RunVirtualTrial(truth, PaperSurgeSine(), 0.0, o);
  const int s = Index(Dof::kSurge);
  ASSERT_EQ(a.t, b.t);
  for (std::size_t i = 0; i < a.t.size(); ++i) {
    if (std::isnan(a.position[s][i])) {
      EXPECT_TRUE(std::isnan(b.position[s][i]));
    } else {
      EXPECT_EQ(a.position[s][i], b.position[s][i]);
    }
  }
  EXPECT_NE(Column(a, a.position[s], nullptr), Column(c, c.position[s], nullptr));
}

TEST(VirtualPoolTest, SensorRateNoiseAndHeldCommands) {
  const Truth truth = RomeoSurgeTruth();
  VirtualPoolOptions o;
  o.seed = 3;
  const TrialDesign d = PaperSurgeSine();
  const TrialLog log = RunVirtualTrial(truth, d, 0.0, o);
  const int s = Index(Dof::kSurge);
  std::vector<double> tp;
  const std::vector<double> pos = Column(log, log.position[s], &tp);
  // 3.33 Hz over 78 s: floor(78·3.33) + 1 samples.
  EXPECT_EQ(pos.size(), static_cast<std::size_t>(std::floor(78 * 3.33)) + 1);

  // The logged commands, held, are exactly what drove the truth: re-simulating the truth from
  // the log's own force column reproduces the clean position; the residual is the noise.
  std::vector<double> tf;
  const std::vector<double> f = Column(log, log.force[s], &tf);
  EXPECT_EQ(f.size(), 78u * 20u + 1u);  // 20 Hz command rate
  for (std::size_t i = 0; i < f.size(); ++i) {
    EXPECT_NEAR(f[i], 35 + 25 * std::sin(2 * M_PI / 26 * tf[i]), 1e-9);
  }
  const auto held = MakeHeldExcitation(tf, f, std::vector<int>(tf.size(), 0), d.duration);
  const DofModel model(truth.vehicle, TruthStructure(truth, Dof::kSurge));
  const Eigen::VectorXd theta = model.Theta(truth.dofs.at(Dof::kSurge).params);
  const Trajectory clean = Simulate(model, theta, TrialConditions{held.get()}, tp, {});
  double sum2 = 0.0;
  for (std::size_t i = 0; i < pos.size(); ++i) sum2 += std::pow(pos[i] - clean.x(i, 0), 2);
  const double sigma_hat = std::sqrt(sum2 / pos.size());
  // 260 samples: the sample σ has relative standard error 1/sqrt(2·260) = 4.4%; 15% is > 3 SE.
  EXPECT_NEAR(sigma_hat, 0.02, 0.15 * 0.02);
}

TEST(VirtualPoolTest, DropoutsAndOutliersAtTheirRates) {
  Truth truth = RomeoSurgeTruth();
  truth.defects.dropout_probability = 0.1;
  truth.defects.outlier_probability = 0.05;
  truth.defects.outlier_size = 1.0;  // m: sonar multipath (ref 000 Fig. 14)
  TrialDesign d = PaperSurgeSine();
  d.duration = 600;
  VirtualPoolOptions o;
  o.seed = 11;
  const TrialLog log = RunVirtualTrial(truth, d, 0.0, o);
  const int s = Index(Dof::kSurge);
  std::vector<double> tf, tp;
  const std::vector<double> f = Column(log, log.force[s], &tf);
  const auto held = MakeHeldExcitation(tf, f, std::vector<int>(tf.size(), 0), d.duration);
  const DofModel model(truth.vehicle, TruthStructure(truth, Dof::kSurge));
  const Eigen::VectorXd theta = model.Theta(truth.dofs.at(Dof::kSurge).params);
  // Sample rows: every 1/3.33 s; missing ones are NaN in the position column.
  int samples = 0, missing = 0, outliers = 0;
  for (std::size_t i = 0; i < log.t.size(); ++i) {
    const double k = log.t[i] * 3.33;
    if (std::abs(k - std::round(k)) > 1e-6) continue;
    ++samples;
    if (std::isnan(log.position[s][i])) ++missing;
  }
  const std::vector<double> pos = Column(log, log.position[s], &tp);
  const Trajectory clean = Simulate(model, theta, TrialConditions{held.get()}, tp, {});
  for (std::size_t i = 0; i < pos.size(); ++i) {
    if (std::abs(pos[i] - clean.x(i, 0)) > 0.5) ++outliers;  // 25σ: only outliers
  }
  // 1999 samples: drop-out 10% ± 0.67% and outliers 5% ± 0.5% (1σ binomial); 4σ bounds.
  EXPECT_NEAR(static_cast<double>(missing) / samples, 0.10, 0.027);
  EXPECT_NEAR(static_cast<double>(outliers) / pos.size(), 0.05, 0.02);
}

TEST(VirtualPoolTest, HeadingsAreWrapped) {
  const Truth truth = RomeoSurgeTruth();
  TrialDesign d;
  d.id = "yaw_spin";
  d.dof = Dof::kYaw;
  d.kind = TrialKind::kSteady;
  d.mapping = "yaw-a";
  d.force = 30;  // 30 N·m / 28.6 ≈ 1 rad/s: the heading passes ±π many times in 100 s
  d.duration = 100;
  const TrialLog log = RunVirtualTrial(truth, d, 0.0, VirtualPoolOptions{});
  const std::vector<double> psi = Column(log, log.position[Index(Dof::kYaw)], nullptr);
  int jumps = 0;
  for (std::size_t i = 0; i < psi.size(); ++i) {
    EXPECT_GT(psi[i], -M_PI);
    EXPECT_LE(psi[i], M_PI);
    if (i > 0 && std::abs(psi[i] - psi[i - 1]) > M_PI) ++jumps;
  }
  EXPECT_GE(jumps, 10);  // ~100 rad of rotation: about 16 wraps
}

TEST(VirtualPoolTest, CampaignWrittenWholeAndNeverOverwritten) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "uuvplan_vp_test";
  fs::remove_all(dir);
  const Truth truth = RomeoSurgeTruth();
  VirtualCampaignOptions o;
  const Campaign c = SimulateCampaign(truth, {PaperSurgeSine()}, dir.string(), o);
  EXPECT_TRUE(fs::exists(dir / "campaign.yaml"));
  EXPECT_TRUE(fs::exists(dir / "vehicle.yaml"));
  EXPECT_TRUE(fs::exists(dir / "trials" / "surge_sine.csv"));
  EXPECT_FALSE(fs::exists(dir.string() + ".tmp-uuvplan"));
  // A second run into the same directory is refused and leaves it untouched.
  const auto stamp = fs::last_write_time(dir / "campaign.yaml");
  EXPECT_THROW(SimulateCampaign(truth, {PaperSurgeSine()}, dir.string(), o), InputError);
  EXPECT_EQ(fs::last_write_time(dir / "campaign.yaml"), stamp);
  // What was written reads back: the vehicle and the trial.
  const Campaign back = ReadCampaign((dir / "campaign.yaml").string());
  ASSERT_EQ(back.trials.size(), 1u);
  EXPECT_EQ(back.vehicle.name, truth.vehicle.name);
  EXPECT_EQ(back.trials[0].log.t.size(), c.trials[0].log.t.size());
  fs::remove_all(dir);
}

TEST(VehicleWriterTest, RoundTripsTheRomeoCase) {
  namespace fs = std::filesystem;
  const std::string src = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/vehicle.yaml";
  const Vehicle v = ReadVehicle(src);
  const std::string out = (fs::temp_directory_path() / "uuvplan_vehicle_rt.yaml").string();
  WriteVehicleYaml(out, v);
  const Vehicle w = ReadVehicle(out);
  EXPECT_EQ(w.name, v.name);
  EXPECT_EQ(w.mass, v.mass);
  EXPECT_EQ(w.size, v.size);
  EXPECT_EQ(w.added_mass, v.added_mass);
  ASSERT_EQ(w.thrusters.size(), v.thrusters.size());
  for (std::size_t i = 0; i < v.thrusters.size(); ++i) {
    EXPECT_EQ(w.thrusters[i].model.Thrust(3.0), v.thrusters[i].model.Thrust(3.0));
    EXPECT_EQ(w.thrusters[i].command_max, v.thrusters[i].command_max);
  }
  ASSERT_EQ(w.mappings.size(), v.mappings.size());
  for (std::size_t i = 0; i < v.mappings.size(); ++i) {
    EXPECT_EQ(w.mappings[i].shares, v.mappings[i].shares);
    EXPECT_EQ(w.mappings[i].open_water, v.mappings[i].open_water);
  }
  EXPECT_EQ(w.sensors.size(), v.sensors.size());
  EXPECT_EQ(w.priors.size(), v.priors.size());
  fs::remove(out);
}

// The builder's trial i is RunVirtualTrial with StreamSeed(seed, i), at the campaign clock.
TEST(CampaignBuilderTest, TrialIDrawsFromStreamSeedAtTheCampaignClock) {
  const Truth truth = RomeoSurgeTruth();
  TrialDesign second = PaperSurgeSine();
  second.id = "surge_sine_2";
  VirtualCampaignOptions o;
  o.seed = 7;
  o.pause_s = 30.0;
  o.uses = {TrialUse::kFit, TrialUse::kValidate};
  const Campaign c = BuildVirtualCampaign(truth, {PaperSurgeSine(), second}, o);
  ASSERT_EQ(c.trials.size(), 2u);
  EXPECT_EQ(c.trials[1].file, "surge_sine_2");
  EXPECT_EQ(c.trials[1].use, TrialUse::kValidate);
  EXPECT_DOUBLE_EQ(c.trials[1].start, 78.0 + 30.0);
  VirtualPoolOptions one;
  one.seed = StreamSeed(7, 1);
  const TrialLog expected = RunVirtualTrial(truth, second, 78.0 + 30.0, one);
  const auto& got = c.trials[1].log.position[Index(Dof::kSurge)];
  const auto& want = expected.position[Index(Dof::kSurge)];
  ASSERT_EQ(got.size(), want.size());
  for (std::size_t i = 0; i < got.size(); ++i) {
    if (std::isnan(want[i])) {
      EXPECT_TRUE(std::isnan(got[i]));
    } else {
      EXPECT_EQ(got[i], want[i]);
    }
  }
}

TEST(TrialDesignTest, AnswersForceMappingAndPushes) {
  TrialDesign sine = PaperSurgeSine();
  EXPECT_DOUBLE_EQ(sine.NominalForce(0.0), 35.0);
  EXPECT_NEAR(sine.NominalForce(26.0 / 4), 60.0, 1e-9);
  EXPECT_EQ(sine.MappingAt(10.0), "surge-front");
  EXPECT_TRUE(sine.Pushes("surge-front", +1));
  EXPECT_FALSE(sine.Pushes("surge-front", -1));  // 35 - 25 > 0: no reversal
  TrialDesign legs;
  legs.kind = TrialKind::kSegments;
  legs.mapping = "surge-front";
  legs.segments = {{20.0, 10.0, ""}, {-15.0, 5.0, "surge-rear"}};
  legs.duration = 15.0;
  EXPECT_DOUBLE_EQ(legs.NominalForce(9.99), 20.0);
  EXPECT_DOUBLE_EQ(legs.NominalForce(10.0), -15.0);  // a segment starts at its start time
  EXPECT_EQ(legs.MappingAt(12.0), "surge-rear");
  EXPECT_EQ(legs.MappingAt(1.0), "surge-front");
  ASSERT_EQ(legs.Demands().size(), 2u);
  EXPECT_EQ(legs.Demands()[1].mapping, "surge-rear");
  EXPECT_TRUE(legs.Pushes("surge-rear", -1));
  EXPECT_FALSE(legs.Pushes("surge-front", -1));
  EXPECT_EQ(TrialKindName(TrialKind::kSegments), "segments");
}

TEST(PoolTest, WallToWallAndFreeTravel) {
  Pool pool;
  pool.length = 20;
  pool.width = 8;
  pool.depth = 4;
  pool.margin = 1;
  EXPECT_DOUBLE_EQ(pool.WallToWall(Dof::kSway), 8.0);
  EXPECT_DOUBLE_EQ(pool.FreeTravel(Dof::kSurge), 18.0);
  EXPECT_DOUBLE_EQ(pool.WallToWallFor(pool.FreeTravel(Dof::kHeave)), 4.0);
  // A rotation is bounded by the tether: 2π rad per turn, default 3 turns (docs/formats.md).
  EXPECT_DOUBLE_EQ(pool.FreeTravel(Dof::kYaw), 2 * M_PI * Pool::kDefaultMaxTurns);
  pool.max_turns = 1.5;
  EXPECT_DOUBLE_EQ(pool.FreeTravel(Dof::kRoll), 3 * M_PI);
  EXPECT_DOUBLE_EQ(pool.ExtentFor(Dof::kYaw, 3 * M_PI), 1.5);  // turns
  EXPECT_DOUBLE_EQ(pool.ExtentFor(Dof::kHeave, 2.0), 4.0);     // m wall to wall
  EXPECT_EQ(Pool::SideName(Dof::kHeave), "depth");
}

}  // namespace
}  // namespace uuvplan::model
