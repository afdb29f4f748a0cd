#include "uuvplan/model/thruster.h"

#include <algorithm>
#include <cmath>

namespace uuvplan::model {

double ThrustModel::Thrust(double v) const {
  if (std::abs(v) < dead_band) return 0.0;
  double tau = 0.0;
  switch (kind) {
    case Kind::kSquare:  // ref 000 eq. 6
      tau = (v >= 0 ? c_pos : c_neg) * v * std::abs(v);
      break;
    case Kind::kPoly2: {  // ref 002 eq. 1, odd extension
      const double av = std::abs(v);
      tau = std::copysign(a * av * av + b * av, v);
      break;
    }
  }
  return (1.0 - deduction) * tau;  // ref 003: T_a = (1 - t)·T
}

double ThrustModel::Command(double thrust) const {
  const double y = std::abs(thrust) / (1.0 - deduction);  // ref 003: T = T_a / (1 - t)
  double v = 0.0;
  switch (kind) {
    case Kind::kSquare:  // ref 000 eq. 6 inverted: |V| = sqrt(|tau|/c)
      v = std::sqrt(y / (thrust >= 0 ? c_pos : c_neg));
      break;
    case Kind::kPoly2:  // ref 002 eq. 1 inverted: a·V² + b·V = |tau|, V >= 0
      v = a > 0 ? (-b + std::sqrt(b * b + 4 * a * y)) / (2 * a) : y / b;
      break;
  }
  return std::copysign(v, thrust);
}

double ThrustModel::EdgeThrust(int sign) const {
  return dead_band > 0 ? std::abs(Thrust(std::copysign(dead_band, sign))) : 0.0;
}

namespace {
// Extremes of the thrust over [lo, hi]: sampled finely (the models are smooth and at most
// quadratic per side, so a fine grid plus the ends finds them to far below any tolerance).
std::pair<double, double> ThrustRange(const ThrustModel& m, double lo, double hi) {
  double tmin = std::min(m.Thrust(lo), m.Thrust(hi));
  double tmax = std::max(m.Thrust(lo), m.Thrust(hi));
  constexpr int kSamples = 400;
  for (int i = 1; i < kSamples; ++i) {
    const double tau = m.Thrust(lo + (hi - lo) * i / kSamples);
    tmin = std::min(tmin, tau);
    tmax = std::max(tmax, tau);
  }
  return {tmin, tmax};
}
}  // namespace

double Thruster::MaxForwardThrust() const {
  const auto [lo, hi] = SpanFromNeutral();
  return std::max(0.0, ThrustRange(model, lo, hi).second);
}

double Thruster::MaxReverseThrust() const {
  const auto [lo, hi] = SpanFromNeutral();
  return std::max(0.0, -ThrustRange(model, lo, hi).first);
}

}  // namespace uuvplan::model
