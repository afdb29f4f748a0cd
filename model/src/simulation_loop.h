// The RK4 and forward-sensitivity loop of every model, written once (simulator.h): a System
// gives its state count (kStates when fixed at compile time, else 0; kMaxStates, the size of
// its state arrays; num_states()), num_parameters(), its input samples
// (Input, Sample, Refresh, held, Breakpoints), Derivative and Linearize. simulator.cc
// instantiates it for a DofModel, multi_dof_kernel.cc for the joint model (one translation unit
// each, so that the 1-DOF loop is inlined as before). Model library only.
#pragma once

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "uuvplan/model/simulator.h"
#include "uuvplan/model/util/checked_count.h"

namespace uuvplan::model::internal {

// Inputs are right-continuous at breakpoints; a step [a, b] ending at b must see the left
// limit, so stage times are held just below the interval's end — but never before its start
// (a step shorter than that margin, e.g. between an output time and a breakpoint a rounding
// error apart, samples at a).
inline double Inside(double t, double a, double b) {
  return std::max(a, std::min(t, b - 1e-12 * std::max(1.0, b)));
}

// Throws std::invalid_argument on a step <= 0 or unsorted or negative output times, and
// InputError when the simulation would take more than limits::kMaxSimulationSteps steps.
inline void CheckOutputTimes(TimesView output_times, const SimulationOptions& options) {
  if (!(options.step_s > 0)) throw std::invalid_argument("SimulationOptions::step_s must be > 0");
  if (!std::is_sorted(output_times.begin(), output_times.end()) ||
      (!output_times.empty() && output_times.front() < 0)) {
    throw std::invalid_argument("Simulate: output times must be sorted and >= 0");
  }
  if (!output_times.empty()) {
    CheckedCount(output_times.back() / options.step_s, "simulation (duration / integration step)",
                 limits::kMaxSimulationSteps, "a shorter trial or a longer integration step");
  }
}

// The output trajectory, sized: x for every output time, S (with sensitivities) in place
// (CheckOutputTimes first).
inline Trajectory SizedOutput(int nx, int np, TimesView output_times,
                              const SimulationOptions& options) {
  CheckOutputTimes(output_times, options);
  Trajectory out;
  out.t = output_times.ToVector();
  out.x.resize(output_times.size(), nx);
  if (options.sensitivities) {
    out.S.resize(nx);  // sized in place: copying a prototype would touch 3 × n_out × np doubles
    for (auto& s : out.S) s.resize(output_times.size(), np);
  }
  return out;
}

// The state count of `sys`: a compile-time constant where the system has one, so that the state
// loops unroll.
template <class System>
[[gnu::always_inline]] inline int StatesOf(const System& sys) {
  return System::kStates > 0 ? System::kStates : sys.num_states();
}

// K = A·St + B with St = S + c·K_prev (c = 0 for the first stage). S, St, K are row-major
// nx × np (row s: the sensitivities of state s); A (nx × nx) and B (nx × nb) as the kernel
// writes them, nb <= np: the columns past nb (an initial state's) have no B; kNx: nx when known
// at compile time (0: the argument).
template <int kNx>
[[gnu::always_inline]] inline void SensitivitySlope(int n_states, const double* A, const double* B,
                                                    int nb, const double* S, const double* k_prev,
                                                    double c_prev, int np, double* St, double* K) {
  const int nx = kNx > 0 ? kNx : n_states;
  const int ns = nx * np;
  for (int j = 0; j < ns; ++j) St[j] = k_prev ? S[j] + c_prev * k_prev[j] : S[j];
  for (int r = 0; r < nx; ++r) {
    double* Kr = K + r * np;
    const double* Br = B + r * nb;
    for (int j = 0; j < np; ++j) {
      double v = j < nb ? Br[j] : 0.0;
      for (int q = 0; q < nx; ++q) v += A[r * nx + q] * St[q * np + j];
      Kr[j] = v;
    }
  }
}

// A bound on the spectral radius of A (nx × nx, row-major), the model's fastest local rate
// (1/s): a DOF model's Jacobian is triangular in (actuator, velocity, position) — no force
// reads the position and the lag state reads only the command — so its eigenvalues are its
// diagonal; a force that reads the position adds the pair's natural frequency √|A_ij·A_ji|
// (the 2 × 2 block's eigenvalues (a ± √(a² + 4·A_ij·A_ji))/2).
inline double FastestRate(int nx, const double* A) {
  double diagonal = 0.0, pair = 0.0;
  for (int i = 0; i < nx; ++i) {
    diagonal = std::max(diagonal, std::abs(A[i * nx + i]));
    for (int j = i + 1; j < nx; ++j) {
      pair = std::max(pair, std::sqrt(std::abs(A[i * nx + j] * A[j * nx + i])));
    }
  }
  return diagonal + pair;
}

// GCC cannot see that a DofModel of three states has a thruster lag (DofModel::has_lag), so
// that the kernel writes every state's slope: its -Wmaybe-uninitialized on the stage arrays
// below is a false positive.
#if defined(__GNUC__) && !defined(__clang__)  // clang has no -Wmaybe-uninitialized
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#endif

// One classical RK4 step on x: x += h/6·(k1 + 2k2 + 2k3 + k4), the input sampled at the
// step's start, middle and end (in_a, in_m, in_e).
template <class System>
[[gnu::always_inline]] inline void StateStep(const System& sys, double ta, double tm, double te,
                                             double h, const typename System::Input& in_a,
                                             const typename System::Input& in_m,
                                             const typename System::Input& in_e, double* x) {
  constexpr int kMax = System::kMaxStates;
  const int nx = StatesOf(sys);
  double k1[kMax], k2[kMax], k3[kMax], k4[kMax], xt[kMax];
  sys.Derivative(ta, x, in_a, k1);
  for (int s = 0; s < nx; ++s) xt[s] = x[s] + 0.5 * h * k1[s];
  sys.Derivative(tm, xt, in_m, k2);
  for (int s = 0; s < nx; ++s) xt[s] = x[s] + 0.5 * h * k2[s];
  sys.Derivative(tm, xt, in_m, k3);
  for (int s = 0; s < nx; ++s) xt[s] = x[s] + h * k3[s];
  sys.Derivative(te, xt, in_e, k4);
  for (int s = 0; s < nx; ++s) x[s] += (h / 6.0) * (k1[s] + 2 * k2[s] + 2 * k3[s] + k4[s]);
}

// One RK4 step on x and on S = ∂x/∂theta by the forward sensitivity equations dS/dt = A·S + B
// (A = ∂f/∂x, B = ∂f/∂theta), with StateStep's stages, each linearised: S, the stage argument St,
// the stage slopes K1–K4 (SensitivitySlope), B and A are the caller's buffers. S has np
// columns, the model's parameters and then any initial state's (SensitivitySlope).
template <class System>
[[gnu::always_inline]] inline void SensitivityStep(
    const System& sys, double ta, double tm, double te, double h,
    const typename System::Input& in_a, const typename System::Input& in_m,
    const typename System::Input& in_e, double* x, int np, double* S, double* St, double* K1,
    double* K2, double* K3, double* K4, double* B, double* A) {
  constexpr int kMax = System::kMaxStates;
  const int nx = StatesOf(sys), nb = sys.num_parameters(), ns = nx * np;
  double k1[kMax], k2[kMax], k3[kMax], k4[kMax], xt[kMax];
  sys.Linearize(ta, x, in_a, k1, A, B);
  SensitivitySlope<System::kStates>(nx, A, B, nb, S, nullptr, 0.0, np, St, K1);
  for (int s = 0; s < nx; ++s) xt[s] = x[s] + 0.5 * h * k1[s];
  sys.Linearize(tm, xt, in_m, k2, A, B);
  SensitivitySlope<System::kStates>(nx, A, B, nb, S, K1, 0.5 * h, np, St, K2);
  for (int s = 0; s < nx; ++s) xt[s] = x[s] + 0.5 * h * k2[s];
  sys.Linearize(tm, xt, in_m, k3, A, B);
  SensitivitySlope<System::kStates>(nx, A, B, nb, S, K2, 0.5 * h, np, St, K3);
  for (int s = 0; s < nx; ++s) xt[s] = x[s] + h * k3[s];
  sys.Linearize(te, xt, in_e, k4, A, B);
  SensitivitySlope<System::kStates>(nx, A, B, nb, S, K3, h, np, St, K4);
  for (int j = 0; j < ns; ++j) S[j] += (h / 6.0) * (K1[j] + 2.0 * K2[j] + 2.0 * K3[j] + K4[j]);
  for (int s = 0; s < nx; ++s) x[s] += (h / 6.0) * (k1[s] + 2 * k2[s] + 2 * k3[s] + k4[s]);
}

#if defined(__GNUC__) && !defined(__clang__)
#pragma GCC diagnostic pop
#endif

// Hands the outputs due by time t (output_times[i] - shift <= t) to `visit` or stores them in
// `out`; returns the index of the next output.
[[gnu::always_inline]] inline std::size_t Record(TimesView output_times, double shift, double t,
                                                 std::size_t next_out, const double* x,
                                                 const double* S, int nx, int np,
                                                 const OutputVisitor* visit, Trajectory* out) {
  for (; next_out < output_times.size() && output_times[next_out] - shift <= t; ++next_out) {
    if (visit) {
      (*visit)(next_out, x, S);
      continue;
    }
    for (int s = 0; s < nx; ++s) out->x(next_out, s) = x[s];
    for (int s = 0; s < (S ? nx : 0); ++s) {
      for (int j = 0; j < np; ++j) out->S[s](next_out, j) = S[s * np + j];
    }
  }
  return next_out;
}

// Integrates `sys` from x0 at t = 0 and records the state at output_times[i] - shift (the state
// x0 for shifted times before 0), or hands it to `visit` (nothing stored). Every RK4 step ends
// at the input's breakpoints and at the (shifted) output times, which are merged on the fly;
// the steps between two such ends are equal, at most step_s, and with
// options.time_constant_fraction c at most c/FastestRate of the last linearisation.
// The one loop of every model (DofSystem, internal::JointSystem); its buffers are local (a
// class holding them was 8% slower in the planner: stores through its pointers forced reloads
// of every member).
template <class System>
Trajectory IntegrateSystem(const System& sys, TimesView output_times, double shift,
                           const SimulationOptions& options, const Eigen::VectorXd* x0,
                           const OutputVisitor* visit) {
  const bool sens = options.sensitivities;
  const bool velocity_column = sens && options.initial_velocity_column;
  const int nx = StatesOf(sys), nb = sys.num_parameters(), np = nb + (velocity_column ? 1 : 0);
  Trajectory out;
  if (visit) {
    CheckOutputTimes(output_times, options);
  } else {
    out = SizedOutput(nx, np, output_times, options);
  }
  const std::size_t n_out = output_times.size();
  double x[System::kMaxStates] = {};
  for (int s = 0; x0 && s < nx && s < x0->size(); ++s) x[s] = (*x0)[s];
  const int ns = sens ? nx * np : 0;
  std::vector<double> S(ns, 0.0), St(ns), K1(ns), K2(ns), K3(ns), K4(ns), B(sens ? nx * nb : 0);
  if (velocity_column) S[1 * np + nb] = 1.0;  // ∂ξ(0)/∂ξ0 (state 1: the velocity)
  double A[System::kMaxStates * System::kMaxStates];
  const double* S_out = sens ? S.data() : nullptr;
  std::size_t next_out = Record(output_times, shift, 0.0, 0, x, S_out, nx, np, visit, &out);
  const auto breaks = sys.Breakpoints();  // a view of the input's, or the joint system's merge
  std::size_t next_break = 0;
  // The input is sampled once per stage time; a step's end sample starts the next step
  // unless the step ended at a breakpoint (where the input jumps). A piecewise-constant input
  // does not change inside a step (steps end at its breakpoints): only what Refresh moves is
  // sampled at the inner stage times.
  const bool held = sys.held();
  double t = 0.0;
  typename System::Input in_a = sys.Sample(0.0);
  const bool local_step = sens && options.time_constant_fraction > 0;
  double rate = 0.0;  // FastestRate at the last linearisation (local_step)
  if (local_step) {
    double dx[System::kMaxStates];
    sys.Linearize(0.0, x, in_a, dx, A, B.data());
    rate = FastestRate(nx, A);
  }
  while (next_out < n_out) {
    while (next_break < breaks.size() && breaks[next_break] <= t) ++next_break;
    double b = output_times[next_out] - shift;
    if (next_break < breaks.size()) b = std::min(b, breaks[next_break]);
    const double longest = local_step && rate > 0
                               ? std::min(options.step_s, options.time_constant_fraction / rate)
                               : options.step_s;
    // One step when the interval fits (a log's force changing at every sample: every interval).
    const int n =
        b - t <= longest
            ? 1
            : std::max(1, CheckedCount<int>((b - t) / longest, "simulation step count",
                                            limits::kMaxSimulationSteps, "a longer step"));
    const double h = (b - t) / n;
    for (int k = 0; k < n; ++k) {
      const double ta = t + k * h;
      const double tm = Inside(ta + 0.5 * h, ta, b), te = Inside(ta + h, ta, b);
      typename System::Input in_m = held ? in_a : sys.Sample(tm);
      typename System::Input in_e = held ? in_a : sys.Sample(te);
      if (held) {
        sys.Refresh(tm, &in_m);
        sys.Refresh(te, &in_e);
      }
      if (sens) {
        SensitivityStep(sys, ta, tm, te, h, in_a, in_m, in_e, x, np, S.data(), St.data(), K1.data(),
                        K2.data(), K3.data(), K4.data(), B.data(), A);
      } else {
        StateStep(sys, ta, tm, te, h, in_a, in_m, in_e, x);
      }
      in_a = in_e;
    }
    if (local_step) rate = FastestRate(nx, A);
    t = b;
    if (next_break < breaks.size() && breaks[next_break] <= t) in_a = sys.Sample(t);  // right limit
    next_out = Record(output_times, shift, t, next_out, x, S_out, nx, np, visit, &out);
  }
  return out;
}

}  // namespace uuvplan::model::internal
