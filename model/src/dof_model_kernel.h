// DofModel's right-hand side, inline for the simulation loop (simulator.cc) and DofModel
// itself (dof_model.cc): with the terms held by their final type the compiler inlines
// Derivative → TotalForce → each term's Value into the RK4 stages. Model library only.
#pragma once

#include <cmath>

#include "force_terms_impl.h"
#include "uuvplan/model/dof_model.h"

namespace uuvplan::model::internal {

struct DofModelKernel {
  /// The actuator path (effects beyond the papers), evaluated once per input sample (not per RK4
  /// stage: a held input is sampled once per step):
  ///   u0 = sign(phi_n)·max(|phi_n| − d, 0)     dead zone;      ∂u0/∂d = −sign(phi_n) outside it
  ///   u  = u0·r^p,  r = |u0|/u_ref              thrust map;     ∂u/∂u0 = (1 + p)·r^p, ∂u/∂p = u·ln
  ///   r
  static void Actuate(const DofModel& m, const double* theta, InputSample* in) {
    const double phi_n = in->phi_n;
    const int dz = m.deadzone_index_, tm = m.thrust_exponent_index_;
    double u0 = phi_n, du0_dd = 0.0;
    if (dz >= 0) {
      const double excess = std::abs(phi_n) - theta[dz];
      u0 = excess > 0 ? std::copysign(excess, phi_n) : 0.0;
      du0_dd = excess > 0 ? -std::copysign(1.0, phi_n) : 0.0;
    }
    in->u = u0;
    in->du_dd = du0_dd;
    in->du_dp = 0.0;
    if (tm >= 0 && u0 != 0.0) {
      const double ln_r = std::log(std::abs(u0) / m.thrust_reference_);
      const double g = std::exp(theta[tm] * ln_r);
      in->u = u0 * g;
      in->du_dd = (1.0 + theta[tm]) * g * du0_dd;
      in->du_dp = in->u * ln_r;
    }
  }

  static double ActuatorInput(const DofModel& m, double phi_n, const double* theta) {
    InputSample in;
    in.phi_n = phi_n;
    Actuate(m, theta, &in);
    return in.u;
  }

  static InputSample SampleInput(const DofModel& m, double t, const TrialConditions& c,
                                 const double* theta) {
    InputSample in;
    if (c.input) c.input->Sample(t, &in.phi_n, &in.mapping);
    if (m.needs_aux_ && c.aux) c.aux->At(t, &in.velocities);
    Actuate(m, theta, &in);
    return in;
  }

  [[gnu::always_inline]] static TermInputs TermInputsAt(const DofModel& m, double t,
                                                        const double* x, const InputSample& in,
                                                        const TrialConditions& c) {
    TermInputs tc;
    tc.xi = x[1];
    tc.phi = m.has_lag() ? x[2] : in.u;
    tc.mapping = in.mapping;
    tc.t_campaign = c.start_time + t;
    tc.ballast_steps = c.ballast_steps;
    if (m.needs_aux_) tc.velocities = in.velocities;
    return tc;
  }

  [[gnu::noinline]] static double OtherForces(const DofModel& m, const TermInputs& tc,
                                              const double* theta) {
    double f = 0.0;
    for (const auto& typed : m.others_) f += typed.term->Value(tc, theta + typed.offset);
    return f;
  }

  /// kOthers: the model has terms of registered effects (DofModel::has_registered_terms());
  /// without them the simulation loop is instantiated with no call that could clobber memory.
  template <bool kOthers = true>
  [[gnu::always_inline]] static double TotalForce(const DofModel& m, const TermInputs& tc,
                                                  const double* theta) {
    // Summed as a tree, not left to right: the state-dependent terms (drag, advance loss,
    // coupling) then meet the others after two additions instead of five.
    auto value = [&](const auto& typed) {
      return typed.term ? typed.term->Value(tc, theta + typed.offset) : 0.0;
    };
    const double known = (value(m.drag_) + value(m.advance_)) +
                         (value(m.coupling_) + value(m.thrust_)) +
                         (value(m.constant_) + value(m.drift_));
    // Terms of registered effects the loop does not know (virtual calls), out of line.
    if constexpr (kOthers) return m.others_.empty() ? known : known + OtherForces(m, tc, theta);
    return known;
  }

