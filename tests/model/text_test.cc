// Numbers for people (model/util/text.h): significant digits without a
// positive exponent, durations as s or min:s, angles in degrees with turns.
#include "uuvplan/model/util/text.h"

#include <gtest/gtest.h>

#include <cmath>

namespace uuvplan::model {
namespace {

TEST(Text, SignificantIsPositionalForEverydayMagnitudes) {
  EXPECT_EQ(Significant(1234.4, 2), "1234");  // whole digits kept, no "1.2e+03"
  EXPECT_EQ(Significant(0.052341, 3), "0.0523");
  EXPECT_EQ(Significant(1.5, 4), "1.5");  // trailing zeros dropped
  EXPECT_EQ(Significant(-2.04999, 3), "-2.05");
  EXPECT_EQ(Significant(9.9996, 3), "10");
  EXPECT_EQ(Significant(0.0, 3), "0");
  EXPECT_EQ(Significant(2.5e-5, 2), "2.5e-05");  // tiny: an exponent is clearer
  EXPECT_EQ(Significant(3e8, 2), "3e+08");       // beyond 10⁷
}

TEST(Text, DurationsReadAsSecondsOrMinutesAndSeconds) {
  EXPECT_EQ(DurationText(45.24), "45.2 s");
  EXPECT_EQ(DurationText(1234.0), "20:34 min");
  EXPECT_EQ(DurationText(59.97), "1:00 min");
  EXPECT_EQ(DurationText(240.0), "4:00 min");
}

TEST(Text, AnglesReadInDegreesWithTurns) {
  EXPECT_EQ(AngleText(M_PI / 2), "90°");
  EXPECT_EQ(AngleText(-6 * M_PI), "-1080° (-3 turns)");
}

}  // namespace
}  // namespace uuvplan::model
