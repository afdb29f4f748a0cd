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

namespace uuvplan::model::internal {

class RotatingSine {
 public:
  RotatingSine(double omega, double phase) : omega_(omega), phase_(phase) {}

  double At(double t) {
    constexpr int kAnchorEvery = 256;
    const double delta = t - t_;
    if (delta == 0) return sin_;  // asked again at the same time (a step end, then its output)
    if (rotations_ < kAnchorEvery && delta > 0 && std::abs(delta - delta_) <= 1e-6 * delta_) {
      // The spacing differs from delta_ by rounding (up to ~1e-12 s after a time shift): rotate
      // by ω·delta_ + e with cos(a + e) = cos a − e·sin a, sin(a + e) = sin a + e·cos a, whose
      // error e²/2 stays below 1e-17 for |e| ≤ 1e-6·ω·delta_.
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

}  // namespace uuvplan::model::internal
