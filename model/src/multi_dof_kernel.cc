#include "multi_dof_kernel.h"

#include <algorithm>
#include <cmath>

#include "simulation_loop.h"

namespace uuvplan::model::internal {

using Kernel = DofModelKernel;

JointSystem::JointSystem(const MultiDofModel& model, const JointConditions& c,
                         const Eigen::VectorXd& theta)
    : model_(model) {
  std::size_t largest = 0;
  for (int i = 0; i < model.num_dofs(); ++i) {
    const Excitation* input = i < static_cast<int>(c.inputs.size()) ? c.inputs[i] : nullptr;
    conditions_.push_back({input, 0, c.start_time, nullptr});
    theta_.push_back(model.LocalTheta(i, theta));
    inv_.push_back(Kernel::Invert(model.dof_model(i), theta_.back().data()));
    const DofModel& m = model.dof_model(i);
    largest = std::max(largest, static_cast<std::size_t>(m.num_states() * m.num_parameters()));
    velocity_.push_back({Index(model.dof(i)), model.state_offset(i) + 1});
  }
  b_local_.resize(largest);
  if (model.planar()) {
    x_ = model.state_offset(model.DofIndex(Dof::kSurge));
    y_ = model.state_offset(model.DofIndex(Dof::kSway));
    psi_ = model.state_offset(model.DofIndex(Dof::kYaw));
  }
}

JointSystem::Input JointSystem::Sample(double t) const {
  Input in;
  for (int i = 0; i < model_.num_dofs(); ++i) {
    in[i] = Kernel::SampleInput(model_.dof_model(i), t, conditions_[i], theta_[i].data());
  }
  return in;
}

bool JointSystem::held() const {
  return std::all_of(conditions_.begin(), conditions_.end(), [](const TrialConditions& c) {
    return !c.input || c.input->piecewise_constant();
  });
}

std::vector<double> JointSystem::Breakpoints() const {
  std::vector<double> breaks;
  for (const TrialConditions& c : conditions_) {
    if (!c.input) continue;
    const TimesView b = c.input->Breakpoints();
    breaks.insert(breaks.end(), b.begin(), b.end());
  }
  std::sort(breaks.begin(), breaks.end());
  return breaks;
}

TermInputs JointSystem::TermInputsOf(int i, double t, const double* x, const Input& in) const {
  const DofModel& m = model_.dof_model(i);
  TermInputs tc = Kernel::TermInputsAt(m, t, x + model_.state_offset(i), in[i], conditions_[i]);
  if (m.needs_aux()) {
    for (const auto& [dof, state] : velocity_) tc.velocities[dof] = x[state];
  }
  return tc;
}

void JointSystem::Derivative(double t, const double* x, const Input& in, double* dx) const {
  for (int i = 0; i < model_.num_dofs(); ++i) {
    const int o = model_.state_offset(i);
    Kernel::DerivativeAt(model_.dof_model(i), TermInputsOf(i, t, x, in), x + o, in[i],
                         theta_[i].data(), inv_[i], dx + o);
  }
  Kinematics(x, dx, nullptr);
}

void JointSystem::Linearize(double t, const double* x, const Input& in, double* dx, double* A,
                            double* B) const {
  const int nx = num_states(), np = num_parameters();
  std::fill(A, A + nx * nx, 0.0);
  std::fill(B, B + nx * np, 0.0);
  for (int i = 0; i < model_.num_dofs(); ++i) {
    const DofModel& m = model_.dof_model(i);
    const int o = model_.state_offset(i), n = m.num_states(), p = m.num_parameters();
    // The DOF's input with the other DOFs' velocities from the joint state.
    InputSample s = in[i];
    for (const auto& [dof, state] : velocity_) s.velocities[dof] = x[state];
    const double* th = theta_[i].data();
    double a[9];
    double* b = b_local_.data();
    if (n == 3) {
      Kernel::Linearize<3>(m, t, x + o, s, conditions_[i], th, inv_[i], dx + o, a, b);
    } else {
      Kernel::Linearize<2>(m, t, x + o, s, conditions_[i], th, inv_[i], dx + o, a, b);
    }
    for (int r = 0; r < n; ++r) {
      for (int q = 0; q < n; ++q) A[(o + r) * nx + o + q] = a[r * n + q];
      // ∂f/∂θ = ∂f/∂θ_i·T_i
      for (const TieEntry& e : model_.tie(i))
        B[(o + r) * np + e.global] += b[r * p + e.local] * e.coefficient;
    }
    if (m.needs_aux())
      AddOtherVelocityPartials(i, Kernel::TermInputsAt(m, t, x + o, s, conditions_[i]), A);
  }
  Kinematics(x, dx, A);
}

void JointSystem::AddOtherVelocityPartials(int i, const TermInputs& tc, double* A) const {
  const DofModel& m = model_.dof_model(i);
  const int o = model_.state_offset(i), nx = num_states();
  double J_F_v[kNumDofs] = {};
  for (std::size_t k = 0; k < m.terms().size(); ++k) {
    const ForceTerm& term = *m.terms()[k];
    if (!term.NeedsOtherVelocities()) continue;
    term.OtherVelocityPartials(tc, theta_[i].data() + m.term_offset(static_cast<int>(k)), J_F_v);
  }
  for (int j = 0; j < model_.num_dofs(); ++j) {
    if (j == i) continue;
    A[(o + 1) * nx + model_.state_offset(j) + 1] += J_F_v[Index(model_.dof(j))] * inv_[i].mass;
  }
}

void JointSystem::Kinematics(const double* x, double* dx, double* A) const {
  if (x_ < 0) return;
  const double u = x[x_ + 1], v = x[y_ + 1], c = std::cos(x[psi_]), s = std::sin(x[psi_]);
  dx[x_] = u * c - v * s;  // ref 003: η̇₁ = J₁(η₂)·ν₁ in the plane
  dx[y_] = u * s + v * c;
  if (!A) return;
  const int nx = num_states();
  A[x_ * nx + x_ + 1] = c;
  A[x_ * nx + y_ + 1] = -s;
  A[x_ * nx + psi_] = -u * s - v * c;
  A[y_ * nx + x_ + 1] = s;
  A[y_ * nx + y_ + 1] = c;
  A[y_ * nx + psi_] = u * c - v * s;
}

}  // namespace uuvplan::model::internal

namespace uuvplan::model {

// The joint model through the one simulation loop (simulation_loop.h, simulator.h).
Trajectory Simulate(const MultiDofModel& model, const Eigen::VectorXd& theta,
                    const JointConditions& c, TimesView output_times,
                    const SimulationOptions& options, const Eigen::VectorXd* x0) {
  if (options.initial_velocity_column) {
    throw std::invalid_argument(
        "Simulate: SimulationOptions::initial_velocity_column is for a 1-DOF model only");
  }
  const internal::JointSystem sys(model, c, theta);
  return internal::IntegrateSystem(sys, output_times, 0.0, options, x0, nullptr);
}

}  // namespace uuvplan::model
