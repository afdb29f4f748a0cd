// Several DOFs' models as one (ref 003's 3-DOF horizontal model; ref 000 eq. 1's 6-DOF model
// is the same frame with more DOFs and kinematics). Each DOF's dynamics is its DofModel — the
// same ForceTerms, actuator path and θ layout as a 1-DOF model — and the joint model adds what
// joins them:
//
//  - the state: the DOFs' states stacked, block i = [χ_i, ξ_i(, φ_a,i)] from state_offset(i);
//  - motion: a term that reads another DOF's velocity (the coupling term c_ab·a·b,
//    TermInputs::velocities) reads it from the joint state, so that its partial ∂F/∂ξ_j
//    (ForceTerm::OtherVelocityPartials) enters the Jacobian A;
//  - kinematics: χ̇_i = ξ_i, except that with surge, sway and yaw together the three positions
//    are the pose in the pool frame, η̇ = J(ψ)·ν (ref 003, J₁ reduced to the plane):
//      ẋ = u·cos ψ − v·sin ψ,   ẏ = u·sin ψ + v·cos ψ,   ψ̇ = r;
//  - parameters: one global θ, and each DOF's θ_i a linear map of it, θ_i = T_i·θ, so that a
//    coefficient several equations share (an inertia in the Coriolis terms) is one parameter:
//    ∂f/∂θ = Σ_i ∂f/∂θ_i·T_i. θ lists, DOF by DOF, every local parameter no tie defines, named
//    "<dof>.<parameter>" ("sway.kq"); a tied local parameter is Σ coefficient·θ[global].
//
// A model of one DOF without ties is that DofModel (MultiDofModel.OneDofIsTheDofModel). The
// simulator (simulator.h) integrates both with one RK4 and forward-sensitivity loop.
#pragma once

#include <Eigen/Dense>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "uuvplan/model/dof_model.h"

namespace uuvplan::model {

/// A local parameter defined by global ones: θ_dof[parameter] = Σ coefficient·θ[name].
struct ParameterTie {
  Dof dof = Dof::kSurge;
  std::string parameter;                              ///< local name, e.g. "coupling.uv"
  std::vector<std::pair<std::string, double>> terms;  ///< e.g. {{"surge.m", 1}, {"sway.m", -1}}
};

/// One non-zero entry of T_i: local parameter `local` of DOF i gets coefficient·θ[global].
struct TieEntry {
  int local = 0;
  int global = 0;
  double coefficient = 1.0;
};

/// What drives a joint trial: per DOF of the model (its index) the commanded force, or null
/// for a DOF the trial does not push.
struct JointConditions {
  std::vector<const Excitation*> inputs;
  double start_time = 0.0;  ///< campaign clock at t = 0 (s)
};

class MultiDofModel {
 public:
  /// One DofModel per structure (distinct DOFs, in the order given); InputError when a tie
  /// names a DOF, a local or a global parameter the model does not have.
  MultiDofModel(const Vehicle& vehicle, const std::vector<ModelStructure>& structures,
                const std::vector<ParameterTie>& ties = {});

  int num_dofs() const { return static_cast<int>(dofs_.size()); }
  Dof dof(int i) const { return dofs_[i].dof(); }
  /// Index of `dof` among the model's DOFs, or -1.
  int DofIndex(Dof dof) const;
  const DofModel& dof_model(int i) const { return dofs_[i]; }
  /// First state of DOF i's block (its position; the velocity follows).
  int state_offset(int i) const { return offsets_[i]; }
  int num_states() const { return offsets_.back(); }
  /// Whether the positions of surge, sway and yaw are the pose in the pool frame (above).
  bool planar() const { return planar_; }
  /// DOF i's position by name: the pose's x, y and heading in the planar model, else the DOF.
  std::string PositionName(int i) const;

  const std::vector<std::string>& parameter_names() const { return names_; }
  int num_parameters() const { return static_cast<int>(names_.size()); }
  /// Index of a global parameter ("yaw.kq"), or -1.
  int ParameterIndex(std::string_view name) const;
  /// The DOF a global parameter belongs to and its local name.
  std::pair<Dof, std::string> LocalName(int j) const;
  /// Unit of θ_j (parameter.h: its local name's family, for its DOF).
  std::string ParameterUnit(int j) const;
  /// T_i as its non-zero entries.
  const std::vector<TieEntry>& tie(int i) const { return ties_[i]; }
  /// θ_i = T_i·θ.
  Eigen::VectorXd LocalTheta(int i, const Eigen::VectorXd& theta) const;
  /// θ from each DOF's named local values (a truth's params); a name missing takes
  /// `fallback`'s value, or InputError naming the DOF and the parameter (DofModel::Theta).
  Eigen::VectorXd Theta(const std::map<Dof, std::map<std::string, double>>& values,
                        const std::map<std::string, double>* fallback = nullptr) const;
  /// "" when every parameter is admissible in its family (parameter.h), else the first that is
  /// not: "sway.kq = -3 N·s²/m² is not …".
  std::string Inadmissible(const Eigen::VectorXd& theta) const;

  /// DOF i's equation linear in θ (ref 003's H matrix, generalised): given the velocities ν of
  /// the model's DOFs (by index),  m_i·ξ̇_i + r_i(ν)·θ = φ_i  with r_i = −Σ_j h_j(ν)·T_i, h_j
  /// the regressor of DOF i's force term j (force_term.h) at φ = 0, so that the thrust (η = 1)
  /// is the right-hand side; m_i's own entry is 0. For terms linear in θ and free of φ.
  Eigen::RowVectorXd EquationRegressor(int i, const Eigen::Ref<const Eigen::RowVectorXd>& nu) const;

  /// dx/dt of the joint state at time t.
  void Derivative(double t, const double* x, const JointConditions& c, const Eigen::VectorXd& theta,
                  double* dx) const;
  /// dx/dt and its Jacobians A = ∂f/∂x (nx × nx) and B = ∂f/∂θ (nx × np, global θ).
  void Linearize(double t, const double* x, const JointConditions& c, const Eigen::VectorXd& theta,
                 double* dx, Eigen::Ref<Eigen::MatrixXd> A, Eigen::Ref<Eigen::MatrixXd> B) const;

 private:
  void AddTies(const std::vector<ParameterTie>& ties);

  std::vector<DofModel> dofs_;
  std::vector<int> offsets_;                 ///< state offsets, then the number of states
  std::vector<std::string> names_;           ///< global θ
  std::vector<std::pair<int, int>> owner_;   ///< global j -> (DOF index, local index)
  std::vector<std::vector<TieEntry>> ties_;  ///< T_i
  bool planar_ = false;
};

}  // namespace uuvplan::model
