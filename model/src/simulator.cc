#include "uuvplan/model/simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <type_traits>

#include "dof_model_kernel.h"
#include "simulation_loop.h"
#include "uuvplan/model/util/checked_count.h"

namespace uuvplan::model {
namespace {

using Kernel = internal::DofModelKernel;
using internal::IntegrateSystem;

// A DofModel for the simulation loop: NX = number of states (2, or 3 with thruster lag), a
// template parameter so that the state loops unroll; kOthers: the model has terms of
// registered effects (DofModelKernel::TotalForce).
template <int NX, bool kOthers>
class DofSystem {
 public:
  static constexpr int kStates = NX;
  static constexpr int kMaxStates = 3;  // the kernel's state arrays; NX of them used
  using Input = InputSample;
  DofSystem(const DofModel& model, const TrialConditions& c, const double* theta)
      : model_(model), c_(c), th_(theta), inv_(Kernel::Invert(model, theta)) {}
  int num_states() const { return NX; }
  int num_parameters() const { return model_.num_parameters(); }
  Input Sample(double t) const { return Kernel::SampleInput(model_, t, c_, th_); }
  // A held input does not change inside a step; the other DOFs' velocities do.
  void Refresh(double t, Input* in) const {
    if (c_.aux && model_.needs_aux()) c_.aux->At(t, &in->velocities);
  }
  bool held() const { return c_.input && c_.input->piecewise_constant(); }
  TimesView Breakpoints() const { return c_.input ? c_.input->Breakpoints() : TimesView(); }
  [[gnu::always_inline]] void Derivative(double t, const double* x, const Input& in,
                                         double* dx) const {
    Kernel::Derivative<kOthers>(model_, t, x, in, c_, th_, inv_, dx);
  }
  void Linearize(double t, const double* x, const Input& in, double* dx, double* A,
                 double* B) const {
    Kernel::Linearize<NX, kOthers>(model_, t, x, in, c_, th_, inv_, dx, A, B);
  }

 private:
  const DofModel& model_;
  const TrialConditions& c_;
  const double* th_;
  Kernel::Inverses inv_;
};

Trajectory Integrate(const DofModel& model, const Eigen::VectorXd& theta, const TrialConditions& c,
                     TimesView output_times, double shift, const SimulationOptions& options,
                     const Eigen::VectorXd* x0, const OutputVisitor* visit = nullptr) {
  const auto run = [&](auto nx, auto others) {
    const DofSystem<decltype(nx)::value, decltype(others)::value> sys(model, c, theta.data());
    return IntegrateSystem(sys, output_times, shift, options, x0, visit);
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
