// The joint model's right-hand side (multi_dof_model.h) for the simulation loop (simulator.cc)
// and MultiDofModel itself: each DOF's block by DofModelKernel, the other DOFs' velocities read
// from the joint state, their partials ∂F_i/∂ξ_j, the planar kinematics, and
// B = Σ_i ∂f/∂θ_i·T_i. Model library only.
#pragma once

#include <array>
#include <utility>
#include <vector>

#include "dof_model_kernel.h"
#include "uuvplan/model/multi_dof_model.h"

namespace uuvplan::model::internal {

class JointSystem {
 public:
  static constexpr int kStates = 0;  // the model's: num_states()
  static constexpr int kMaxStates = 3 * kNumDofs;
  /// One input sample per DOF of the model.
  using Input = std::array<InputSample, kNumDofs>;

  JointSystem(const MultiDofModel& model, const JointConditions& c, const Eigen::VectorXd& theta);

  int num_states() const { return model_.num_states(); }
  int num_parameters() const { return model_.num_parameters(); }
  Input Sample(double t) const;
  /// A held input does not move inside a step (the other DOFs' velocities are states).
  void Refresh(double /*t*/, Input* /*in*/) const {}
  /// Every input null or piecewise constant.
  bool held() const;
  /// Every input's breakpoints, sorted.
  std::vector<double> Breakpoints() const;

  /// dx/dt (multi_dof_model.h).
  void Derivative(double t, const double* x, const Input& in, double* dx) const;
  /// dx/dt and A = ∂f/∂x, B = ∂f/∂θ, row-major (nx × nx, nx × np), both fully written.
  void Linearize(double t, const double* x, const Input& in, double* dx, double* A,
                 double* B) const;

 private:
  /// DOF i's term context, every DOF's velocity from the joint state.
  TermInputs TermInputsOf(int i, double t, const double* x, const Input& in) const;
  /// Adds ∂F_i/∂ξ_j / m_i of the terms that read other DOFs' velocities to A's row of ξ_i.
  void AddOtherVelocityPartials(int i, const TermInputs& tc, double* A) const;
  /// The pose rows of dx (and A): η̇ = J(ψ)·ν in the plane.
  void Kinematics(const double* x, double* dx, double* A) const;

  const MultiDofModel& model_;
  std::vector<TrialConditions> conditions_;  // per DOF: its input, the campaign clock
  std::vector<Eigen::VectorXd> theta_;       // θ_i = T_i·θ
  std::vector<DofModelKernel::Inverses> inv_;
  mutable std::vector<double> b_local_;        // ∂f_i/∂θ_i of one block
  std::vector<std::pair<int, int>> velocity_;  // per DOF: (Index(dof), its velocity's state)
  int x_ = -1, y_ = -1, psi_ = -1;             // state offsets of surge, sway, yaw when planar
};

}  // namespace uuvplan::model::internal
