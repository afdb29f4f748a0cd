// A long record whose logged force changes at every sample (a sine logged at 100 Hz, as the
// planner's own sine trials are): the output error's coarse stage averages the held force over
// pieces of a coarse step (ident/src/estimators/averaged_input.h), keeping each piece's impulse,
// so its answer starts the full-size fit within a few σ of its minimum, where the Gauss–Newton
// step is tried undamped (output_error_levenberg_marquardt.cc) and converges quadratically.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "ident_cases.h"
#include "uuvplan/ident/identify.h"
#include "uuvplan/ident/stats/monte_carlo.h"
#include "uuvplan/io/io.h"

namespace uuvplan::ident {
namespace {

// bench/cases/position_surge_truth.yaml: ROMEO's surge at m = 900 kg, a 100 Hz position sensor
// (σ 1 cm) alone; 60 N·sin(2π t/40 s) for 2,500 s: 250,001 samples, above the coarse stage's
// 2 × 100,000, each with a new force value.
model::Campaign ContinuousForceCampaign() {
  const model::Truth truth =
      io::ReadTruth(std::string(UUVPLAN_SOURCE_DIR) + "/bench/cases/position_surge_truth.yaml");
  const model::TrialDesign d =
      testing::Sine("surge_sine", model::Dof::kSurge, "surge-front", 0.0, 60.0, 40.0, 2500.0);
  return VirtualCampaign(truth, {d}, 16, {}, 60.0, /*command_rate_hz=*/100.0);
}

TEST(OutputErrorLongRecord, AForceChangingEverySampleNeedsTwoFullSizeIterations) {
  const model::Campaign c = ContinuousForceCampaign();
  ASSERT_EQ(c.trials.at(0).log.size(), 250001u);
  const IdentifyResult r = Identify(c, IdentifyOptions{});
  const DofIdentification* s = r.Find(model::Dof::kSurge);
  ASSERT_NE(s, nullptr);
  ASSERT_TRUE(s->output_error.has_value());
  EXPECT_EQ(s->output_error->status, OutputErrorStatus::kConverged) << s->output_error->message;
  // One Gauss–Newton step from the coarse answer and one that finds the step negligible
  // (< 0.1σ): with the force's impulse kept per piece the coarse answer lies within a few σ of
  // the full-size minimum. Pieces holding their first row's force instead (the impulse shifted
  // by half a piece) leave the full-size fit 4 iterations.
  EXPECT_LE(s->output_error->iterations, 2);
  const ParameterEstimate* m = s->Param("m");
  ASSERT_NE(m, nullptr);
  EXPECT_LE(std::abs(m->value - 900.0), 3 * m->sigma) << m->value << " ± " << m->sigma;
}

}  // namespace
}  // namespace uuvplan::ident
