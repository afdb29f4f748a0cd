#include "uuvplan/model/simulator.h"

#include <algorithm>
#include <cmath>
#include <type_traits>
#include <stdexcept>

#include "dof_model_kernel.h"
#include "uuvplan/model/util/checked_count.h"

namespace uuvplan::model {
namespace {

using Kernel = internal::DofModelKernel;

// Inputs are right-continuous at breakpoints; a step [a, b] ending at b must see the left
// limit, so stage times are held just below the interval's end — but never before its start
// (a step shorter than that margin, e.g. between an output time and a breakpoint a rounding
// error apart, samples at a).
inline double Inside(double t, double a, double b) {
  return std::max(a, std::min(t, b - 1e-12 * std::max(1.0, b)));
}

// Throws std::invalid_argument on a step <= 0 or unsorted or negative output times, and
// InputError when the simulation would take more than limits::kMaxSimulationSteps steps.
void CheckOutputTimes(TimesView output_times, const SimulationOptions& options) {
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
Trajectory SizedOutput(int nx, int np, TimesView output_times, const SimulationOptions& options) {
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

// K = A·St + B with St = S + c·K_prev (c = 0 for the first stage). S, St, K are row-major
// NX × np (row s: the sensitivities of state s); A (NX × NX) and B (NX × np) as the kernel
// writes them.
template <int NX>
__attribute__((always_inline)) inline void SensitivitySlope(const double* A, const double* B, const double* S,
                             const double* k_prev, double c_prev, int np, double* St,
                             double* K) {
  const int ns = NX * np;
  for (int j = 0; j < ns; ++j) St[j] = k_prev ? S[j] + c_prev * k_prev[j] : S[j];
  for (int r = 0; r < NX; ++r) {
    double* Kr = K + r * np;
    const double* Br = B + r * np;
    for (int j = 0; j < np; ++j) {
      double v = Br[j];
      for (int q = 0; q < NX; ++q) v += A[r * NX + q] * St[q * np + j];
      Kr[j] = v;
    }
  }
}

// Integrates from x0 at t = 0 and records the state at output_times[i] - shift (the state x0
// for shifted times before 0), or hands it to `visit` (nothing stored). Every RK4 step ends at the
// input's breakpoints and at the (shifted) output times, which are merged on the fly. NX = number
// of states (2, or 3 with thruster lag), a template parameter so that the state loops unroll. The
// hot loop keeps its buffers local (a class holding them was 8% slower in the planner: stores
// through its pointers forced reloads of every member).
template <int NX, bool kOthers>
Trajectory IntegrateN(const DofModel& model, const Eigen::VectorXd& theta, const TrialConditions& c,
                      TimesView output_times, double shift, const SimulationOptions& options,
                      const Eigen::VectorXd* x0, const OutputVisitor* visit) {
  constexpr int nx = NX;
  const int np = model.num_parameters();
  Trajectory out;
  if (visit) {
    CheckOutputTimes(output_times, options);
  } else {
    out = SizedOutput(nx, np, output_times, options);
  }
  const double* th = theta.data();
  const Kernel::Inverses inv = Kernel::Invert(model, th);
  const bool sens = options.sensitivities;
  const std::size_t n_out = output_times.size();
  double x[3] = {0, 0, 0};
  if (x0) {
    for (int s = 0; s < nx && s < x0->size(); ++s) x[s] = (*x0)[s];
  }
  // S = ∂x/∂theta with the RK4 stage slopes K and the stage argument St (SensitivitySlope).
  const int ns = sens ? nx * np : 0;
  std::vector<double> S(ns, 0.0), St(ns), K1(ns), K2(ns), K3(ns), K4(ns), B(ns);
  double A[NX * NX];
  std::size_t next_out = 0;
  auto record = [&](double t) {
    for (; next_out < n_out && output_times[next_out] - shift <= t; ++next_out) {
      if (visit) {
        (*visit)(next_out, x, sens ? S.data() : nullptr);
        continue;
      }
      for (int s = 0; s < nx; ++s) out.x(next_out, s) = x[s];
      for (int s = 0; s < (sens ? nx : 0); ++s) {
        for (int j = 0; j < np; ++j) out.S[s](next_out, j) = S[s * np + j];
      }
    }
  };
  record(0.0);
  std::vector<double> breaks = c.input ? c.input->Breakpoints() : std::vector<double>{};
  std::sort(breaks.begin(), breaks.end());
  std::size_t next_break = 0;
  // The input is sampled once per stage time; a step's end sample starts the next step
  // unless the step ended at a breakpoint (where the input jumps). A piecewise-constant input
  // does not change inside a step (steps end at its breakpoints): only the other DOFs'
  // velocities are sampled at the inner stage times.
  const bool held = c.input && c.input->piecewise_constant();
  double t = 0.0;
  InputSample in_a = model.SampleInput(0.0, c, th);
  while (next_out < n_out) {
    while (next_break < breaks.size() && breaks[next_break] <= t) ++next_break;
    double b = output_times[next_out] - shift;
    if (next_break < breaks.size()) b = std::min(b, breaks[next_break]);
    const int n = std::max(1, CheckedCount<int>((b - t) / options.step_s, "simulation step count",
                                                limits::kMaxSimulationSteps, "a longer step"));
    const double h = (b - t) / n;
    for (int k = 0; k < n; ++k) {
      const double ta = t + k * h;
      const double tm = Inside(ta + 0.5 * h, ta, b), te = Inside(ta + h, ta, b);
      InputSample in_m = in_a, in_e = in_a;
      if (!held) {
        in_m = Kernel::SampleInput(model, tm, c, th);
        in_e = Kernel::SampleInput(model, te, c, th);
      } else if (c.aux && model.needs_aux()) {
        c.aux->At(tm, &in_m.velocities);
        c.aux->At(te, &in_e.velocities);
      }
      double k1[3], k2[3], k3[3], k4[3], xt[3];
      // Classical RK4 on x (and on S with the same stages): x += h/6·(k1 + 2k2 + 2k3 + k4).
      // With S: dS/dt = A·S + B (forward sensitivity equations), A = ∂f/∂x, B = ∂f/∂theta.
      if (!sens) {
        Kernel::Derivative<kOthers>(model, ta, x, in_a, c, th, inv, k1);
        for (int s = 0; s < nx; ++s) xt[s] = x[s] + 0.5 * h * k1[s];
        Kernel::Derivative<kOthers>(model, tm, xt, in_m, c, th, inv, k2);
        for (int s = 0; s < nx; ++s) xt[s] = x[s] + 0.5 * h * k2[s];
        Kernel::Derivative<kOthers>(model, tm, xt, in_m, c, th, inv, k3);
        for (int s = 0; s < nx; ++s) xt[s] = x[s] + h * k3[s];
        Kernel::Derivative<kOthers>(model, te, xt, in_e, c, th, inv, k4);
      } else {
        double* Bp = B.data();
        Kernel::Linearize<NX, kOthers>(model, ta, x, in_a, c, th, inv, k1, A, Bp);
        SensitivitySlope<NX>(A, Bp, S.data(), nullptr, 0.0, np, St.data(), K1.data());
        for (int s = 0; s < nx; ++s) xt[s] = x[s] + 0.5 * h * k1[s];
        Kernel::Linearize<NX, kOthers>(model, tm, xt, in_m, c, th, inv, k2, A, Bp);
        SensitivitySlope<NX>(A, Bp, S.data(), K1.data(), 0.5 * h, np, St.data(), K2.data());
        for (int s = 0; s < nx; ++s) xt[s] = x[s] + 0.5 * h * k2[s];
        Kernel::Linearize<NX, kOthers>(model, tm, xt, in_m, c, th, inv, k3, A, Bp);
        SensitivitySlope<NX>(A, Bp, S.data(), K2.data(), 0.5 * h, np, St.data(), K3.data());
        for (int s = 0; s < nx; ++s) xt[s] = x[s] + h * k3[s];
        Kernel::Linearize<NX, kOthers>(model, te, xt, in_e, c, th, inv, k4, A, Bp);
        SensitivitySlope<NX>(A, Bp, S.data(), K3.data(), h, np, St.data(), K4.data());
      }
      for (int j = 0; j < ns; ++j) S[j] += (h / 6.0) * (K1[j] + 2.0 * K2[j] + 2.0 * K3[j] + K4[j]);
      for (int s = 0; s < nx; ++s) x[s] += (h / 6.0) * (k1[s] + 2 * k2[s] + 2 * k3[s] + k4[s]);
      in_a = in_e;
    }
    t = b;
    if (next_break < breaks.size() && breaks[next_break] <= t) {
      in_a = model.SampleInput(t, c, th);  // right limit after a jump
    }
    record(t);
  }
  return out;
}

Trajectory Integrate(const DofModel& model, const Eigen::VectorXd& theta, const TrialConditions& c,
                     TimesView output_times, double shift, const SimulationOptions& options,
                     const Eigen::VectorXd* x0, const OutputVisitor* visit = nullptr) {
  const auto run = [&](auto nx, auto others) {
    return IntegrateN<decltype(nx)::value, decltype(others)::value>(model, theta, c, output_times,
                                                                    shift, options, x0, visit);
  };
  using Lag = std::integral_constant<int, 3>;
  using NoLag = std::integral_constant<int, 2>;
  using Others = std::true_type;
  using NoOthers = std::false_type;
  if (model.has_registered_terms()) {
    return model.num_states() == 3 ? run(Lag{}, Others{}) : run(NoLag{}, Others{});
  }
  return model.num_states() == 3 ? run(Lag{}, NoOthers{}) : run(NoLag{}, NoOthers{});
}

}  // namespace

Trajectory Simulate(const DofModel& model, const Eigen::VectorXd& theta, const TrialConditions& c,
                    TimesView output_times, const SimulationOptions& options,
                    const Eigen::VectorXd* x0) {
  return Integrate(model, theta, c, output_times, 0.0, options, x0);
}

void SimulateVisiting(const DofModel& model, const Eigen::VectorXd& theta, const TrialConditions& c,
                      TimesView output_times, const SimulationOptions& options,
                      const Eigen::VectorXd* x0, Seen seen, const OutputVisitor& visit) {
  const int di = seen == Seen::kBySensors ? model.sensor_delay_index() : -1;
  if (options.sensitivities && di >= 0) {
    throw std::invalid_argument(
        "SimulateVisiting: no sensitivity to a sensor delay (SimulateMeasured has it)");
  }
  Integrate(model, theta, c, output_times, di >= 0 ? theta[di] : 0.0, options, x0, &visit);
}

Trajectory SimulateMeasured(const DofModel& model, const Eigen::VectorXd& theta,
                            const TrialConditions& c, TimesView times,
                            const SimulationOptions& options, const Eigen::VectorXd* x0) {
  const int di = model.sensor_delay_index();
  const double tau = di >= 0 ? theta[di] : 0.0;
  // y(t) = x(t - tau); before the trial starts the sensors see the initial state.
  Trajectory out = Integrate(model, theta, c, times, tau, options, x0);
  if (options.sensitivities && di >= 0) {
    double dx[3];
    double xs[3] = {0, 0, 0};
    for (std::size_t i = 0; i < times.size(); ++i) {
      const double ts = times[i] - tau;
      if (ts < 0) {
        out.S[0](i, di) = out.S[1](i, di) = 0.0;
        continue;
      }
      for (int s = 0; s < model.num_states(); ++s) xs[s] = out.x(i, s);
      model.Derivative(ts, xs, c, theta.data(), dx);
      out.S[0](i, di) = -dx[0];  // ∂chi(t - tau)/∂tau = -dchi/dt
      out.S[1](i, di) = -dx[1];
    }
  }
  return out;
}

}  // namespace uuvplan::model
