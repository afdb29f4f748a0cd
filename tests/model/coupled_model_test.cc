// The coupled horizontal model of seed 003 (model/coupled_model.h), its simulation and its
// virtual pool trial.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "uuvplan/io/truth_yaml.h"
#include "uuvplan/model/coupled_model.h"
#include "uuvplan/model/coupled_simulator.h"
#include "uuvplan/model/coupled_virtual_trial.h"
#include "uuvplan/model/input_error.h"

namespace uuvplan::model {
namespace {

CoupledHorizontalModel Asv() {
  CoupledHorizontalModel m;
  m.theta << 330, 30, 90, 1.5, 510, 80, 260, -2.0, 177, 40, 60, 0.5;
  return m;
}

Truth AsvTruth() { return io::ReadTruth(std::string(UUVPLAN_SOURCE_DIR) + "/cases/asv/truth.yaml"); }

TEST(CoupledModel, NamesAndUnitsComeFromTheVocabulary) {
  const std::vector<std::string> names = CoupledParameterNames();
  ASSERT_EQ(names.size(), 12u);
  EXPECT_EQ(names[5], "sway.k");
  EXPECT_EQ(CoupledParameterUnit(5), "N·s/m");
  EXPECT_EQ(CoupledParameterUnit(10), "N·m·s²/rad²");
  EXPECT_EQ(CoupledParameterUnit(8), "kg·m²");
}

// Seed 003: with x_g = 0 and Y_ṙ = 0, C_RB + C_A is skew-symmetric, so the Coriolis and
// centripetal forces do no work: νᵀ·C(ν)·ν = 0 for every ν (exact up to rounding).
TEST(CoupledModel, CoriolisDoesNoWork) {
  const CoupledHorizontalModel m = Asv();
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int k = 0; k < 100; ++k) {
    const Horizontal nu(n(rng), n(rng), n(rng));
    EXPECT_NEAR(nu.dot(m.Coriolis(nu)), 0.0, 1e-9 * m.Coriolis(nu).norm() * nu.norm() + 1e-12);
  }
  // The seed's terms one by one: surge m_v·v·r, sway −m_u·u·r, yaw −(X_u̇ − Y_v̇)·u·v.
  const Horizontal f = m.Coriolis(Horizontal(1.0, 0.5, 0.2));
  EXPECT_DOUBLE_EQ(f[0], 510 * 0.5 * 0.2);
  EXPECT_DOUBLE_EQ(f[1], -330 * 1.0 * 0.2);
  EXPECT_DOUBLE_EQ(f[2], (330 - 510) * 1.0 * 0.5);
}

// The regressor form m_i·ν̇_i + h_i(ν)·θ = τ_i holds for the accelerations the model gives.
TEST(CoupledModel, RegressorReproducesTheEquations) {
  const CoupledHorizontalModel m = Asv();
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int k = 0; k < 50; ++k) {
    const Horizontal nu(n(rng), n(rng), n(rng)), tau(100 * n(rng), 100 * n(rng), 50 * n(rng));
    const Horizontal acc = m.Acceleration(nu, tau);
    for (int i = 0; i < 3; ++i) {
      const double lhs = m.Inertia(i) * acc[i] + CoupledRegressor(i, nu).dot(m.theta);
      EXPECT_NEAR(lhs, tau[i], 1e-9 * (std::abs(tau[i]) + 1));
    }
  }
}

TEST(CoupledModel, AdmissibleNamesTheFirstBadParameter) {
  CoupledHorizontalModel m = Asv();
  std::string why;
  EXPECT_TRUE(m.Admissible(&why));
  m.theta[CoupledIndex(1, "kq")] = -3.0;
  EXPECT_FALSE(m.Admissible(&why));
  EXPECT_NE(why.find("sway.kq = -3 N·s²/m²"), std::string::npos) << why;
}

