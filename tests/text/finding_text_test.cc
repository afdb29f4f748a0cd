// A finding's sentence (text/finding_text.h): the built-in effects' sentences quote the
// breakdown's own figures; an effect registered from outside gives its own sentence, or reads
// as its table entry's physics.
#include "uuvplan/text/finding_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "uuvplan/model/effects.h"

namespace uuvplan::text {
namespace {

ident::Finding FindingOf(const std::string& effect) {
  ident::Finding f;
  f.effect = effect;
  f.dof = model::Dof::kHeave;
  return f;
}

TEST(FindingText, ThrusterLagQuotesTheMeasuredLagWithItsSigma) {
  model::ErrorBreakdown b;
  b.dof = model::Dof::kHeave;
  b.lag_s = 0.0823;
  b.lag_sigma_s = 0.0031;
  EXPECT_EQ(FindingSentence(FindingOf("thruster_lag"), b),
            "the response to every change of thrust comes late and smoothed (measured velocity "
            "lags the standard model's simulation by 0.082 ± 0.0031 s)");
  b.lag_s = 0.0;  // below one sample: not quoted
  EXPECT_EQ(FindingSentence(FindingOf("thruster_lag"), b),
            "the response to every change of thrust comes late and smoothed");
  b.lag_s = -0.04;  // a lead is no evidence of a lag: not quoted
  EXPECT_EQ(FindingSentence(FindingOf("thruster_lag"), b),
            "the response to every change of thrust comes late and smoothed");
}

// The real campaign's case: the standard model's simulation led the measurement (−0.161 s)
// while the fitted delay was +0.349 s. One convention: the fitted delay is the finding; the
// shift is said as a lead, with its size, and what it was measured against.
TEST(FindingText, SensorDelayQuotesTheFittedDelayAndTheShiftWithItsMeaning) {
  ident::Finding f = FindingOf("sensor_delay");
  f.params = {{"sensor_delay", 0.349, 0.113, ident::ParameterState::kEstimated}};
  model::ErrorBreakdown b;
  b.dof = model::Dof::kHeave;
  b.lag_s = -0.161;
  b.lag_sigma_s = 0.094;
  EXPECT_EQ(FindingSentence(f, b),
            "every measurement comes a fixed time after the motion it measures (fitted: 0.35 ± "
            "0.11 s); before the delay was modelled, measured velocity leads the standard model's "
            "simulation by 0.16 ± 0.094 s");
  b.lag_s = 0.0;
  EXPECT_EQ(MeasuredShiftText(b),
            "measured velocity and the standard model's simulation align within a sample");
}

TEST(FindingText, InstallationLossNamesTheMappingAndQuotesTheBreakdown) {
  ident::Finding f = FindingOf("installation_loss");
  f.params = {{"eta.vertical-all.neg", 0.56, 0.023, ident::ParameterState::kEstimated},
              {"eta.vertical-all.pos", 0.98, 0.01, ident::ParameterState::kEstimated}};
  model::ErrorBreakdown b;
  b.by_thrust = {{"thrust negative in vertical-all", 0.381, 0.01, 100}};
  EXPECT_EQ(FindingSentence(f, b),
            "thrust negative in mapping vertical-all delivers 44 ± 2.3% less than the "
            "open-water model (with eta = 1 the standard simulation's speed error there: "
            "+38.1%, its m, drag and bias absorbing part of the loss)");
}

TEST(FindingText, AnEffectFromOutsideGivesItsSentenceOrReadsAsItsPhysics) {
  model::EffectEntry e;
  e.name = "toy_effect";
  e.physics = "a toy physics line";
  e.site = model::EffectSite::kSensor;  // no force term of its own
  const model::ScopedEffect toy(e);
  const model::ErrorBreakdown none;
  EXPECT_EQ(FindingSentence(FindingOf("toy_effect"), none), "a toy physics line");
  {
    const ScopedFindingSentence sentence("toy_effect", [](const FindingQuotes& c) {
      return "toy with " + std::to_string(c.params.size()) + " parameter(s)";
    });
    EXPECT_EQ(FindingSentence(FindingOf("toy_effect"), none), "toy with 0 parameter(s)");
  }
  EXPECT_EQ(FindingSentence(FindingOf("toy_effect"), none), "a toy physics line");
  EXPECT_EQ(FindingSentence(FindingOf("not_in_the_table"), none), "not_in_the_table");
}

TEST(FindingText, ThrustMapFindingsAddEachMappingsDeliveredShape) {
  ident::Finding f = FindingOf("thrust_map");
  f.params = {{"thrust_exponent", 0.0, 0.05, ident::ParameterState::kEstimated}};
  ident::CorrectedThrustMap m;
  m.mapping = "vertical-all";
  m.shape = "linear in the command";
  m.command_exponent = 1.02;
  m.command_exponent_sigma = 0.031;
  f.thrust_maps = {m};
  const std::string s = FindingSentence(f, model::ErrorBreakdown{});
  EXPECT_NE(s.find(": the thrust map is wrong in shape; vertical-all: the delivered thrust is "
                   "linear in the command (|command|^1.02 ± 0.031)"),
            std::string::npos)
      << s;
}

}  // namespace
}  // namespace uuvplan::text
