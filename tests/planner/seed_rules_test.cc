// The numbers ref 000 (Caccia, Indiveri, Veruggio 2000) prints for ROMEO's a priori design
// (§III-B eqs. 13-14, §IV-D), reproduced by the closed-form rules the planner starts from.
// The seed writes "Hz" for ω_opt; eq. 14 gives rad/s, and only rad/s is consistent with its
// remark that a 26 s period (0.24 rad/s) is "higher than the suboptimal" frequency.
#include "uuvplan/planner/design/seed_rules.h"

#include <gtest/gtest.h>

#include <cmath>

namespace uuvplan::planner {
namespace {

constexpr double kDeg = M_PI / 180.0;

TEST(SeedRules, RomeoYawOptimalFrequency) {
  // §IV-D: I_r = (1/12)·450·(1.3² + 0.9²) = 93.75 kg·m², k_r = 28.6 (Table III, linear model):
  // t_c = 3.278 s, ω_opt = 1/(√3·t_c) = 0.176. The seed prints three digits: tolerance 0.0005.
  const double tc = TimeConstant(93.75, 28.6);
  EXPECT_NEAR(DOptimalSineFrequency(tc), 0.176, 0.0005);
}

TEST(SeedRules, RomeoSurgeLinearisedDragAndFrequency) {
  // §IV-D: offset 35 N "corresponding to a regime speed of 0.27 m/s" with Table IV forward
  // k = 46.9, kq = 306.2; eq. 13: k_L = k + 2·kq·0.27 = 212.25 N·s/m.
  const double v = SteadySpeed(46.9, 306.2, 35.0);
  EXPECT_NEAR(v, 0.27, 0.005);  // the seed rounds the speed to 2 digits
  // 46.9 + 2·306.2·0.27 = 212.248, printed with two decimals.
  EXPECT_NEAR(LinearisedDrag(46.9, 306.2, 0.27), 212.25, 0.005);
  // From the exact steady speed instead of the rounded 0.27: within 0.1%.
  EXPECT_NEAR(LinearisedDrag(46.9, 306.2, v), 212.25, 0.2);
  // m = 450 + 50% = 675 kg: ω_opt = 212.25/(√3·675) = 0.1815, printed "0.18".
  EXPECT_NEAR(DOptimalSineFrequency(TimeConstant(675.0, 212.25)), 0.18, 0.005);
}

TEST(SeedRules, PhaseLagsThePaperPredicts) {
  // §IV-D yaw: I = 84, k_r = 28.6, period 24 s: atan(ω·I/k) = 37.5° ("about 37.5°").
  EXPECT_NEAR(FirstOrderPhaseLag(84.0, 28.6, 2 * M_PI / 24.0) / kDeg, 37.5, 0.1);
  // §IV-D surge: m = 890, k_L = 212.25, period 26 s: 45.4°, "about 45°" (tolerance 0.5°).
  EXPECT_NEAR(FirstOrderPhaseLag(890.0, 212.25, 2 * M_PI / 26.0) / kDeg, 45.0, 0.5);
}

TEST(SeedRules, SteadySpeedSolvesTheDragEquation) {
  // k·v + kq·v² = F at the returned v, also without quadratic drag.
  for (double f : {0.1, 3.0, 35.0, 400.0}) {
    const double v = SteadySpeed(46.9, 306.2, f);
    EXPECT_NEAR(46.9 * v + 306.2 * v * v, f, 1e-9 * f);
  }
  EXPECT_NEAR(SteadySpeed(28.6, 0.0, 5.0), 5.0 / 28.6, 1e-15);
}

}  // namespace
}  // namespace uuvplan::planner
