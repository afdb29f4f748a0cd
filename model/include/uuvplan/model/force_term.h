// A DOF's dynamics is a sum of force terms (contract §Conventions, ref 000 eq. 3):
//
//   m·dxi/dt = Σ_j F_j(xi, phi_a, context; theta_j)
//
// Each term knows its parameters, its value, its partial derivatives (for the forward
// sensitivity equations behind Fisher information and output-error fits) and, where it is
// linear in its parameters, its regressor F_j = h_j·theta_j + h0_j (for least squares).
#pragma once

#include <array>
#include <memory>
#include <string>
#include <vector>

#include "uuvplan/model/dof.h"

namespace uuvplan::model {

/// Everything a force term may look at, at one instant.
struct TermInputs {
  double xi = 0.0;          ///< velocity of the DOF (m/s or rad/s)
  double phi = 0.0;         ///< actuator force phi_a after dead zone and lag (N or N·m)
  int mapping = -1;         ///< vehicle mapping index in force, -1 = none
  double t_campaign = 0.0;  ///< time on the campaign clock (s)
  int ballast_steps = 0;    ///< known ballast steps of the trial
  /// Velocities of all six DOFs, indexed by Index(dof) (others measured or exogenous). The
  /// own DOF's entry is not read (its velocity is xi); filled only when a term needs them.
  std::array<double, kNumDofs> velocities{};
};

/// Partial derivatives of one term at one instant. Layout: J_F_theta[j] = dF/dtheta_j for the
/// term's own parameters, in the order of parameter_names().
struct TermPartials {
  double value = 0.0;
  double d_xi = 0.0;   ///< dF/dxi
  double d_phi = 0.0;  ///< dF/dphi_a
};

class ForceTerm {
 public:
  virtual ~ForceTerm() = default;

  /// Parameter names in the shared vocabulary (parameter.h).
  const std::vector<std::string>& parameter_names() const { return names_; }
  int num_parameters() const { return static_cast<int>(names_.size()); }

  /// F(context; theta), theta pointing at this term's parameters.
  virtual double Value(const TermInputs& c, const double* theta) const = 0;
  /// F and its partials; J_F_theta has num_parameters() entries.
  virtual TermPartials Partials(const TermInputs& c, const double* theta,
                                double* J_F_theta) const = 0;
  /// True when the term reads the other DOFs' velocities (TermInputs::velocities).
  virtual bool NeedsOtherVelocities() const { return false; }
  /// For a term that reads them: adds ∂F/∂(velocity of DOF d) to J_F_v[Index(d)] for every DOF
  /// d but the own one (whose partial is TermPartials::d_xi). A multi-DOF model
  /// (multi_dof_model.h) reads those velocities from its state, so they enter its Jacobian.
  virtual void OtherVelocityPartials(const TermInputs& /*c*/, const double* /*theta*/,
                                     double* /*J_F_v*/) const {}
  /// For terms linear in their parameters: F = Σ h[j]·theta[j] + h0; returns false otherwise.
  virtual bool Regressor(const TermInputs& /*c*/, double* /*h*/, double* /*h0*/) const {
    return false;
  }

 protected:
  explicit ForceTerm(std::vector<std::string> names) : names_(std::move(names)) {}

 private:
  std::vector<std::string> names_;
};

/// Drag -k·xi - kq·xi·|xi| (ref 000 eq. 3), the linear and/or quadratic part; with
/// `asymmetric`, k, kq act for xi >= 0 and k_neg, kq_neg for xi < 0. Parameters in the order
/// k, [k_neg], kq, [kq_neg].
std::unique_ptr<ForceTerm> MakeDragTerm(bool linear, bool quadratic, bool asymmetric);
/// Thrust eta(mu, sign phi)·phi (ref 000 eq. 3): eta = 1 where the mapping works in open
/// water, a parameter "eta.<mapping>.<pos|neg>" where listed in `free_eta`.
std::unique_ptr<ForceTerm> MakeThrustTerm(const std::vector<std::string>& mapping_names,
                                          const std::vector<std::string>& free_eta);
/// Constant force bias + bias_step·ballast_steps: weight - buoyancy, tether, mean disturbance
/// (ref 000 eq. 7) and known ballast steps (ref 000 eq. 20: W + i·ΔW). Either may be off.
std::unique_ptr<ForceTerm> MakeConstantTerm(bool bias, bool ballast);
/// Advance-speed thrust loss -c_a·sqrt(|phi_a|)·xi (ref 000 eq. 5, |n| ∝ sqrt|phi|, v_a = xi).
std::unique_ptr<ForceTerm> MakeAdvanceLossTerm();
/// Coupling Σ c_ab·a·b over velocity-letter pairs "ab" (ref 003 3-DOF model, e.g. surge
/// v·r and r², yaw u·r); parameters "coupling.<ab>" in the order given.
std::unique_ptr<ForceTerm> MakeCouplingTerm(Dof own, const std::vector<std::string>& pairs);
/// Slow thrust drift drift·t_c·phi_a (battery), t_c the campaign clock.
std::unique_ptr<ForceTerm> MakeDriftTerm();

}  // namespace uuvplan::model
