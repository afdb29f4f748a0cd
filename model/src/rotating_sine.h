// sin(ω·t + φ) for an integrator that asks at times a fixed δ apart (RK4: its half step): the
// answer is the last one rotated by ωδ — sin(a + b) = sin a·cos b + cos a·sin b, the same for
// cos — which costs four multiplications instead of a libm call (a third of a sine trial's
// simulation time, and 30% of a pool verdict's on switched multisines; docs/performance.md).
// Re-anchored with std::sin/std::cos every kAnchorEvery rotations and whenever the spacing
// changes: the rounding error of a rotation is ~1e-16 and grows as its square root, so the
// values agree with std::sin to ~1e-15. Not thread-safe (it caches), as the excitations that
// hold it.
#pragma once

#include <cmath>
#include <limits>
#include <vector>

#include "uuvplan/model/excitation.h"

namespace uuvplan::model::internal {

class RotatingSine {
 public:
  RotatingSine(double omega, double phase) : omega_(omega), phase_(phase) {}

  double At(double t) {
    constexpr int kAnchorEvery = 256;
    const double delta = t - t_;
    if (delta == 0) return sin_;  // asked again at the same time (a step end, then its output)
    if (rotations_ < kAnchorEvery && delta > 0 && std::abs(delta - delta_) <= 1e-6 * delta_) {
      // The spacing differs from delta_ by rounding (~1e-13 s at t = 600 s) or by a time shift
      // (up to ~1e-12 s): rotate by ω·delta_ + e with cos(a + e) = cos a − e·sin a,
      // sin(a + e) = sin a + e·cos a, which errs by e²/2: below 1e-17 for those differences,
      // and at most 1.25e-13 a rotation at the tolerance's edge (|e| = 1e-6·ω·delta_, ω·delta_
      // ≤ 0.5 for an RK4 half step well inside a period). A tighter tolerance re-anchors more
      // often and moves the planner's numbers in the ninth digit, enough for DIRECT to choose
      // other multisines: kept at the single sine's 1e-6.
      const double e = omega_ * (delta - delta_);
      const double cd = cos_delta_ - e * sin_delta_, sd = sin_delta_ + e * cos_delta_;
      const double s = sin_ * cd + cos_ * sd;
      cos_ = cos_ * cd - sin_ * sd;
      sin_ = s;
      ++rotations_;
    } else {
      if (delta > 0 && delta != delta_) {
        delta_ = delta;
        cos_delta_ = std::cos(omega_ * delta);
        sin_delta_ = std::sin(omega_ * delta);
      }
      sin_ = std::sin(omega_ * t + phase_);
      cos_ = std::cos(omega_ * t + phase_);
      rotations_ = 0;
    }
    t_ = t;
    return sin_;
  }

 private:
  double omega_, phase_;
  double t_ = std::numeric_limits<double>::quiet_NaN();
  double sin_ = 0.0, cos_ = 1.0;
  double delta_ = std::numeric_limits<double>::quiet_NaN();
  double cos_delta_ = 1.0, sin_delta_ = 0.0;
  int rotations_ = 0;
};

/// w(t) = offset + Σ_i a_i·sin(ω_i·t + p_i) (SwitchedWave::Wave) with each sine rotated.
class RotatingWave {
 public:
  explicit RotatingWave(const SwitchedWave& wave) : wave_(wave) {
    for (const SineComponent& c : wave.components) sines_.emplace_back(c.omega, c.phase);
  }
  double At(double t) {
    double w = wave_.offset;
    for (std::size_t i = 0; i < sines_.size(); ++i)
      w += wave_.components[i].amplitude * sines_[i].At(t);
    return w;
  }

 private:
  const SwitchedWave& wave_;
  std::vector<RotatingSine> sines_;
};

}  // namespace uuvplan::model::internal
