// The coupled horizontal model of ref 003 (model/coupled_model.h) as a multi-DOF model, its
// simulation and its virtual pool trial.
#include "uuvplan/model/coupled_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/asv.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/simulator.h"
#include "uuvplan/model/virtual_pool.h"

namespace uuvplan::model {
namespace {

using Horizontal = Eigen::Vector3d;

using testing::AsvCoupledModel;
using testing::AsvTheta;
using testing::AsvTruth;

// The joint state at rest but for the velocities ν.
Eigen::VectorXd StateOf(const MultiDofModel& m, const Horizontal& nu) {
  Eigen::VectorXd x = Eigen::VectorXd::Zero(m.num_states());
  for (int i = 0; i < 3; ++i) x[m.state_offset(i) + 1] = nu[i];
  return x;
}

// The force of each DOF's coupling term (the Coriolis and centripetal forces of the header).
Horizontal Coriolis(const MultiDofModel& m, const Eigen::VectorXd& theta, const Horizontal& nu) {
  Horizontal f = Horizontal::Zero();
  for (int i = 0; i < 3; ++i) {
    const DofModel& d = m.dof_model(i);
    const Eigen::VectorXd local = m.LocalTheta(i, theta);
    TermInputs tc;
    tc.xi = nu[i];
    for (int j = 0; j < 3; ++j) tc.velocities[Index(m.dof(j))] = nu[j];
    for (std::size_t k = 0; k < d.terms().size(); ++k) {
      if (!d.terms()[k]->NeedsOtherVelocities()) continue;
      f[i] += d.terms()[k]->Value(tc, local.data() + d.term_offset(static_cast<int>(k)));
    }
  }
  return f;
}

// ν̇ under a constant thrust τ (η = 1).
Horizontal Acceleration(const MultiDofModel& m, const Eigen::VectorXd& theta, const Horizontal& nu,
                        const Horizontal& tau) {
  std::vector<std::unique_ptr<Excitation>> thrust;
  JointConditions c;
  for (int i = 0; i < 3; ++i) {
    thrust.push_back(MakeSteadyExcitation(tau[i], -1, 10.0));
    c.inputs.push_back(thrust.back().get());
  }
  Eigen::VectorXd dx(m.num_states());
  m.Derivative(0.0, StateOf(m, nu).data(), c, theta, dx.data());
  return {dx[m.state_offset(0) + 1], dx[m.state_offset(1) + 1], dx[m.state_offset(2) + 1]};
}

TEST(CoupledModel, NamesAndUnitsComeFromTheVocabulary) {
  const MultiDofModel m = AsvCoupledModel();
  const std::vector<std::string>& names = m.parameter_names();
  ASSERT_EQ(names.size(), 12u);
  EXPECT_EQ(names[5], "sway.k");
  EXPECT_EQ(m.ParameterUnit(5), "N·s/m");
  EXPECT_EQ(m.ParameterUnit(10), "N·m·s²/rad²");
  EXPECT_EQ(m.ParameterUnit(8), "kg·m²");
  EXPECT_TRUE(m.planar());
}

// Ref 003: with x_g = 0 and Y_ṙ = 0, C_RB + C_A is skew-symmetric, so the Coriolis and
// centripetal forces do no work: νᵀ·C(ν)·ν = 0 for every ν (exact up to rounding).
TEST(CoupledModel, CoriolisDoesNoWork) {
  const MultiDofModel m = AsvCoupledModel();
  const Eigen::VectorXd theta = AsvTheta();
  std::mt19937_64 rng(3);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int k = 0; k < 100; ++k) {
    const Horizontal nu(n(rng), n(rng), n(rng));
    const Horizontal f = Coriolis(m, theta, nu);
    EXPECT_NEAR(nu.dot(f), 0.0, 1e-9 * f.norm() * nu.norm() + 1e-12);
  }
  // The paper's terms one by one: surge m_v·v·r, sway −m_u·u·r, yaw −(X_u̇ − Y_v̇)·u·v.
  const Horizontal f = Coriolis(m, theta, Horizontal(1.0, 0.5, 0.2));
  EXPECT_DOUBLE_EQ(f[0], 510 * 0.5 * 0.2);
  EXPECT_DOUBLE_EQ(f[1], -330 * 1.0 * 0.2);
  EXPECT_DOUBLE_EQ(f[2], (330 - 510) * 1.0 * 0.5);
}

// The regressor form m_i·ν̇_i + r_i(ν)·θ = τ_i holds for the accelerations the model gives.
TEST(CoupledModel, RegressorReproducesTheEquations) {
  const MultiDofModel m = AsvCoupledModel();
  const Eigen::VectorXd theta = AsvTheta();
  std::mt19937_64 rng(5);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int k = 0; k < 50; ++k) {
    const Horizontal nu(n(rng), n(rng), n(rng)), tau(100 * n(rng), 100 * n(rng), 50 * n(rng));
    const Horizontal acc = Acceleration(m, theta, nu, tau);
    for (int i = 0; i < 3; ++i) {
      const double lhs = theta[4 * i] * acc[i] + m.EquationRegressor(i, nu.transpose()).dot(theta);
      EXPECT_NEAR(lhs, tau[i], 1e-9 * (std::abs(tau[i]) + 1));
    }
  }
}

