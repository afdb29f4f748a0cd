#include "uuvplan/model/simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "dof_model_kernel.h"

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

// Integrates from x0 at t = 0 and records the state at output_times[i] - shift (the state x0
// for shifted times before 0). Every RK4 step ends at the input's breakpoints and at the
// (shifted) output times, which are merged on the fly.
// NX = number of states (2, or 3 with thruster lag), a template parameter so that the state
// loops unroll.
template <int NX>
class Rk4Integration {
 public:
  Rk4Integration(const DofModel& model, const Eigen::VectorXd& theta, const TrialConditions& c,
                 const std::vector<double>& output_times, double shift,
                 const SimulationOptions& options, const Eigen::VectorXd* x0)
      : model_(model), c_(c), output_times_(output_times), shift_(shift), options_(options),
        th_(theta.data()), inv_(Kernel::Invert(model, th_)), np_(model.num_parameters()),
        sens_(options.sensitivities), ns_(sens_ ? NX * np_ : 0), S_(ns_, 0.0), St_(ns_),
        K1_(ns_), K2_(ns_), K3_(ns_), K4_(ns_), B_(ns_) {
    if (!(options.step_s > 0)) throw std::invalid_argument("SimulationOptions::step_s must be > 0");
    if (!std::is_sorted(output_times.begin(), output_times.end()) ||
        (!output_times.empty() && output_times.front() < 0)) {
      throw std::invalid_argument("Simulate: output times must be sorted and >= 0");
    }
    if (x0) {
      for (int s = 0; s < NX && s < x0->size(); ++s) x_[s] = (*x0)[s];
    }
    const std::size_t n_out = output_times.size();
    out_.t = output_times;
    out_.x.resize(n_out, NX);
    if (sens_) {
      out_.S.resize(NX);  // sized in place: copying a prototype would touch 3 × n_out × np doubles
      for (auto& m : out_.S) m.resize(n_out, np_);
    }
  }

  Trajectory Run() {
    Record(0.0);
    std::vector<double> breaks = c_.input ? c_.input->Breakpoints() : std::vector<double>{};
    std::sort(breaks.begin(), breaks.end());
    std::size_t next_break = 0;
    // The input is sampled once per stage time; a step's end sample starts the next step
    // unless the step ended at a breakpoint (where the input jumps).
    // A piecewise-constant input does not change inside a step (steps end at its breakpoints):
    // only the other DOFs' velocities are sampled at the inner stage times.
    held_ = c_.input && c_.input->piecewise_constant();
    double t = 0.0;
    InputSample in_a = model_.SampleInput(0.0, c_, th_);
    while (next_out_ < output_times_.size()) {
      while (next_break < breaks.size() && breaks[next_break] <= t) ++next_break;
      double b = output_times_[next_out_] - shift_;
      if (next_break < breaks.size()) b = std::min(b, breaks[next_break]);
      const int n = std::max(1, static_cast<int>(std::ceil((b - t) / options_.step_s - 1e-9)));
      const double h = (b - t) / n;
      for (int k = 0; k < n; ++k) Step(t + k * h, h, b, &in_a);
      t = b;
      if (next_break < breaks.size() && breaks[next_break] <= t) {
        in_a = model_.SampleInput(t, c_, th_);  // right limit after a jump
      }
      Record(t);
    }
    return std::move(out_);
  }

 private:
  // One RK4 step [ta, ta + h] inside the interval ending at b; in_a is the input at ta on
  // entry and at the step's end on return.
  inline void Step(double ta, double h, double b, InputSample* in_a) {
    const double tm = Inside(ta + 0.5 * h, ta, b), te = Inside(ta + h, ta, b);
    InputSample in_m = *in_a, in_e = *in_a;
    if (!held_) {
      in_m = Kernel::SampleInput(model_, tm, c_, th_);
      in_e = Kernel::SampleInput(model_, te, c_, th_);
    } else if (c_.aux && model_.needs_aux()) {
      c_.aux->At(tm, &in_m.velocities);
      c_.aux->At(te, &in_e.velocities);
    }
    double k1[3], k2[3], k3[3], k4[3];
    if (!sens_) {
      StateStages(ta, tm, te, h, *in_a, in_m, in_e, k1, k2, k3, k4);
    } else {
      SensitivityStages(ta, tm, te, h, *in_a, in_m, in_e, k1, k2, k3, k4);
    }
    // Classical RK4: x += h/6·(k1 + 2k2 + 2k3 + k4) (on S with the same stages).
    for (int s = 0; s < NX; ++s) x_[s] += (h / 6.0) * (k1[s] + 2 * k2[s] + 2 * k3[s] + k4[s]);
    *in_a = in_e;
  }

