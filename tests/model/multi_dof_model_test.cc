// The multi-DOF model (model/multi_dof_model.h): a model of one DOF is the DofModel, the joint
// Jacobians and the forward sensitivities on the global θ against finite differences, the ties.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/asv.h"
#include "uuvplan/model/simulator.h"

namespace uuvplan::model {
namespace {

using testing::AsvCoupledModel;
using testing::AsvTheta;

// Sines on every DOF of the coupled model (η = 1).
struct Sines {
  explicit Sines(const MultiDofModel& m) {
    for (int i = 0; i < m.num_dofs(); ++i) {
      thrust.push_back(MakeSineExcitation(20.0 + 10 * i, 40.0, 0.3 + 0.2 * i, -1, 40.0));
      c.inputs.push_back(thrust.back().get());
    }
  }
  std::vector<std::unique_ptr<Excitation>> thrust;
  JointConditions c;
};

// A model of one DOF without ties is its DofModel: the same state and sensitivities, with every
// standard term, thruster lag and a free η on.
TEST(MultiDofModel, OneDofIsTheDofModel) {
  const Vehicle v = testing::AsvTruth().vehicle;
  ModelStructure s;
  s.dof = Dof::kSurge;
  s.Add("lag");
  const DofModel dof(v, s);
  const MultiDofModel joint(v, {s});
  ASSERT_EQ(joint.num_states(), dof.num_states());
  ASSERT_EQ(joint.num_parameters(), dof.num_parameters());
  EXPECT_EQ(joint.parameter_names()[1], "surge." + dof.parameter_names()[1]);
  Eigen::VectorXd theta(dof.num_parameters());
  theta << 330, 30, 90, 1.5, 0.3;
  const auto input = MakeSineExcitation(20.0, 40.0, 0.4, 0, 30.0);
  SimulationOptions o;
  o.step_s = 0.05;
  o.sensitivities = true;
  std::vector<double> times;
  for (int k = 0; k <= 300; ++k) times.push_back(0.1 * k);
  const Trajectory a = Simulate(dof, theta, TrialConditions{input.get()}, times, o);
  const Trajectory b = Simulate(joint, theta, JointConditions{{input.get()}, 0.0}, times, o);
  for (int s_ = 0; s_ < dof.num_states(); ++s_) {
    EXPECT_LE((a.x.col(s_) - b.x.col(s_)).norm(), 1e-12 * a.x.col(s_).norm()) << s_;
    EXPECT_LE((a.S[s_] - b.S[s_]).norm(), 1e-12 * a.S[s_].norm()) << s_;
  }
}

TEST(MultiDofModel, TiesMapTheGlobalThetaOnEachDof) {
  const MultiDofModel m = AsvCoupledModel();
  const Eigen::VectorXd theta = AsvTheta();
  const int yaw = m.DofIndex(Dof::kYaw), surge = m.DofIndex(Dof::kSurge);
  const Eigen::VectorXd local = m.LocalTheta(yaw, theta);
  EXPECT_EQ(local[m.dof_model(yaw).ParameterIndex("coupling.uv")], 330.0 - 510.0);
  EXPECT_EQ(m.LocalTheta(surge, theta)[m.dof_model(surge).ParameterIndex("coupling.vr")], 510.0);
  EXPECT_EQ(m.ParameterIndex("yaw.coupling.uv"), -1);  // tied: not a parameter of its own
}

// A = ∂f/∂x (the coupling's cross partials and the planar kinematics among them) and
// B = ∂f/∂θ = Σ_i ∂f/∂θ_i·T_i against central differences, off the axes (ψ, u, v, r ≠ 0).
TEST(MultiDofModel, JacobiansMatchFiniteDifferences) {
  const MultiDofModel m = AsvCoupledModel();
  const Sines sines(m);
  const Eigen::VectorXd theta = AsvTheta();
  const int nx = m.num_states(), np = m.num_parameters();
  Eigen::VectorXd x(nx);
  for (int s = 0; s < nx; ++s) x[s] = 0.3 + 0.17 * s * (s % 2 ? 1 : -1);
  Eigen::VectorXd dx(nx);
  Eigen::MatrixXd A(nx, nx), B(nx, np);
  m.Linearize(3.0, x.data(), sines.c, theta, dx.data(), A, B);
  Eigen::VectorXd fp(nx), fm(nx);
  for (int s = 0; s < nx; ++s) {
    const double h = 1e-6;
    Eigen::VectorXd xp = x, xm = x;
    xp[s] += h;
    xm[s] -= h;
    m.Derivative(3.0, xp.data(), sines.c, theta, fp.data());
    m.Derivative(3.0, xm.data(), sines.c, theta, fm.data());
    EXPECT_LE(((fp - fm) / (2 * h) - A.col(s)).norm(), 1e-6 * (A.col(s).norm() + 1))
        << "state " << s;
  }
  for (int j = 0; j < np; ++j) {
    const double h = 1e-6 * std::max(1.0, std::abs(theta[j]));
    Eigen::VectorXd tp = theta, tm = theta;
    tp[j] += h;
    tm[j] -= h;
    m.Derivative(3.0, x.data(), sines.c, tp, fp.data());
    m.Derivative(3.0, x.data(), sines.c, tm, fm.data());
    EXPECT_LE(((fp - fm) / (2 * h) - B.col(j)).norm(), 1e-6 * (B.col(j).norm() + 1e-9))
        << m.parameter_names()[j];
  }
}

// The forward sensitivities integrated with the joint state against central differences of
// whole simulations.
TEST(MultiDofModel, SensitivitiesMatchFiniteDifferences) {
  const MultiDofModel m = AsvCoupledModel();
  const Sines sines(m);
  const Eigen::VectorXd theta = AsvTheta();
  SimulationOptions o;
  o.step_s = 0.05;
  o.sensitivities = true;
  const std::vector<double> times = {5.0, 20.0, 40.0};
  const Trajectory t = Simulate(m, theta, sines.c, times, o);
  o.sensitivities = false;
  for (int j = 0; j < m.num_parameters(); ++j) {
    const double h = 1e-5 * std::max(1.0, std::abs(theta[j]));
    Eigen::VectorXd tp = theta, tm = theta;
    tp[j] += h;
    tm[j] -= h;
    const Trajectory p = Simulate(m, tp, sines.c, times, o), q = Simulate(m, tm, sines.c, times, o);
    for (int s = 0; s < m.num_states(); ++s) {
      const Eigen::VectorXd fd = (p.x.col(s) - q.x.col(s)) / (2 * h);
      EXPECT_LE((fd - t.S[s].col(j)).norm(), 1e-5 * (t.S[s].col(j).norm() + 1e-6))
          << m.parameter_names()[j] << ", state " << s;
    }
  }
}

}  // namespace
}  // namespace uuvplan::model
