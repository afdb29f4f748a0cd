// The closed-form design rules of ref 000 §III-B: the linearised time constant and the
// d-optimal single-sine frequency of a first-order system. Starting points for the optimiser.
#pragma once

namespace uuvplan::planner {

/// Ref 000 eq. 13: linearised drag k_L = k + 2·kq·|xi*| about the regime speed xi*.
double LinearisedDrag(double k, double kq, double regime_speed);

/// Ref 000 eq. 13: time constant t_c = m / k_L (s).
double TimeConstant(double m, double k_linearised);

/// Ref 000 eq. 14 (Goodwin & Payne): d-optimal sine frequency of a first-order system,
/// omega_opt = 1 / (sqrt(3)·t_c) (rad/s).
double DOptimalSineFrequency(double time_constant);

/// Phase lag (rad) of the velocity behind a sine force of frequency omega for the linear
/// first-order system m·dxi/dt = -k_L·xi + phi: atan(omega·m/k_L).
double FirstOrderPhaseLag(double m, double k_linearised, double omega);

/// Regime speed xi* >= 0 at which k·xi + kq·xi² = force (force >= 0).
double SteadySpeed(double k, double kq, double force);

}  // namespace uuvplan::planner
