// Motion in the DOFs a single-DOF trial does not drive is measured from the log (other_motion.h)
// and worded with the trial's own for scale (text/trial_notes_text.h).
#include "uuvplan/ident/prepare/other_motion.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "uuvplan/text/trial_notes_text.h"

namespace uuvplan::ident {
namespace {

using model::Dof;
using model::Index;

// A surge trial whose log also has pos_heave (a 0.3 m dive) and vel_pitch (a ±0.2 rad/s square
// wave: rms 0.2), with NaN cells and rows before the first force row that are not counted.
TEST(OtherDofMotion, TravelAndRmsOfEveryOtherLoggedDof) {
  model::TrialLog log;
  const double nan = std::numeric_limits<double>::quiet_NaN();
  for (int i = 0; i < 101; ++i) log.t.push_back(0.1 * i);
  auto& surge = log.velocity[Index(Dof::kSurge)];
  auto& heave = log.position[Index(Dof::kHeave)];
  auto& pitch = log.velocity[Index(Dof::kPitch)];
  for (int i = 0; i < 101; ++i) {
    surge.push_back(0.5);
    heave.push_back(i < 10 ? 5.0 : 0.003 * (i - 10));  // a 5 m outlier before t = 1 s
    pitch.push_back(i % 7 == 3 ? nan : (i % 2 ? 0.2 : -0.2));
  }
  const std::vector<TrialNote> notes = OtherDofMotion(log, Dof::kSurge, 1.0);
  ASSERT_EQ(notes.size(), 2u);  // heave and pitch; sway, roll, yaw not logged
  EXPECT_EQ(notes[0].names[0], "heave");
  EXPECT_NEAR(notes[0].numbers[0], 0.003 * 90, 1e-12);  // from t = 1 s: 0 … 0.27 m
  EXPECT_TRUE(std::isnan(notes[0].numbers[1]));         // no vel_heave
  EXPECT_EQ(notes[1].names[0], "pitch");
  EXPECT_NEAR(notes[1].numbers[1], 0.2, 1e-12);
  EXPECT_NEAR(notes[1].numbers[3], 0.5, 1e-12);  // surge's own rms, for scale
  EXPECT_EQ(text::OtherMotionText(notes),
            "motion in other DOFs: heave (travel 0.27 m), pitch (0.2 rad/s rms), beside surge "
            "(0.5 m/s rms) itself; the one-DOF model holds none of it (a coupling: `uuvplan "
            "diagnose` tests it)");
}

TEST(OtherDofMotion, ALogOfTheTrialsDofAloneHasNone) {
  model::TrialLog log;
  log.t = {0, 1, 2};
  log.velocity[Index(Dof::kYaw)] = {0.1, 0.2, 0.3};
  EXPECT_TRUE(OtherDofMotion(log, Dof::kYaw, 0.0).empty());
  EXPECT_EQ(text::OtherMotionText({}), "");
}

}  // namespace
}  // namespace uuvplan::ident
