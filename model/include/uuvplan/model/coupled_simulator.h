// Simulation of the coupled horizontal model (coupled_model.h): RK4 on ν = [u, v, r] with the
// pose η = [x, y, ψ] in the pool frame, η̇ = J(ψ)·ν (seed 003, J₁ reduced to the plane:
// ẋ = u·cos ψ − v·sin ψ, ẏ = u·sin ψ + v·cos ψ, ψ̇ = r).
#pragma once

#include <functional>
#include <vector>

#include "uuvplan/model/coupled_model.h"

namespace uuvplan::model {

/// τ = [X, Y, N] at time t (s from the trial start).
using HorizontalThrust = std::function<Horizontal(double t)>;

struct CoupledTrajectory {
  std::vector<double> t;
  std::vector<Horizontal> nu;    ///< [u, v, r] at t[i]
  std::vector<Horizontal> pose;  ///< [x, y, ψ] at t[i], from the origin at t = 0
};

/// Integrates from ν(0) = nu0 (pose 0) and reports at the sorted times `t_out` (>= 0). Steps
/// are at most `step_s` and end at every time of `t_out` and `breakpoints`, and τ is taken at
/// each step's midpoint, so a thrust held between breakpoints is integrated exactly as held.
CoupledTrajectory SimulateCoupled(const CoupledHorizontalModel& model,
                                  const HorizontalThrust& thrust, const Horizontal& nu0,
                                  const std::vector<double>& t_out,
                                  const std::vector<double>& breakpoints, double step_s);

}  // namespace uuvplan::model
