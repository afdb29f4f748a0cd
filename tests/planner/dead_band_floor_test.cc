// A thruster's dead band as the floor of every working thrust (model::Vehicle::
// WorkingThrustFloor): where its edge lies above min_thrust, the planner's force range starts
// there and a trial whose thrust falls inside it is refused naming the dead band.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "planner/planner_test_util.h"
#include "uuvplan/model/excitation.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner {
namespace {

using ::testing::HasSubstr;

TEST(DeadBandFloor, TheEdgeAboveMinThrustIsTheFloor) {
  model::Vehicle v = testing::Romeo();
  const int front = v.MappingIndex("surge-front");
  ASSERT_GE(front, 0);
  const double floor_before = DirectionForceRange(v, front, +1).min_abs;
  EXPECT_NEAR(floor_before, v.min_thrust / 0.70711, 1e-9);  // the mapping's shares 0.70711
  // A 3 V dead band: 1.02·3² = 9.18 N forward, 1.09·3² = 9.81 N reverse at its edge.
  for (model::Thruster& t : v.thrusters) t.model.dead_band = 3.0;
  ASSERT_GT(9.81, v.min_thrust);
  EXPECT_NEAR(v.WorkingThrustFloor(), 9.81, 1e-12);
  EXPECT_NEAR(DirectionForceRange(v, front, +1).min_abs, 9.81 / 0.70711, 1e-9);
  // 10 N of surge: 7.07 N per thruster, above min_thrust but inside the dead band.
  const auto input = model::MakeSteadyExcitation(10.0, front, 20.0);
  const ThrustCheck c = CheckThrust(v, *input, 20.0);
  EXPECT_TRUE(c.below_min);
  ASSERT_FALSE(c.reasons.empty());
  EXPECT_THAT(c.reasons.back(),
              HasSubstr("below the thrusters' dead band edge (thrust.dead_band)"));
}

}  // namespace
}  // namespace uuvplan::planner
