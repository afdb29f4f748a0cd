// CentreTravel (planner/design/centred_travel.h): the start and the margin lines of a travel
// centred in the free travel, as the schedule's start and the run sheet's abort lines use them.
#include "uuvplan/planner/design/centred_travel.h"

#include <gtest/gtest.h>

namespace uuvplan::planner {
namespace {

TEST(CentreTravelTest, SlackSplitEvenlyBetweenBothEnds) {
  // A 3 m travel, 1 m behind the start and 2 m ahead, in 5 m of free travel: 1 m to spare at
  // each end, so the start is 2 m from the negative end and the ends 2 m behind, 3 m ahead.
  const CentredTravel c = CentreTravel(5.0 - 3.0, {-1.0, 2.0});
  EXPECT_EQ(c.start, 2.0);
  EXPECT_EQ(c.ends[0], -2.0);
  EXPECT_EQ(c.ends[1], 3.0);
  EXPECT_EQ(c.ends[1] - c.ends[0], 5.0);  // the whole free travel
  EXPECT_EQ(c.start, -c.ends[0]);
}

TEST(CentreTravelTest, NoSlackStartsTheTravelAtTheNegativeEnd) {
  const CentredTravel c = CentreTravel(0.0, {-0.5, 4.0});
  EXPECT_EQ(c.start, 0.5);
  EXPECT_EQ(c.ends[0], -0.5);
  EXPECT_EQ(c.ends[1], 4.0);
}

}  // namespace
}  // namespace uuvplan::planner
