// The built-in cases (cases/romeo, cases/vsor, cases/uris): every file loads with the readers,
// each truth file repeats its vehicle file, the thrust mappings give exactly the DOF force of
// the papers' control matrices, and the true parameters reproduce the numbers the papers print
// (so a typo or a sign slip in a case file fails here, not in a Monte Carlo three areas away).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "uuvplan/io/io.h"

namespace uuvplan::model {
namespace {

using io::ReadPool;
using io::ReadTruth;
using io::ReadVehicle;

const std::string kCasesDir = std::string(UUVPLAN_SOURCE_DIR) + "/cases/";
constexpr double kPi = 3.14159265358979323846;

std::string Case(const std::string& name, const std::string& file) {
  return kCasesDir + name + "/" + file;
}

TEST(Cases, EveryFileLoads) {
  for (const char* name : {"romeo", "vsor", "uris", "bluerov2"}) {
    SCOPED_TRACE(name);
    EXPECT_NO_THROW(ReadVehicle(Case(name, "vehicle.yaml")));
    EXPECT_NO_THROW(ReadPool(Case(name, "pool.yaml")));
    EXPECT_NO_THROW(ReadTruth(Case(name, "truth.yaml")));
    if (std::filesystem::exists(Case(name, "truth-effects.yaml"))) {
      EXPECT_NO_THROW(ReadTruth(Case(name, "truth-effects.yaml")));
    }
  }
}

void ExpectSameVehicle(const Vehicle& a, const Vehicle& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.mass, b.mass);
  EXPECT_EQ(a.size, b.size);
  EXPECT_EQ(a.inertia, b.inertia);
  EXPECT_EQ(a.added_mass, b.added_mass);
  EXPECT_EQ(a.min_thrust, b.min_thrust);
  ASSERT_EQ(a.thrusters.size(), b.thrusters.size());
  for (std::size_t i = 0; i < a.thrusters.size(); ++i) {
    const auto &x = a.thrusters[i], &y = b.thrusters[i];
    EXPECT_EQ(x.name, y.name);
    EXPECT_EQ(x.model.kind, y.model.kind);
    EXPECT_EQ(x.model.c_pos, y.model.c_pos);
    EXPECT_EQ(x.model.c_neg, y.model.c_neg);
    EXPECT_EQ(x.model.a, y.model.a);
    EXPECT_EQ(x.model.b, y.model.b);
    EXPECT_EQ(x.model.deduction, y.model.deduction);
    EXPECT_EQ(x.command_min, y.command_min);
    EXPECT_EQ(x.command_max, y.command_max);
    EXPECT_EQ(x.model.dead_band, y.model.dead_band);
    EXPECT_EQ(x.reversible, y.reversible);
    ASSERT_EQ(x.geometry.has_value(), y.geometry.has_value());
    if (x.geometry) {
      EXPECT_EQ(x.geometry->position, y.geometry->position);
      EXPECT_EQ(x.geometry->direction, y.geometry->direction);
    }
  }
  EXPECT_EQ(a.speed_limits.translation, b.speed_limits.translation);
  EXPECT_EQ(a.speed_limits.rotation, b.speed_limits.rotation);
  EXPECT_EQ(a.mapping_derivation.jet_clearance, b.mapping_derivation.jet_clearance);
  EXPECT_EQ(a.mapping_derivation.restoring, b.mapping_derivation.restoring);
  ASSERT_EQ(a.mappings.size(), b.mappings.size());
  for (std::size_t i = 0; i < a.mappings.size(); ++i) {
    EXPECT_EQ(a.mappings[i].name, b.mappings[i].name);
    EXPECT_EQ(a.mappings[i].dof, b.mappings[i].dof);
    EXPECT_EQ(a.mappings[i].shares, b.mappings[i].shares);
    EXPECT_EQ(a.mappings[i].open_water, b.mappings[i].open_water);
  }
  // A truth file lists every DOF it has parameters for under dofs:, so its vehicle may carry
  // empty priors (no drag, no added mass) where the vehicle file has none: the same knowledge.
  const auto known = [](const std::map<Dof, DofPrior>& priors) {
    std::map<Dof, DofPrior> out;
    for (const auto& [dof, p] : priors) {
      if (p.drag || p.added_mass) out[dof] = p;
    }
    return out;
  };
  const auto pa = known(a.priors), pb = known(b.priors);
  ASSERT_EQ(pa.size(), pb.size());
  for (const auto& [dof, p] : pa) {
    ASSERT_EQ(pb.count(dof), 1u) << DofName(dof);
    const DofPrior& q = pb.at(dof);
    EXPECT_EQ(p.added_mass, q.added_mass);
    ASSERT_EQ(p.drag.has_value(), q.drag.has_value());
    if (p.drag) {
      EXPECT_EQ(p.drag->k, q.drag->k);
      EXPECT_EQ(p.drag->kq, q.drag->kq);
      EXPECT_EQ(p.drag->rel_sigma, q.drag->rel_sigma);
    }
  }
  ASSERT_EQ(a.sensors.size(), b.sensors.size());
  for (const auto& [dof, s] : a.sensors) {
    ASSERT_EQ(b.sensors.count(dof), 1u) << DofName(dof);
    const DofSensors& t = b.sensors.at(dof);
    ASSERT_EQ(s.position.has_value(), t.position.has_value());
    ASSERT_EQ(s.velocity.has_value(), t.velocity.has_value());
    if (s.position) {
      EXPECT_EQ(s.position->rate_hz, t.position->rate_hz);
      EXPECT_EQ(s.position->sigma, t.position->sigma);
    }
    if (s.velocity) {
      EXPECT_EQ(s.velocity->rate_hz, t.velocity->rate_hz);
      EXPECT_EQ(s.velocity->sigma, t.velocity->sigma);
    }
  }
}

// A truth file is the vehicle file plus the truth: the two must never drift apart.
TEST(Cases, TruthFilesRepeatTheirVehicle) {
  for (const char* name : {"romeo", "vsor", "uris", "bluerov2"}) {
    SCOPED_TRACE(name);
    const Vehicle v = ReadVehicle(Case(name, "vehicle.yaml"));
    ExpectSameVehicle(v, ReadTruth(Case(name, "truth.yaml")).vehicle);
    if (std::filesystem::exists(Case(name, "truth-effects.yaml"))) {
      const Truth plain = ReadTruth(Case(name, "truth.yaml"));
      const Truth effects = ReadTruth(Case(name, "truth-effects.yaml"));
      ExpectSameVehicle(v, effects.vehicle);
      // The effects file adds parameters, it changes none of the standard ones.
      for (const auto& [dof, t] : plain.dofs) {
        for (const auto& [param, value] : t.params) {
          EXPECT_EQ(effects.dofs.at(dof).params.at(param), value) << DofName(dof) << " " << param;
        }
      }
    }
  }
}

// Thruster forces of a mapping for a unit DOF force: tau_i = share_i (phi = 1), by name.
std::map<std::string, double> UnitForces(const Vehicle& v, const std::string& mapping) {
  const int m = v.MappingIndex(mapping);
  EXPECT_GE(m, 0) << mapping;
  std::map<std::string, double> tau;
  for (const auto& t : v.thrusters) tau[t.name] = 0.0;
  if (m < 0) return tau;
  for (const auto& [i, share] : v.mappings[m].shares) tau[v.thrusters[i].name] = share;
  return tau;
}

// Shares are written with 5 significant digits: a unit force is reproduced to 4 shares · 5e-6
// times the largest lever factor (b = 0.64) — 1e-4 bounds it with margin.
constexpr double kShareTolerance = 1e-4;

// Ref 000 §IV-B: phi_H = B_H·tau_H with phi_H = [F_u/cos(alpha), F_v/sin(alpha), T_r/b] and
// phi_V = B_V·tau_V with phi_V = [T_p/c, T_q/d, F_w]. With alpha = 45° and b = 0.9·sin 45°
// (cases/romeo/vehicle.yaml), each mapping of a DOF must give exactly a unit force on it and
// nothing on the other DOFs of its plane; its open-water direction is Table I's.
TEST(Cases, RomeoMappingsReproduceTableIThroughTheControlMatrices) {
  const Vehicle v = ReadVehicle(Case("romeo", "vehicle.yaml"));
  const double alpha = kPi / 4, b = 0.9 * std::sin(kPi / 4);
  struct Expect {
    const char* mapping;
    Dof dof;
    OpenWater open_water;
  };
  const Expect horizontal[] = {
      {"surge-front", Dof::kSurge, OpenWater::kPositive},
      {"surge-rear", Dof::kSurge, OpenWater::kNegative},
      {"horizontal-all-surge", Dof::kSurge, OpenWater::kNone},
      {"sway-left", Dof::kSway, OpenWater::kPositive},
      {"sway-right", Dof::kSway, OpenWater::kNegative},
      {"horizontal-all-sway", Dof::kSway, OpenWater::kNone},
      {"yaw-fl-rr", Dof::kYaw, OpenWater::kPositive},
      {"yaw-fr-rl", Dof::kYaw, OpenWater::kNegative},
      {"horizontal-all-yaw", Dof::kYaw, OpenWater::kNone},
  };
  for (const Expect& e : horizontal) {
    SCOPED_TRACE(e.mapping);
    auto t = UnitForces(v, e.mapping);
    const double fl = t["HFL"], fr = t["HFR"], rl = t["HRL"], rr = t["HRR"];
    const double surge = std::cos(alpha) * (fl + fr - rl - rr);  // B_H row 1
    const double sway = std::sin(alpha) * (fl - fr + rl - rr);   // B_H row 2
    const double yaw = b * (fl - fr - rl + rr);                  // B_H row 3
    EXPECT_NEAR(surge, e.dof == Dof::kSurge ? 1.0 : 0.0, kShareTolerance);
    EXPECT_NEAR(sway, e.dof == Dof::kSway ? 1.0 : 0.0, kShareTolerance);
    EXPECT_NEAR(yaw, e.dof == Dof::kYaw ? 1.0 : 0.0, kShareTolerance);
    EXPECT_EQ(t["VFL"] + t["VFR"] + t["VRL"] + t["VRR"], 0.0);
    const int m = v.MappingIndex(e.mapping);
    EXPECT_EQ(v.mappings[m].dof, e.dof);
    EXPECT_EQ(v.mappings[m].open_water, e.open_water);
  }
  auto t = UnitForces(v, "vertical-all");
  const double fl = t["VFL"], fr = t["VFR"], rl = t["VRL"], rr = t["VRR"];
  EXPECT_NEAR(-fl + fr - rl + rr, 0.0, 1e-12);  // B_V row 1: roll (exact quarters)
  EXPECT_NEAR(-fl - fr + rl + rr, 0.0, 1e-12);  // B_V row 2: pitch
  EXPECT_NEAR(fl + fr + rl + rr, 1.0, 1e-12);   // B_V row 3: heave
  EXPECT_EQ(v.mappings[v.MappingIndex("vertical-all")].open_water, OpenWater::kPositive);
}

// Regime speed xi* > 0 with k·xi + kq·xi² = force.
double SteadySpeed(double k, double kq, double force) {
  return kq == 0 ? force / k : (-k + std::sqrt(k * k + 4 * kq * force)) / (2 * kq);
}

double Deg(double rad) { return rad * 180.0 / kPi; }

// The ROMEO truth against the numbers ref 000 §IV-D derives from it.
TEST(Cases, RomeoTruthReproducesSeed000) {
  const Truth truth = ReadTruth(Case("romeo", "truth.yaml"));
  const auto& surge = truth.dofs.at(Dof::kSurge).params;
  const auto& yaw = truth.dofs.at(Dof::kYaw).params;
  const auto& heave = truth.dofs.at(Dof::kHeave).params;

  // "offset 35 N, corresponding to a regime speed of 0.27 m/s" (two digits: ±0.005).
  EXPECT_NEAR(SteadySpeed(surge.at("k"), surge.at("kq"), 35.0), 0.27, 0.005);
  // eq. 13 at 0.27 m/s: "k_L = 212.25 (Ns/m)" (printed to 0.01: ±0.005).
  const double k_l = surge.at("k") + 2 * surge.at("kq") * 0.27;
  EXPECT_NEAR(k_l, 212.25, 0.005);
  // eq. 14 with m_u = 675 kg: "omega_opt = 0.18" (two digits).
  EXPECT_NEAR(1.0 / (std::sqrt(3.0) * 675.0 / k_l), 0.18, 0.005);
  // m_u = 890 kg: "a phase lag ... of about 45° is expected" for a 26 s period: atan(w·m/k_L).
  EXPECT_NEAR(Deg(std::atan(2 * kPi / 26 * surge.at("m") / k_l)), 45.0, 1.0);

  // Yaw: I_r = (1/12)·450·(1.3² + 0.9²) = 93.75 kg·m², "omega_opt = 0.176" from it (eq. 14),
  // and with the estimate I_r = 84, k_r = 28.6: "a phase lag of about 37.5°" at 24 s.
  EXPECT_DOUBLE_EQ(truth.vehicle.RigidInertia(Dof::kYaw), 93.75);
  EXPECT_NEAR(1.0 / (std::sqrt(3.0) * 93.75 / yaw.at("k")), 0.176, 0.0005);
  EXPECT_NEAR(Deg(std::atan(2 * kPi / 24 * yaw.at("m") / yaw.at("k"))), 37.5, 0.5);

  // Heave, eq. 20 / Table II: "during experiments 0 and 1 the vehicle was positive, during
  // experiment 2 it was roughly neutral, and in the last two it was negative" (z down: a
  // positive vehicle has a negative net force).
  const double w = heave.at("bias"), dw = heave.at("bias_step");
  EXPECT_LT(w + 0 * dw, 0.0);
  EXPECT_LT(w + 1 * dw, 0.0);
  EXPECT_LT(std::abs(w + 2 * dw), dw / 2);
  EXPECT_GT(w + 3 * dw, 0.0);
  EXPECT_GT(w + 4 * dw, 0.0);
  // One diver's lead is "about 0.7 kg in water": 7.1 N / 9.81 = 0.72 kg.
  EXPECT_NEAR(dw / 9.81, 0.7, 0.05);
}

// VSOR: the contract parameters give back Table 5's coefficients of ref 002 eq. 4 (Table 2:
// alpha = -d_L/m, beta = -d_Q/m, gamma = 1/m, delta = -b/m; bias = -b). Tolerances are half a
// unit of the last printed digit, plus the rounding of d_Q and m for beta.
TEST(Cases, VsorTruthReproducesTable5) {
  const Truth truth = ReadTruth(Case("vsor", "truth.yaml"));
  const auto& p = truth.dofs.at(Dof::kYaw).params;
  EXPECT_NEAR(-p.at("k") / p.at("m"), -0.5478, 5e-5);
  EXPECT_NEAR(-p.at("kq") / p.at("m"), -4.9945, 5e-4);
  EXPECT_NEAR(1.0 / p.at("m"), 0.007317, 5e-7);
  EXPECT_NEAR(p.at("bias") / p.at("m"), 0.068256, 5e-6);
}

// VSOR mappings against ref 002 eq. 5 with beta = 45°, R = 1.1·sin 45° (vehicle.yaml).
TEST(Cases, VsorMappingsReproduceEquation5) {
  const Vehicle v = ReadVehicle(Case("vsor", "vehicle.yaml"));
  const double beta = kPi / 4, r = 1.1 * std::sin(kPi / 4);
  auto t = UnitForces(v, "surge-ht1-ht6");
  EXPECT_NEAR((t["HT1"] + t["HT6"]) * std::cos(beta), 1.0, kShareTolerance);  // tau_1
  t = UnitForces(v, "sway-ht6-ht7");
  EXPECT_NEAR((t["HT6"] + t["HT7"]) * std::sin(beta), 1.0, kShareTolerance);  // tau_2
  t = UnitForces(v, "vertical-all");
  EXPECT_NEAR(t["VT3"] + t["VT4"] + t["VT5"] + t["VT8"], 1.0, 1e-12);  // tau_3 / eta
  t = UnitForces(v, "yaw-ht1-ht7");
  EXPECT_NEAR((t["HT1"] + t["HT7"]) * r, 1.0, kShareTolerance);  // tau_4
}

// URIS: the contract parameters give back Table 4 of ref 004 (dx/dt = -alpha·x + gamma·tau +
// delta, see cases/uris/truth.yaml). Half a unit of the last printed digit.
TEST(Cases, UrisTruthReproducesTable4) {
  const Truth truth = ReadTruth(Case("uris", "truth.yaml"));
  struct Row {
    Dof dof;
    double alpha, gamma, delta, tol_alpha, tol_gamma, tol_delta;
  };
  const Row rows[] = {{Dof::kSurge, 0.3302, 0.0169, -0.0070, 5e-5, 5e-5, 5e-5},
                      {Dof::kPitch, 0.6514, 0.8052, 0.0, 5e-5, 5e-5, 1e-12},
                      {Dof::kYaw, 1.1006, 0.5236, -0.0435, 5e-5, 5e-5, 5e-5}};
  for (const Row& row : rows) {
    SCOPED_TRACE(DofName(row.dof));
    const auto& p = truth.dofs.at(row.dof).params;
    EXPECT_NEAR(p.at("k") / p.at("m"), row.alpha, row.tol_alpha);
    EXPECT_NEAR(1.0 / p.at("m"), row.gamma, row.tol_gamma);
    EXPECT_NEAR(p.at("bias") / p.at("m"), row.delta, row.tol_delta);
    EXPECT_EQ(p.at("kq"), 0.0);  // Table 4: beta = 0
  }
  // Differential mappings with 0.25 m arms (vehicle.yaml): N = 0.25·(F_XL - F_XR),
  // M = 0.25·(F_ZR - F_ZF).
  auto t = UnitForces(truth.vehicle, "yaw-x");
  EXPECT_NEAR(0.25 * (t["XL"] - t["XR"]), 1.0, 1e-12);
  t = UnitForces(truth.vehicle, "pitch-z");
  EXPECT_NEAR(0.25 * (t["ZR"] - t["ZF"]), 1.0, 1e-12);
}

// Where the truth lies against the a priori inertia box of its vehicle file. Inside, except
// where the papers' own a priori missed (documented in the case files): ROMEO's yaw (84 kg·m²
// measured against a 93.75 uniform box, ref 000 §IV-D) and VSOR's yaw (136.66 against
// 60·(1 + 100%), ref 002 §7). A planner must cope with both.
TEST(Cases, TruthsAgainstTheirAPrioriInertiaBoxes) {
  const std::vector<std::pair<std::string, Dof>> misses = {{"romeo", Dof::kYaw},
                                                           {"vsor", Dof::kYaw}};
  for (const char* name : {"romeo", "vsor", "uris"}) {
    const Truth truth = ReadTruth(Case(name, "truth.yaml"));
    for (const auto& [dof, t] : truth.dofs) {
      const auto box = truth.vehicle.InertiaBounds(dof);
      const double m = t.params.at("m");
      const bool inside = box[0] <= m && m <= box[1];
      const bool documented_miss =
          std::find(misses.begin(), misses.end(), std::make_pair(std::string(name), dof)) !=
          misses.end();
      EXPECT_EQ(inside, !documented_miss) << name << " " << DofName(dof) << ": m = " << m
                                          << ", box [" << box[0] << ", " << box[1] << "]";
    }
  }
}

}  // namespace
}  // namespace uuvplan::model
