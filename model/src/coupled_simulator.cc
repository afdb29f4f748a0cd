#include "uuvplan/model/coupled_simulator.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace uuvplan::model {
namespace {

using State = Eigen::Matrix<double, 6, 1>;  // [u, v, r, x, y, ψ]

State Derivative(const CoupledHorizontalModel& model, const State& s, const Horizontal& tau) {
  const Horizontal nu = s.head<3>();
  State d;
  d.head<3>() = model.Acceleration(nu, tau);
  const double c = std::cos(s[5]), sn = std::sin(s[5]);
  d[3] = nu[0] * c - nu[1] * sn;  // seed 003: η̇₁ = J₁(η₂)·ν₁ in the plane
  d[4] = nu[0] * sn + nu[1] * c;
  d[5] = nu[2];
  return d;
}

// Classical RK4 over [t, t + h] with the thrust held at the midpoint value.
State Rk4Step(const CoupledHorizontalModel& model, const State& s, const Horizontal& tau,
              double h) {
  const State k1 = Derivative(model, s, tau);
  const State k2 = Derivative(model, s + 0.5 * h * k1, tau);
  const State k3 = Derivative(model, s + 0.5 * h * k2, tau);
  const State k4 = Derivative(model, s + h * k3, tau);
  return s + h / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4);
}

}  // namespace

CoupledTrajectory SimulateCoupled(const CoupledHorizontalModel& model,
                                  const HorizontalThrust& thrust, const Horizontal& nu0,
                                  const std::vector<double>& t_out,
                                  const std::vector<double>& breakpoints, double step_s) {
  if (!(step_s > 0)) throw std::invalid_argument("SimulateCoupled: step_s must be positive");
  std::vector<double> stops = t_out;
  stops.insert(stops.end(), breakpoints.begin(), breakpoints.end());
  std::sort(stops.begin(), stops.end());
  State s = State::Zero();
  s.head<3>() = nu0;
  CoupledTrajectory out;
  double t = 0.0;
  std::size_t next_out = 0;
  auto report = [&]() {
    while (next_out < t_out.size() && t_out[next_out] <= t + 1e-9) {
      out.t.push_back(t_out[next_out++]);
      out.nu.push_back(s.head<3>());
      out.pose.push_back(s.tail<3>());
    }
  };
  report();
  for (double stop : stops) {
    if (stop <= t + 1e-9) continue;
    const int n = static_cast<int>(std::ceil((stop - t) / step_s - 1e-9));
    const double h = (stop - t) / n;
    for (int k = 0; k < n; ++k) {
      s = Rk4Step(model, s, thrust(t + 0.5 * h), h);
      t += h;
    }
    t = stop;
    report();
  }
  return out;
}

}  // namespace uuvplan::model