// Without drag or thrust the kinetic energy ½(m_u u² + m_v v² + m_r r²) is conserved (the
// Coriolis terms do no work): RK4 at 10 ms over 20 s keeps it to 1e-6.
TEST(CoupledSimulator, ConservesEnergyWithoutDrag) {
  CoupledHorizontalModel m;
  m.theta << 330, 0, 0, 0, 510, 0, 0, 0, 177, 0, 0, 0;
  const Horizontal nu0(1.0, 0.3, 0.4);
  auto energy = [&](const Horizontal& nu) {
    return 0.5 * (330 * nu[0] * nu[0] + 510 * nu[1] * nu[1] + 177 * nu[2] * nu[2]);
  };
  const CoupledTrajectory x = SimulateCoupled(
      m, [](double) { return Horizontal::Zero(); }, nu0, {0.0, 10.0, 20.0}, {}, 0.01);
  ASSERT_EQ(x.nu.size(), 3u);
  EXPECT_NEAR(energy(x.nu[2]) / energy(nu0), 1.0, 1e-6);
  EXPECT_GT((x.nu[2] - nu0).norm(), 0.05);  // the energy moved between the DOFs
}

// A steady turn under constant thrust: the state settles where the equations balance.
TEST(CoupledSimulator, SettlesInASteadyTurn) {
  const CoupledHorizontalModel m = Asv();
  const Horizontal tau(80, 0, 20);
  const CoupledTrajectory x = SimulateCoupled(
      m, [&](double) { return tau; }, Horizontal::Zero(), {200.0}, {}, 0.01);
  const Horizontal acc = m.Acceleration(x.nu[0], tau);
  EXPECT_LT(acc.norm(), 1e-6);
  EXPECT_GT(x.nu[0][2], 0.1);   // turning
  EXPECT_LT(x.nu[0][1], -1e-3); // a surging, turning body side-slips outward (−m_u·u·r)
}

TEST(CoupledVirtualTrial, LogsEveryHorizontalColumnDeterministically) {
  const Truth truth = AsvTruth();
  TrialDesign surge;
  surge.dof = Dof::kSurge;
  surge.kind = TrialKind::kSteady;
  surge.mapping = "horizontal-all-surge";
  surge.force = 80;
  const CoupledTrialDesign design{"t", CombinedMode::kSurgeYaw, 30.0, {surge, [] {
    TrialDesign yaw;
    yaw.dof = Dof::kYaw;
    yaw.kind = TrialKind::kSteady;
    yaw.mapping = "horizontal-all-yaw";
    yaw.force = 20;
    return yaw;
  }()}};
  VirtualPoolOptions options;
  options.seed = 7;
  const TrialLog a = RunCoupledVirtualTrial(truth, design, options);
  const TrialLog b = RunCoupledVirtualTrial(truth, design, options);
  ASSERT_EQ(a.t, b.t);
  for (Dof d : kHorizontalDofs) {
    EXPECT_TRUE(a.HasForce(d) && a.HasVelocity(d)) << DofName(d);
  }
  EXPECT_TRUE(a.HasPosition(Dof::kYaw));
  EXPECT_FALSE(a.HasPosition(Dof::kSurge));  // the ASV declares no surge position sensor
  EXPECT_EQ(a.force[Index(Dof::kSway)].front(), 0.0);  // sway is not pushed in surge+yaw
  // The sway velocity is not zero: the turn drives it (−m_u·u·r), measured with 0.02 m/s noise.
  double sum = 0.0;
  int n = 0;
  for (double v : a.velocity[Index(Dof::kSway)]) {
    if (std::isnan(v)) continue;
    sum += v;
    ++n;
  }
  EXPECT_LT(sum / n, -0.02);
}

TEST(CoupledVirtualTrial, RefusesInputsThatDoNotMatchTheMode) {
  const Truth truth = AsvTruth();
  TrialDesign sway;
  sway.dof = Dof::kSway;
  sway.mapping = "horizontal-all-sway";
  const CoupledTrialDesign design{"bad", CombinedMode::kSurgeYaw, 10.0, {sway}};
  try {
    RunCoupledVirtualTrial(truth, design, VirtualPoolOptions{});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("expected one input for surge"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace uuvplan::model
