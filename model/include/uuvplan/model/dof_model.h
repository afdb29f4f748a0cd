// The 1-DOF model of a vehicle: inertia, a sum of force terms, and the actuator path
// (dead zone, first-order thruster lag) and sensor delay of the effects it includes.
//
// State x = [chi, xi, phi_a]: position, velocity, and (with thruster lag only) actuator force.
//   dchi/dt  = xi
//   dxi/dt   = Σ_j F_j(xi, phi_a, ·; theta_j) / m                       (ref 000 eq. 3)
//   dphi_a/dt = (u - phi_a) / T,  u = u0·(|u0|/u_ref)^p,  u0 = sign(phi_n)·max(|phi_n| - d, 0)
//                                  (lag T, dead zone d, thrust-map exponent p)
// Without lag phi_a = u. Parameters theta = [m, term parameters..., lag, deadzone,
// sensor_delay, thrust_exponent], names from the shared vocabulary (parameter.h, effects.h);
// the effect table says which effect acts where.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <map>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "uuvplan/model/excitation.h"
#include "uuvplan/model/force_term.h"
#include "uuvplan/model/model_structure.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::model {

namespace internal {
class DragTerm;
class ConstantTerm;
class ThrustTerm;
class AdvanceLossTerm;
class CouplingTerm;
class DriftTerm;
struct DofModelKernel;
}  // namespace internal

/// The conditions of one trial that are not states: its input, ballast, clock, other DOFs.
struct TrialConditions {
  const Excitation* input = nullptr;
  int ballast_steps = 0;
  double start_time = 0.0;             ///< campaign clock at t = 0 (s)
  const AuxVelocities* aux = nullptr;  ///< null: other DOFs at rest
};

/// The input at one instant, sampled once per RK4 stage time (and once per step for a
/// piecewise-constant input): commanded force, mapping, the other DOFs' velocities, and the
/// actuator path at phi_n for the theta it was sampled with.
struct InputSample {
  double phi_n = 0.0;
  int mapping = -1;
  std::array<double, kNumDofs> velocities{};
  double u = 0.0;      ///< after the dead zone and the thrust map's shape (DofModel::ActuatorInput)
  double du_dd = 0.0;  ///< ∂u/∂deadzone
  double du_dp = 0.0;  ///< ∂u/∂thrust_exponent
};

class DofModel {
 public:
  DofModel(const Vehicle& vehicle, const ModelStructure& structure);
  DofModel(const DofModel&) = delete;
  DofModel& operator=(const DofModel&) = delete;
  DofModel(DofModel&&) = default;

  Dof dof() const { return structure_.dof; }
  const ModelStructure& structure() const { return structure_; }
  const std::vector<std::string>& parameter_names() const { return names_; }
  int num_parameters() const { return static_cast<int>(names_.size()); }
  /// Index of a parameter in theta, or -1.
  int ParameterIndex(std::string_view name) const;
  int num_states() const { return has_lag() ? 3 : 2; }
  bool has_lag() const { return lag_index_ >= 0; }
  /// True when a term needs the other DOFs' velocities (TrialConditions::aux).
  bool needs_aux() const { return needs_aux_; }
  int sensor_delay_index() const { return delay_index_; }
  const std::vector<std::unique_ptr<ForceTerm>>& terms() const { return terms_; }
  /// True when a term of an effect registered beyond the built-in ones is on (a virtual call
  /// in the simulation loop).
  bool has_registered_terms() const { return !others_.empty(); }
  /// Offset of term j's parameters in theta.
  int term_offset(int j) const { return term_offsets_[j]; }

  /// theta from named values; names missing from `values` take `fallback`'s value, or throw
  /// InputError naming the missing parameter when there is no fallback.
  Eigen::VectorXd Theta(const std::map<std::string, double>& values,
                        const std::map<std::string, double>* fallback = nullptr) const;

  /// The input of trial `c` at time t (the aux velocities only when a coupling term needs them)
  /// and its actuator path for `theta`.
  InputSample SampleInput(double t, const TrialConditions& c, const double* theta) const;
  /// The term context at time t for state x and input `in`.
  TermInputs TermInputsAt(double t, const double* x, const InputSample& in,
                          const TrialConditions& c) const;
  /// Commanded force after the dead zone and the thrust map's shape:
  /// u = u0·(|u0|/u_ref)^p, u0 = sign(phi_n)·max(|phi_n| - d, 0).
  double ActuatorInput(double phi_n, const double* theta) const;

  /// dx/dt at time t, state x, input `in` (sampled with the same theta).
  void Derivative(double t, const double* x, const InputSample& in, const TrialConditions& c,
                  const double* theta, double* dx) const;
  /// dx/dt and its Jacobians A = ∂f/∂x (nx × nx) and B = ∂f/∂theta (nx × ntheta).
  void Linearize(double t, const double* x, const InputSample& in, const TrialConditions& c,
                 const double* theta, double* dx, Eigen::Ref<Eigen::MatrixXd> A,
                 Eigen::Ref<Eigen::MatrixXd> B) const;
  /// The same, sampling the input of `c` at t.
  void Derivative(double t, const double* x, const TrialConditions& c, const double* theta,
                  double* dx) const {
    Derivative(t, x, SampleInput(t, c, theta), c, theta, dx);
  }
  void Linearize(double t, const double* x, const TrialConditions& c, const double* theta,
                 double* dx, Eigen::Ref<Eigen::MatrixXd> A, Eigen::Ref<Eigen::MatrixXd> B) const {
    Linearize(t, x, SampleInput(t, c, theta), c, theta, dx, A, B);
  }
  /// Total force Σ F_j (N or N·m) at a context.
  double TotalForce(const TermInputs& tc, const double* theta) const;

 private:
  friend struct internal::DofModelKernel;  // the simulation loop's inlined derivative
  // The terms by their concrete type, for the simulation loop (no virtual dispatch).
  template <typename T>
  struct Typed {
    const T* term = nullptr;
    int offset = 0;
  };
  template <typename T>
  void Adopt(std::unique_ptr<T> term, Typed<T>* typed);
  void AdoptStandardTerms(const Vehicle& vehicle);
  void AdoptEffectTerm(std::unique_ptr<ForceTerm> term);

  ModelStructure structure_;
  Typed<internal::DragTerm> drag_;
  Typed<internal::ConstantTerm> constant_;
  Typed<internal::ThrustTerm> thrust_;
  Typed<internal::AdvanceLossTerm> advance_;
  Typed<internal::CouplingTerm> coupling_;
  Typed<internal::DriftTerm> drift_;
  std::vector<std::unique_ptr<ForceTerm>> terms_;
  std::vector<int> term_offsets_;
  std::vector<std::string> names_;
  bool needs_aux_ = false;
  int lag_index_ = -1;
  int deadzone_index_ = -1;
  int delay_index_ = -1;
  int thrust_exponent_index_ = -1;
  double thrust_reference_ = 1.0;
  std::vector<Typed<ForceTerm>> others_;  ///< terms of registered effects the loop does not know
};

}  // namespace uuvplan::model