  // The four RK4 slopes of x.
  inline void StateStages(double ta, double tm, double te, double h, const InputSample& in_a,
                          const InputSample& in_m, const InputSample& in_e, double* k1,
                          double* k2, double* k3, double* k4) const {
    double xt[3] = {0, 0, 0};  // xt[2] unused without thruster lag
    Kernel::Derivative(model_, ta, x_, in_a, c_, th_, inv_, k1);
    for (int s = 0; s < NX; ++s) xt[s] = x_[s] + 0.5 * h * k1[s];
    Kernel::Derivative(model_, tm, xt, in_m, c_, th_, inv_, k2);
    for (int s = 0; s < NX; ++s) xt[s] = x_[s] + 0.5 * h * k2[s];
    Kernel::Derivative(model_, tm, xt, in_m, c_, th_, inv_, k3);
    for (int s = 0; s < NX; ++s) xt[s] = x_[s] + h * k3[s];
    Kernel::Derivative(model_, te, xt, in_e, c_, th_, inv_, k4);
  }

  // The four RK4 slopes of x and of S (dS/dt = A·S + B, the forward sensitivity equations,
  // A = ∂f/∂x, B = ∂f/∂theta), and the step of S.
  inline void SensitivityStages(double ta, double tm, double te, double h,
                                const InputSample& in_a, const InputSample& in_m,
                                const InputSample& in_e, double* k1, double* k2, double* k3,
                                double* k4) {
    double xt[3] = {0, 0, 0};  // xt[2] unused without thruster lag
    double* Bp = B_.data();
    Kernel::Linearize<NX>(model_, ta, x_, in_a, c_, th_, inv_, k1, A_, Bp);
    Slope(nullptr, 0.0, K1_.data());
    for (int s = 0; s < NX; ++s) xt[s] = x_[s] + 0.5 * h * k1[s];
    Kernel::Linearize<NX>(model_, tm, xt, in_m, c_, th_, inv_, k2, A_, Bp);
    Slope(K1_.data(), 0.5 * h, K2_.data());
    for (int s = 0; s < NX; ++s) xt[s] = x_[s] + 0.5 * h * k2[s];
    Kernel::Linearize<NX>(model_, tm, xt, in_m, c_, th_, inv_, k3, A_, Bp);
    Slope(K2_.data(), 0.5 * h, K3_.data());
    for (int s = 0; s < NX; ++s) xt[s] = x_[s] + h * k3[s];
    Kernel::Linearize<NX>(model_, te, xt, in_e, c_, th_, inv_, k4, A_, Bp);
    Slope(K3_.data(), h, K4_.data());
    for (int j = 0; j < ns_; ++j) {
      S_[j] += (h / 6.0) * (K1_[j] + 2.0 * K2_[j] + 2.0 * K3_[j] + K4_[j]);
    }
  }

  // K = A·St + B with St = S + c·K_prev (c = 0 for the first stage). S, St, K are row-major
  // NX × np (row s: the sensitivities of state s); A (NX × NX) and B (NX × np) as the kernel
  // writes them.
  inline void Slope(const double* k_prev, double c_prev, double* K) {
    for (int j = 0; j < ns_; ++j) St_[j] = k_prev ? S_[j] + c_prev * k_prev[j] : S_[j];
    for (int r = 0; r < NX; ++r) {
      double* Kr = K + r * np_;
      const double* Br = B_.data() + r * np_;
      for (int j = 0; j < np_; ++j) {
        double v = Br[j];
        for (int q = 0; q < NX; ++q) v += A_[r * NX + q] * St_[q * np_ + j];
        Kr[j] = v;
      }
    }
  }

  // The state (and S) at every output time reached by t.
  void Record(double t) {
    while (next_out_ < output_times_.size() && output_times_[next_out_] - shift_ <= t) {
      for (int s = 0; s < NX; ++s) out_.x(next_out_, s) = x_[s];
      if (sens_) {
        for (int s = 0; s < NX; ++s) {
          for (int j = 0; j < np_; ++j) out_.S[s](next_out_, j) = S_[s * np_ + j];
        }
      }
      ++next_out_;
    }
  }

  const DofModel& model_;
  const TrialConditions& c_;
  const std::vector<double>& output_times_;
  const double shift_;
  const SimulationOptions& options_;
  const double* th_;
  const Kernel::Inverses inv_;
  const int np_;
  const bool sens_;
  const int ns_;
  bool held_ = false;
  double x_[3] = {0, 0, 0};
  std::vector<double> S_, St_, K1_, K2_, K3_, K4_, B_;
  double A_[NX * NX];
  std::size_t next_out_ = 0;
  Trajectory out_;
};

Trajectory Integrate(const DofModel& model, const Eigen::VectorXd& theta,
                     const TrialConditions& c, const std::vector<double>& output_times,
                     double shift, const SimulationOptions& options, const Eigen::VectorXd* x0) {
  return model.num_states() == 3
             ? Rk4Integration<3>(model, theta, c, output_times, shift, options, x0).Run()
             : Rk4Integration<2>(model, theta, c, output_times, shift, options, x0).Run();
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