  /// 1/m and 1/T: they do not depend on the state, so the caller computes them once and the
  /// RK4 stages multiply (a division costs ~4× a multiplication in latency).
  struct Inverses {
    double mass = 0.0, lag = 0.0;
  };
  static Inverses Invert(const DofModel& m, const double* theta) {
    return {1.0 / theta[0], m.has_lag() ? 1.0 / theta[m.lag_index_] : 0.0};
  }

  /// dx/dt (dof_model.h): [xi, ΣF/m, (u - phi_a)/T].
  template <bool kOthers = true>
  [[gnu::always_inline]] static void Derivative(const DofModel& m, double t, const double* x,
                                                const InputSample& in, const TrialConditions& c,
                                                const double* theta, const Inverses& inv,
                                                double* dx) {
    DerivativeAt<kOthers>(m, TermInputsAt(m, t, x, in, c), x, in, theta, inv, dx);
  }
  /// The same at a term context already made (a joint model's: the other DOFs' velocities
  /// from its state, multi_dof_kernel.h).
  template <bool kOthers = true>
  [[gnu::always_inline]] static void DerivativeAt(const DofModel& m, const TermInputs& tc,
                                                  const double* x, const InputSample& in,
                                                  const double* theta, const Inverses& inv,
                                                  double* dx) {
    dx[0] = x[1];
    dx[1] = TotalForce<kOthers>(m, tc, theta) * inv.mass;
    if (m.has_lag()) dx[2] = (in.u - x[2]) * inv.lag;
  }

  /// dx/dt with its Jacobians, row-major: A = ∂f/∂x (NX × NX), B = ∂f/∂theta (NX × np); both
  /// fully written. Row 1: ∂(ΣF/m)/∂θ = J_term/m, ∂/∂m = −ΣF/m²; row 2 (lag):
  /// ∂((u − φ_a)/T)/∂T = −(u − φ_a)/T², ∂/∂d = (∂u/∂d)/T.
  template <int NX, bool kOthers = true>
  static void Linearize(const DofModel& m, double t, const double* x, const InputSample& in,
                        const TrialConditions& c, const double* theta, const Inverses& inv,
                        double* dx, double* A, double* B) {
    const int np = m.num_parameters();
    const TermInputs tc = TermInputsAt(m, t, x, in, c);
    for (int i = 0; i < NX * NX; ++i) A[i] = 0.0;
    for (int i = 0; i < NX * np; ++i) B[i] = 0.0;
    double* b1 = B + np;
    double force = 0.0, d_xi = 0.0, d_phi = 0.0;
    auto visit = [&](const auto& typed) {
      if (!typed.term) return;
      const TermPartials p = typed.term->Partials(tc, theta + typed.offset, b1 + typed.offset);
      force += p.value;
      d_xi += p.d_xi;
      d_phi += p.d_phi;
    };
    visit(m.drag_);
    visit(m.constant_);
    visit(m.thrust_);
    visit(m.advance_);
    visit(m.coupling_);
    visit(m.drift_);
    if constexpr (kOthers) {
      for (const auto& typed : m.others_) visit(typed);
    }
    for (int j = 1; j < np; ++j) b1[j] *= inv.mass;
    b1[0] = -force * inv.mass * inv.mass;
    dx[0] = x[1];
    dx[1] = force * inv.mass;
    A[0 * NX + 1] = 1.0;
    A[1 * NX + 1] = d_xi * inv.mass;

    const int dz = m.deadzone_index_, tm = m.thrust_exponent_index_;
    const double u = in.u, du_dd = in.du_dd, du_dp = in.du_dp;
    if constexpr (NX == 3) {
      A[1 * NX + 2] = d_phi * inv.mass;
      A[2 * NX + 2] = -inv.lag;
      dx[2] = (u - x[2]) * inv.lag;
      B[2 * np + m.lag_index_] = -(u - x[2]) * inv.lag * inv.lag;
      if (dz >= 0) B[2 * np + dz] = du_dd * inv.lag;
      if (tm >= 0) B[2 * np + tm] = du_dp * inv.lag;
    } else {
      if (dz >= 0) b1[dz] = d_phi * du_dd * inv.mass;
      if (tm >= 0) b1[tm] = d_phi * du_dp * inv.mass;
    }
  }
};

}  // namespace uuvplan::model::internal
