// model::RestateThrustReference (model/thrust_reference.h): a thrust map stated at another
// reference force, with m, drag, bias and coupling rescaled, is the same dynamics.
#include "uuvplan/model/thrust_reference.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "support/every_effect.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/excitation.h"
#include "uuvplan/model/simulator.h"

namespace uuvplan::model {
namespace {

// The free run of a sine of forces through the model with every effect on (support/
// every_effect.h), at the parameters and reference of `p`: position and velocity at 0.5 s steps.
Eigen::MatrixXd FreeRun(const DofParameters& p) {
  ModelStructure s = testing::EveryEffectStructure(p.settings.at("thrust_reference"));
  const DofModel model(testing::FrontRearVehicle(), s);
  const Eigen::VectorXd theta = model.Theta(p.params);
  const auto input = MakeSineExcitation(35, 25, 2 * M_PI / 26, 0, 60);
  std::vector<double> times;
  for (double t = 0.5; t <= 60; t += 0.5) times.push_back(t);
  // Columns 0 and 1; the lag's state (column 2) is the delivered force, stated at the reference.
  return Simulate(model, theta, TrialConditions{input.get()}, times, SimulationOptions{})
      .x.leftCols(2);
}

TEST(ThrustReferenceTest, RestatedModelMovesTheSame) {
  DofParameters p;
  p.params = testing::EveryEffectValues();
  p.settings["thrust_reference"] = 60.0;
  DofParameters q = p;
  ASSERT_TRUE(RestateThrustReference(25.0, &q));
  EXPECT_EQ(q.settings.at("thrust_reference"), 25.0);
  // c = (25/60)^-0.3 = 1.3006: m, drag, bias, bias_step, coupling divided by it; the rest kept.
  const double c = std::pow(25.0 / 60.0, -0.3);
  EXPECT_NEAR(q.params.at("m"), 890 / c, 1e-9);
  EXPECT_NEAR(q.params.at("kq_neg"), 331.4 / c, 1e-9);
  EXPECT_NEAR(q.params.at("coupling.rr"), 30.0 / c, 1e-12);
  EXPECT_NEAR(q.params.at("advance_loss"), 2.0 / std::sqrt(c), 1e-12);
  for (const char* kept :
       {"eta.front.neg", "lag", "deadzone", "sensor_delay", "thrust_exponent", "drift"}) {
    EXPECT_EQ(q.params.at(kept), p.params.at(kept)) << kept;
  }
  // Same motion to the integrator's rounding (both runs take the same RK4 steps): 1e-9 of the
  // largest speed and position reached.
  const Eigen::MatrixXd a = FreeRun(p), b = FreeRun(q);
  EXPECT_LE((a - b).cwiseAbs().maxCoeff(), 1e-9 * a.cwiseAbs().maxCoeff());
}

TEST(ThrustReferenceTest, AModelWithoutThrustMapIsUnchanged) {
  DofParameters p;
  p.params = {{"m", 890}, {"k", 46.9}};
  DofParameters q = p;
  EXPECT_FALSE(RestateThrustReference(25.0, &q));
  EXPECT_EQ(q.params, p.params);
  EXPECT_TRUE(q.settings.empty());
}

}  // namespace
}  // namespace uuvplan::model