TEST(CoupledModel, AdmissibleNamesTheFirstBadParameter) {
  const MultiDofModel m = AsvCoupledModel();
  Eigen::VectorXd theta = AsvTheta();
  EXPECT_EQ(m.Inadmissible(theta), "");
  theta[m.ParameterIndex("sway.kq")] = -3.0;
  EXPECT_NE(m.Inadmissible(theta).find("sway.kq = -3 N·s²/m²"), std::string::npos)
      << m.Inadmissible(theta);
}

// Without drag or thrust the kinetic energy ½(m_u u² + m_v v² + m_r r²) is conserved (the
// Coriolis terms do no work): RK4 at 10 ms over 20 s keeps it to 1e-6.
TEST(CoupledSimulator, ConservesEnergyWithoutDrag) {
  const MultiDofModel m = AsvCoupledModel();
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(12);
  theta << 330, 0, 0, 0, 510, 0, 0, 0, 177, 0, 0, 0;
  const Horizontal nu0(1.0, 0.3, 0.4);
  auto energy = [&](const Horizontal& nu) {
    return 0.5 * (330 * nu[0] * nu[0] + 510 * nu[1] * nu[1] + 177 * nu[2] * nu[2]);
  };
  const Eigen::VectorXd x0 = StateOf(m, nu0);
  SimulationOptions options;
  options.step_s = 0.01;
  const std::vector<double> times = {0.0, 10.0, 20.0};
  const Trajectory x = Simulate(m, theta, JointConditions{}, times, options, &x0);
  ASSERT_EQ(x.t.size(), 3u);
  const Horizontal nu(x.x(2, m.state_offset(0) + 1), x.x(2, m.state_offset(1) + 1),
                      x.x(2, m.state_offset(2) + 1));
  EXPECT_NEAR(energy(nu) / energy(nu0), 1.0, 1e-6);
  EXPECT_GT((nu - nu0).norm(), 0.05);  // the energy moved between the DOFs
}

// A steady turn under constant thrust: the state settles where the equations balance.
TEST(CoupledSimulator, SettlesInASteadyTurn) {
  const MultiDofModel m = AsvCoupledModel();
  const Eigen::VectorXd theta = AsvTheta();
  const Horizontal tau(80, 0, 20);
  std::vector<std::unique_ptr<Excitation>> thrust;
  JointConditions c;
  for (int i = 0; i < 3; ++i) {
    thrust.push_back(MakeSteadyExcitation(tau[i], -1, 300.0));
    c.inputs.push_back(thrust.back().get());
  }
  SimulationOptions options;
  options.step_s = 0.01;
  const std::vector<double> times = {200.0};
  const Trajectory x = Simulate(m, theta, c, times, options);
  const Horizontal nu(x.x(0, m.state_offset(0) + 1), x.x(0, m.state_offset(1) + 1),
                      x.x(0, m.state_offset(2) + 1));
  EXPECT_LT(Acceleration(m, theta, nu, tau).norm(), 1e-6);
  EXPECT_GT(nu[2], 0.1);    // turning
  EXPECT_LT(nu[1], -1e-3);  // a surging, turning body side-slips outward (−m_u·u·r)
}

TrialDesign Steady(Dof dof, const char* mapping, double force) {
  TrialDesign d;
  d.dof = dof;
  d.kind = TrialKind::kSteady;
  d.mapping = mapping;
  d.force = force;
  return d;
}

TEST(CoupledVirtualTrial, LogsEveryHorizontalColumnDeterministically) {
  const Truth truth = AsvTruth();
  const MultiDofModel m = CoupledModelOfTruth(truth);
  const Eigen::VectorXd theta = CoupledThetaOfTruth(m, truth);
  const CombinedTrialDesign design{"t",
                                   {Dof::kSurge, Dof::kYaw},
                                   30.0,
                                   {Steady(Dof::kSurge, "horizontal-all-surge", 80),
                                    Steady(Dof::kYaw, "horizontal-all-yaw", 20)}};
  VirtualPoolOptions options;
  options.seed = 7;
  const TrialLog a = RunCombinedTrial(truth, m, theta, design, options);
  const TrialLog b = RunCombinedTrial(truth, m, theta, design, options);
  ASSERT_EQ(a.t, b.t);
  for (Dof d : kHorizontalDofs) {
    EXPECT_TRUE(a.HasForce(d) && a.HasVelocity(d)) << DofName(d);
  }
  EXPECT_TRUE(a.HasPosition(Dof::kYaw));
  EXPECT_FALSE(a.HasPosition(Dof::kSurge));            // the ASV declares no surge position sensor
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
  const MultiDofModel m = CoupledModelOfTruth(truth);
  const CombinedTrialDesign design{
      "bad", {Dof::kSurge, Dof::kYaw}, 10.0, {Steady(Dof::kSway, "horizontal-all-sway", 0)}};
  try {
    RunCombinedTrial(truth, m, CoupledThetaOfTruth(m, truth), design, VirtualPoolOptions{});
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("expected one input for surge"), std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace uuvplan::model
