#include "uuvplan/model/simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace uuvplan::model {
namespace {

// Inputs are right-continuous at breakpoints; a step ending at b must see the left limit, so
// stage times are held just below the interval's end.
inline double Inside(double t, double b) { return std::min(t, b - 1e-12 * std::max(1.0, b)); }

// Integrates from x0 at t = 0 and records the state at output_times[i] - shift (the state x0
// for shifted times before 0). Every RK4 step ends at the input's breakpoints and at the
// (shifted) output times, which are merged on the fly.
Trajectory Integrate(const DofModel& model, const Eigen::VectorXd& theta,
                     const TrialConditions& c, const std::vector<double>& output_times,
                     double shift, const SimulationOptions& options, const Eigen::VectorXd* x0) {
  if (!(options.step_s > 0)) throw std::invalid_argument("SimulationOptions::step_s must be > 0");
  if (!std::is_sorted(output_times.begin(), output_times.end()) ||
      (!output_times.empty() && output_times.front() < 0)) {
    throw std::invalid_argument("Simulate: output times must be sorted and >= 0");
  }
  const int nx = model.num_states();
  const int np = model.num_parameters();
  const double* th = theta.data();
  const bool sens = options.sensitivities;
  const std::size_t n_out = output_times.size();

  Trajectory out;
  out.t = output_times;
  out.x.resize(n_out, nx);
  if (sens) out.S.assign(nx, Eigen::MatrixXd(n_out, np));

  double x[3] = {0, 0, 0};
  if (x0) {
    for (int s = 0; s < nx && s < x0->size(); ++s) x[s] = (*x0)[s];
  }
  // S is stored transposed (np × nx) so that recording a row of out.S is a contiguous read.
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(nx, np);
  Eigen::MatrixXd A(nx, nx), B(nx, np), K1(nx, np), K2(nx, np), K3(nx, np), K4(nx, np),
      Stmp(nx, np);

  std::size_t next_out = 0;
  auto record = [&](double t) {
    while (next_out < n_out && output_times[next_out] - shift <= t) {
      for (int s = 0; s < nx; ++s) out.x(next_out, s) = x[s];
      if (sens) {
        for (int s = 0; s < nx; ++s) out.S[s].row(next_out) = S.row(s);
      }
      ++next_out;
    }
  };
  record(0.0);

  std::vector<double> breaks = c.input ? c.input->Breakpoints() : std::vector<double>{};
  std::sort(breaks.begin(), breaks.end());
  std::size_t next_break = 0;

  // The input is sampled once per stage time; a step's end sample starts the next step
  // unless the step ended at a breakpoint (where the input jumps).
  double t = 0.0;
  InputSample in_a = model.SampleInput(0.0, c);
  while (next_out < n_out) {
    while (next_break < breaks.size() && breaks[next_break] <= t) ++next_break;
    double b = output_times[next_out] - shift;
    if (next_break < breaks.size()) b = std::min(b, breaks[next_break]);
    const int n = std::max(1, static_cast<int>(std::ceil((b - t) / options.step_s - 1e-9)));
    const double h = (b - t) / n;
    for (int k = 0; k < n; ++k) {
      const double ta = t + k * h;
      const double tm = Inside(ta + 0.5 * h, b), te = Inside(ta + h, b);
      const InputSample in_m = model.SampleInput(tm, c);
      const InputSample in_e = model.SampleInput(te, c);
      double k1[3], k2[3], k3[3], k4[3], xt[3];
      // Classical RK4 on x (and on S with the same stages): x += h/6·(k1 + 2k2 + 2k3 + k4).
      if (!sens) {
        model.Derivative(ta, x, in_a, c, th, k1);
        for (int s = 0; s < nx; ++s) xt[s] = x[s] + 0.5 * h * k1[s];
        model.Derivative(tm, xt, in_m, c, th, k2);
        for (int s = 0; s < nx; ++s) xt[s] = x[s] + 0.5 * h * k2[s];
        model.Derivative(tm, xt, in_m, c, th, k3);
        for (int s = 0; s < nx; ++s) xt[s] = x[s] + h * k3[s];
        model.Derivative(te, xt, in_e, c, th, k4);
      } else {
        // dS/dt = A·S + B (forward sensitivity equations), A = ∂f/∂x, B = ∂f/∂theta.
        model.Linearize(ta, x, in_a, c, th, k1, A, B);
        K1.noalias() = A.lazyProduct(S);  // tiny: no GEMM blocking
        K1 += B;
        for (int s = 0; s < nx; ++s) xt[s] = x[s] + 0.5 * h * k1[s];
        model.Linearize(tm, xt, in_m, c, th, k2, A, B);
        Stmp = S + 0.5 * h * K1;
        K2.noalias() = A.lazyProduct(Stmp);
        K2 += B;
        for (int s = 0; s < nx; ++s) xt[s] = x[s] + 0.5 * h * k2[s];
        model.Linearize(tm, xt, in_m, c, th, k3, A, B);
        Stmp = S + 0.5 * h * K2;
        K3.noalias() = A.lazyProduct(Stmp);
        K3 += B;
        for (int s = 0; s < nx; ++s) xt[s] = x[s] + h * k3[s];
        model.Linearize(te, xt, in_e, c, th, k4, A, B);
        Stmp = S + h * K3;
        K4.noalias() = A.lazyProduct(Stmp);
        K4 += B;
        S += (h / 6.0) * (K1 + 2.0 * K2 + 2.0 * K3 + K4);
      }
      for (int s = 0; s < nx; ++s) x[s] += (h / 6.0) * (k1[s] + 2 * k2[s] + 2 * k3[s] + k4[s]);
      in_a = in_e;
    }
    t = b;
    if (next_break < breaks.size() && breaks[next_break] <= t) {
      in_a = model.SampleInput(t, c);  // right limit after a jump
    }
    record(t);
  }
  return out;
}

}  // namespace

Trajectory Simulate(const DofModel& model, const Eigen::VectorXd& theta,
                    const TrialConditions& c, const std::vector<double>& output_times,
                    const SimulationOptions& options, const Eigen::VectorXd* x0) {
  return Integrate(model, theta, c, output_times, 0.0, options, x0);
}

Trajectory SimulateMeasured(const DofModel& model, const Eigen::VectorXd& theta,
                            const TrialConditions& c, const std::vector<double>& times,
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
