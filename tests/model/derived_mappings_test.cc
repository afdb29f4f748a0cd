// Mappings derived from thruster geometry (model/derived_mappings.h): ROMEO's derived mappings
// contain ref 000 Table I's (as cases/romeo/vehicle.yaml writes them), the BlueROV2's are the
// vectored frame's pairs, and geometries that cannot drive a DOF alone say so without NaN.
#include "uuvplan/model/derived_mappings.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/model/configuration_matrix.h"
#include "uuvplan/model/jet_clearance.h"

namespace uuvplan::model {
namespace {

const double kC = std::sqrt(0.5);  // cos 45° = sin 45°

Thruster At(const std::string& name, std::array<double, 3> r, std::array<double, 3> d) {
  Thruster t;
  t.name = name;
  t.geometry = ThrusterGeometry{r, d};
  return t;
}

// ROMEO (ref 000 §IV-A: 1.3 × 0.9 × 1.0 m, eight thrusters "two by two in the corners", the
// horizontal ones parallel to the diagonals). The layout cases/romeo/vehicle.yaml CHOOSES:
// horizontal thrusters at (±0.55, ±0.35) m, 45°; directions from Table I's "horizontal all"
// row (HFL = (X + Y + N)/4: HFL pushes +x, +y, +N). Vertical thrusters CHOSEN above them at
// z = −0.2 m (the propulsion sits in the upper sections, §IV-A), pushing down (+z) for positive
// thrust ("vertical all pitch, roll, heave": VFL = (−L − M + Z)/4).
std::vector<Thruster> RomeoThrusters() {
  return {At("HFL", {0.55, -0.35, 0}, {kC, kC, 0}),   At("HFR", {0.55, 0.35, 0}, {kC, -kC, 0}),
          At("HRL", {-0.55, -0.35, 0}, {-kC, kC, 0}), At("HRR", {-0.55, 0.35, 0}, {-kC, -kC, 0}),
          At("VFL", {0.55, -0.35, -0.2}, {0, 0, 1}),  At("VFR", {0.55, 0.35, -0.2}, {0, 0, 1}),
          At("VRL", {-0.55, -0.35, -0.2}, {0, 0, 1}), At("VRR", {-0.55, 0.35, -0.2}, {0, 0, 1})};
}
constexpr std::array<double, 3> kRomeoSize = {1.3, 0.9, 1.0};

// The BlueROV2 (vectored frame) in the body frame of von Benzon et al., "An Open-Source
// Benchmark Simulator: Control of a BlueROV2 Underwater Robot", J. Mar. Sci. Eng. 10 (2022)
// 1898, Table A1 (NED): horizontal thrusters at (±0.156, ±0.111, 0.085) m, each
// e_i = Rz(beta_i)·[1/√2, −1/√2, 0]; the two vertical thrusters of the standard frame at
// (0, ±0.111, 0) (public BlueROV2 models in that frame; Table A1 lists the heavy frame's four
// at (±0.12, ±0.218, 0)), positive thrust up (−z) as in Table A1. Size 0.457 × 0.338 × 0.254 m
// (Blue Robotics' BlueROV2 specification).
std::vector<Thruster> BlueRov2Thrusters(bool heavy) {
  std::vector<Thruster> t = {At("FR", {0.156, 0.111, 0.085}, {kC, -kC, 0}),
                             At("FL", {0.156, -0.111, 0.085}, {kC, kC, 0}),
                             At("RR", {-0.156, 0.111, 0.085}, {-kC, -kC, 0}),
                             At("RL", {-0.156, -0.111, 0.085}, {-kC, kC, 0})};
  if (!heavy) {
    t.push_back(At("VR", {0, 0.111, 0}, {0, 0, -1}));
    t.push_back(At("VL", {0, -0.111, 0}, {0, 0, -1}));
    return t;
  }
  t.push_back(At("VFR", {0.12, 0.218, 0}, {0, 0, -1}));
  t.push_back(At("VFL", {0.12, -0.218, 0}, {0, 0, -1}));
  t.push_back(At("VRR", {-0.12, 0.218, 0}, {0, 0, -1}));
  t.push_back(At("VRL", {-0.12, -0.218, 0}, {0, 0, -1}));
  return t;
}
constexpr std::array<double, 3> kBlueRov2Size = {0.457, 0.338, 0.254};

std::set<int> Support(const ThrustMapping& m) {
  std::set<int> s;
  for (const auto& [i, share] : m.shares) s.insert(i);
  return s;
}

const ThrustMapping* Named(const DerivedMappings& d, const std::string& name) {
  for (const auto& m : d.mappings) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

// Every derived mapping gives its DOF's unit force and nothing else: B·s = e_k (the purity
// tolerance is 1e-3, an exact geometry allocates to rounding: 1e-12).
void ExpectPure(const DerivedMappings& d, const std::vector<Thruster>& thrusters,
                const std::vector<Dof>& exempt = {}) {
  const Eigen::MatrixXd b = ConfigurationMatrix(thrusters);
  for (const ThrustMapping& m : d.mappings) {
    SCOPED_TRACE(m.name);
    Eigen::VectorXd s = Eigen::VectorXd::Zero(b.cols());
    for (const auto& [i, share] : m.shares) s(i) = share;
    const Eigen::VectorXd w = b * s;
    for (Dof dof : kAllDofs) {
      if (std::count(exempt.begin(), exempt.end(), dof) && dof != m.dof) continue;
      EXPECT_NEAR(w(Index(dof)), dof == m.dof ? 1.0 : 0.0, 1e-12) << DofName(dof);
    }
  }
}

// Ref 000 Table I, as cases/romeo/vehicle.yaml writes it in physical units: each of its ten
// mappings is derived, with the same thrusters, the same shares (the file's 5 significant
// digits: 1e-4) and the same open-water direction (the "motion direction with eta = 1").
TEST(DerivedMappings, RomeoGeometryGivesTableI) {
  const Vehicle table =
      io::ReadVehicle(std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/vehicle.yaml");
  const std::vector<Thruster> thrusters = RomeoThrusters();
  ASSERT_EQ(table.thrusters.size(), thrusters.size());
  for (std::size_t i = 0; i < thrusters.size(); ++i) {
    ASSERT_EQ(table.thrusters[i].name, thrusters[i].name);
  }
  const DerivedMappings derived = DeriveMappings(thrusters, kRomeoSize, {});
  ExpectPure(derived, thrusters);
  ASSERT_EQ(table.mappings.size(), 10u);
  for (const ThrustMapping& expected : table.mappings) {
    SCOPED_TRACE(expected.name);
    const ThrustMapping* found = nullptr;
    for (const ThrustMapping& m : derived.mappings) {
      if (m.dof == expected.dof && Support(m) == Support(expected)) found = &m;
    }
    ASSERT_NE(found, nullptr);
    std::map<int, double> share(found->shares.begin(), found->shares.end());
    for (const auto& [i, s] : expected.shares) EXPECT_NEAR(share[i], s, 1e-4) << i;
    EXPECT_EQ(found->open_water, expected.open_water);
  }
}

// The derived names and order: per DOF the all-thrusters mapping, then the minimal subsets by
// size and file order. ROMEO's horizontal DOFs have exactly Table I's three each; heave has
// the four corners and the two diagonals (Z with L = M = 0 needs two opposite corners); roll
// and pitch the front/rear and left/right vertical pairs.
TEST(DerivedMappings, RomeoNamesAndOrderAreDeterministic) {
  const DerivedMappings d = DeriveMappings(RomeoThrusters(), kRomeoSize, {});
  std::vector<std::string> names;
  for (const auto& m : d.mappings) names.push_back(m.name);
  const std::vector<std::string> expected = {
      "surge-all", "surge-HFL-HFR", "surge-HRL-HRR", "sway-all", "sway-HFL-HRL", "sway-HFR-HRR",
      "heave-all", "heave-VFL-VRR", "heave-VFR-VRL", "roll-all", "roll-VFL-VFR", "roll-VRL-VRR",
      "pitch-all", "pitch-VFL-VRL", "pitch-VFR-VRR", "yaw-all",  "yaw-HFL-HRR",  "yaw-HFR-HRL"};
  EXPECT_EQ(names, expected);
  EXPECT_TRUE(d.unreachable.empty());
  // Table I's vertical all: Z/4 on each thruster, open water pushing down (jets up, clear).
  const ThrustMapping* heave = Named(d, "heave-all");
  ASSERT_NE(heave, nullptr);
  for (const auto& [i, s] : heave->shares) EXPECT_NEAR(s, 0.25, 1e-12);
  EXPECT_EQ(heave->open_water, OpenWater::kPositive);
}

// The BlueROV2's horizontal thrusters sit 0.085 m below the centre: a surge force X comes with
// a pitch moment 0.085·X that its vertical thrusters (at x = 0) cannot cancel, so with every
// other DOF held, surge has no mapping; its metacentric restoring holds pitch and roll, and with
// those exempt the vectored frame gives the pairs of ref 000 Table I's idea.
TEST(DerivedMappings, BlueRov2SurgeNeedsPitchRestoring) {
  const std::vector<Thruster> thrusters = BlueRov2Thrusters(false);
  const DerivedMappings strict = DeriveMappings(thrusters, kBlueRov2Size, {});
  EXPECT_EQ(Named(strict, "surge-all"), nullptr);
  ASSERT_FALSE(strict.unreachable.empty());
  EXPECT_NE(strict.unreachable.front().find("surge: no allocation"), std::string::npos)
      << strict.unreachable.front();
  EXPECT_NE(strict.unreachable.front().find("pitch"), std::string::npos);
  ExpectPure(strict, thrusters);

  MappingDerivationOptions restoring;
  restoring.restoring = {Dof::kRoll, Dof::kPitch};
  const DerivedMappings d = DeriveMappings(thrusters, kBlueRov2Size, restoring);
  ExpectPure(d, thrusters, restoring.restoring);
  // Two thrusters at 45° give X = 2·cos 45°·s: s = ±1/√2 for a unit force.
  const std::map<std::string, std::map<std::string, double>> pairs = {
      {"surge-FR-FL", {{"FR", kC}, {"FL", kC}}},
      {"surge-RR-RL", {{"RR", -kC}, {"RL", -kC}}},
      {"sway-FR-RR", {{"FR", -kC}, {"RR", -kC}}},
      {"sway-FL-RL", {{"FL", kC}, {"RL", kC}}},
      // N = 2·s·(0.156 + 0.111)·cos 45° = 1: s = ±2.6455
      {"yaw-FR-RL", {{"FR", -1 / (2 * 0.267 * kC)}, {"RL", -1 / (2 * 0.267 * kC)}}},
      {"yaw-FL-RR", {{"FL", 1 / (2 * 0.267 * kC)}, {"RR", 1 / (2 * 0.267 * kC)}}},
      // heave: the two vertical thrusters push up (−z): Z = −(s + s) = 1
      {"heave-all", {{"VR", -0.5}, {"VL", -0.5}}}};
  for (const auto& [name, shares] : pairs) {
    SCOPED_TRACE(name);
    const ThrustMapping* m = Named(d, name);
    ASSERT_NE(m, nullptr);
    ASSERT_EQ(m->shares.size(), shares.size());
    for (const auto& [i, s] : m->shares) EXPECT_NEAR(s, shares.at(thrusters[i].name), 1e-12);
  }
  // Pitch stays out of reach: only the horizontal thrusters' 0.085 m lever gives it, with surge.
  ASSERT_EQ(d.unreachable.size(), 1u);
  EXPECT_EQ(d.unreachable[0].rfind("pitch:", 0), 0u) << d.unreachable[0];
}

// The jets of the vectored frame's front thrusters pushing forward leave backwards and outwards
// (e.g. FR's along (−1, +1)/√2): at the default clearance (mean half-side, 0.175 m) FR's jet
// passes the vertical VR 0.139 m off its axis; at 0.1 m (about the T200's 0.1 m duct) it is
// clear, while pushing backwards FR's jet crosses the bow towards FL, 0.157 m off.
TEST(DerivedMappings, BlueRov2OpenWaterFollowsTheClearance) {
  const std::vector<Thruster> t = BlueRov2Thrusters(false);
  EXPECT_FALSE(JetIsClear(t, 0, +1, DefaultJetClearance(kBlueRov2Size)));
  EXPECT_TRUE(JetIsClear(t, 0, +1, 0.1));
  EXPECT_FALSE(JetIsClear(t, 0, -1, 0.16));
  EXPECT_TRUE(JetIsClear(t, 0, -1, 0.15));
}

// The heavy frame's four vertical thrusters at x = ±0.12 m cancel the pitch moment of a surge
// force: surge is driven alone without exempting pitch, each front / rear horizontal pair with
// a pair of vertical thrusters on one side.
TEST(DerivedMappings, BlueRov2HeavyDrivesEveryDofAlone) {
  const std::vector<Thruster> thrusters = BlueRov2Thrusters(true);
  const DerivedMappings d = DeriveMappings(thrusters, kBlueRov2Size, {});
  ExpectPure(d, thrusters);
  EXPECT_TRUE(d.unreachable.empty());
  for (Dof dof : kAllDofs) {
    EXPECT_NE(Named(d, std::string(DofName(dof)) + "-all"), nullptr) << DofName(dof);
  }
  const ThrustMapping* front = Named(d, "surge-FR-FL-VFR-VRR");
  ASSERT_NE(front, nullptr);
  // M = 0.085·X from the horizontal pair, cancelled by ∓0.12·s on VFR / VRR pushing up:
  // 0.085 − 2·0.12·s = 0 (r × d of a thruster at x pushing −z is +x about pitch).
  std::map<std::string, double> s;
  for (const auto& [i, share] : front->shares) s[thrusters[i].name] = share;
  EXPECT_NEAR(s["FR"], kC, 1e-12);
  EXPECT_NEAR(s["VFR"], -s["VRR"], 1e-12);
  EXPECT_NEAR(std::abs(s["VFR"]), 0.085 / (2 * 0.12), 1e-12);
}

// A vehicle with two parallel surge thrusters and one vertical thruster on its centre line
// cannot roll, pitch or sway: each is reported, and the DOFs it can drive get their mapping.
TEST(DerivedMappings, UnderActuatedGeometryReportsWhatItCannotDrive) {
  const std::vector<Thruster> t = {At("L", {-0.3, -0.2, 0}, {1, 0, 0}),
                                   At("R", {-0.3, 0.2, 0}, {1, 0, 0}),
                                   At("V", {0, 0, 0}, {0, 0, 1})};
  const DerivedMappings d = DeriveMappings(t, {1.0, 0.6, 0.4}, {});
  ExpectPure(d, t);
  std::vector<std::string> names;
  for (const auto& m : d.mappings) names.push_back(m.name);
  EXPECT_EQ(names, (std::vector<std::string>{"surge-all", "heave-all", "yaw-all"}));
  ASSERT_EQ(d.unreachable.size(), 3u);
  EXPECT_EQ(d.unreachable[0], "sway: the thrusters give no force on it");
  EXPECT_EQ(d.unreachable[1], "roll: the thrusters give no moment on it");
  EXPECT_EQ(d.unreachable[2], "pitch: the thrusters give no moment on it");
}

// Two thrusters on one line (the surge axis) have identical columns of B: the pair is no
// minimal subset (rank 1), each alone drives surge, the minimum-norm allocation halves the
// force; nothing is NaN. The rear thruster's forward jet runs along the hull through the
// centre: only the front one pushing forward and the rear one pushing back are in open water.
TEST(DerivedMappings, ThrustersOnOneLineGiveFiniteMappings) {
  const std::vector<Thruster> t = {At("F", {0.5, 0, 0}, {1, 0, 0}),
                                   At("A", {-0.5, 0, 0}, {1, 0, 0})};
  const DerivedMappings d = DeriveMappings(t, {1.2, 0.3, 0.3}, {});
  ASSERT_EQ(d.mappings.size(), 3u);
  EXPECT_EQ(d.mappings[0].name, "surge-all");
  EXPECT_EQ(d.mappings[1].name, "surge-F");
  EXPECT_EQ(d.mappings[2].name, "surge-A");
  for (const auto& [i, s] : d.mappings[0].shares) EXPECT_NEAR(s, 0.5, 1e-12);
  EXPECT_EQ(d.mappings[0].open_water, OpenWater::kNone);
  EXPECT_EQ(d.mappings[1].open_water, OpenWater::kNegative);
  EXPECT_EQ(d.mappings[2].open_water, OpenWater::kPositive);
  for (const auto& m : d.mappings) {
    for (const auto& [i, s] : m.shares) EXPECT_TRUE(std::isfinite(s));
  }
  EXPECT_EQ(d.unreachable.size(), 5u);
}

}  // namespace
}  // namespace uuvplan::model
