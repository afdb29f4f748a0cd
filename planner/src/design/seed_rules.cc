#include "uuvplan/planner/design/seed_rules.h"

#include <cmath>

namespace uuvplan::planner {

double LinearisedDrag(double k, double kq, double regime_speed) {
  return k + 2.0 * kq * std::abs(regime_speed);
}

double TimeConstant(double m, double k_linearised) { return m / k_linearised; }

double DOptimalSineFrequency(double time_constant) {
  return 1.0 / (std::sqrt(3.0) * time_constant);
}

double FirstOrderPhaseLag(double m, double k_linearised, double omega) {
  return std::atan(omega * m / k_linearised);
}

double SteadySpeed(double k, double kq, double force) {
  if (kq <= 0.0) return force / k;
  // Positive root of kq·x² + k·x - force = 0, written to avoid cancellation.
  return 2.0 * force / (k + std::sqrt(k * k + 4.0 * kq * force));
}

}  // namespace uuvplan::planner
