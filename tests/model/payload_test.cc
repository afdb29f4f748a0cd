// A payload on a known vehicle (model/payload.h, docs/planning.md "A payload on a known
// vehicle"): each rule against the geometry it comes from, and the combined vehicle's box
// around the base's estimates.
#include "uuvplan/model/payload.h"

#include <gtest/gtest.h>

#include "uuvplan/model/parameter.h"

namespace uuvplan::model {
namespace {

// payload60's skid under its frame (cases/payload60/on-frame.yaml).
Payload Skid() {
  Payload p;
  p.mass = 40;
  p.volume = 0.038;
  p.size = {0.9, 0.7, 0.25};
  p.cg = {0, 0, 0.3};
  p.added_mass = {0.1, 1.5};
  p.blocks = {"sway-all.neg"};
  return p;
}

Vehicle Frame() {
  Vehicle v;
  v.name = "frame";
  v.mass = 20;
  v.size = {0.9, 0.7, 0.35};
  ThrustMapping sway;
  sway.name = "sway-all";
  sway.dof = Dof::kSway;
  v.mappings = {sway};
  DofParameters surge;
  surge.params = {{"m", 30}, {"k", 8.5}, {"kq", 85}, {"bias", 0.5}, {"lag", 0.15}};
  surge.sigma = {{"m", 1}, {"k", 0.1}, {"kq", 0.2}, {"bias", 0.01}, {"lag", 0.01}};
  v.models[Dof::kSurge] = surge;
  DofParameters sway_model;
  sway_model.params = {{"m", 36}, {"k", 10.5}, {"kq", 105}, {"eta.sway-all.neg", 0.9}};
  sway_model.sigma = {{"m", 1}, {"k", 0.1}, {"kq", 0.5}, {"eta.sway-all.neg", 0.01}};
  v.models[Dof::kSway] = sway_model;
  return v;
}

TEST(Payload, CombinedSizeHoldsBothBoxes) {
  const auto size = CombinedSize({0.9, 0.7, 0.35}, Skid());
  EXPECT_DOUBLE_EQ(size[0], 0.9);
  EXPECT_DOUBLE_EQ(size[1], 0.7);
  EXPECT_DOUBLE_EQ(size[2], 0.6);  // frame [-0.175, 0.175] and skid [0.175, 0.425] m in z
}

TEST(Payload, RigidInertiaIsTheBoxsOwnPlusTheParallelAxisTerm) {
  Payload p;
  p.mass = 10;
  p.size = {0.2, 0.1, 0.4};
  p.cg = {1.0, 0.0, 0.5};
  EXPECT_DOUBLE_EQ(PayloadRigidInertia(p, Dof::kSurge), 10.0);
  // Yaw: m(l² + w²)/12 + m(x² + y²) = 10·0.05/12 + 10.
  EXPECT_NEAR(PayloadRigidInertia(p, Dof::kYaw), 10 * 0.05 / 12 + 10, 1e-12);
  // Roll: m(w² + h²)/12 + m(y² + z²) = 10·0.17/12 + 2.5.
  EXPECT_NEAR(PayloadRigidInertia(p, Dof::kRoll), 10 * 0.17 / 12 + 2.5, 1e-12);
}

TEST(Payload, DragGrowsAtMostByTheFrontalAreaItAdds) {
  const auto combined = CombinedSize({0.9, 0.7, 0.35}, Skid());
  const auto surge = DragFactorRange({0.9, 0.7, 0.35}, combined, Dof::kSurge);
  EXPECT_DOUBLE_EQ(surge[0], 1.0);                           // in the frame's wake
  EXPECT_NEAR(surge[1], (0.7 * 0.6) / (0.7 * 0.35), 1e-12);  // fully exposed: width × height
  // Heave: the skid has the frame's footprint, so the plan area does not grow.
  EXPECT_NEAR(DragFactorRange({0.9, 0.7, 0.35}, combined, Dof::kHeave)[1], 1.0, 1e-12);
}

TEST(Payload, HeaveBiasChangesByTheWeightInWater) {
  EXPECT_NEAR(PayloadBiasChange(Skid(), Dof::kHeave), (40 - 38.0) * kGravity, 1e-9);
  EXPECT_EQ(PayloadBiasChange(Skid(), Dof::kSurge), 0.0);
}

TEST(Payload, CombinedModelIsABoxAboutTheBasesEstimates) {
  const Vehicle v = WithPayload(Frame(), Skid(), "frame+skid", "the frame with the skid");
  EXPECT_EQ(v.name, "frame+skid");
  EXPECT_DOUBLE_EQ(v.mass, 60.0);
  const DofParameters& surge = v.models.at(Dof::kSurge);
  EXPECT_EQ(surge.origin, "the frame with the skid");
  EXPECT_TRUE(surge.identified());
  // m: [30 - 3·1 + 40·1.1, 30 + 3·1 + 40·2.5] = [71, 133]: its middle ± a sixth of its width.
  EXPECT_NEAR(surge.params.at("m"), 102.0, 1e-9);
  EXPECT_NEAR(surge.sigma.at("m"), 62.0 / 6, 1e-9);
  // kq: [85 - 3·0.2, (85 + 3·0.2)·1.714].
  const double r = 0.6 / 0.35, lo = 84.4, hi = 85.6 * r;
  EXPECT_NEAR(surge.params.at("kq"), 0.5 * (lo + hi), 1e-9);
  EXPECT_NEAR(surge.sigma.at("kq"), (hi - lo) / 6, 1e-9);
  EXPECT_DOUBLE_EQ(surge.params.at("bias"), 0.5);  // surge: the tether's pull, unchanged
  // The thrusters are the frame's: their lag is known as before.
  EXPECT_DOUBLE_EQ(surge.params.at("lag"), 0.15);
  EXPECT_DOUBLE_EQ(surge.sigma.at("lag"), 0.01);
  // Yaw's rigid inertia: the frame's box plus the skid's about the same axis.
  EXPECT_NEAR(v.inertia.at(Dof::kYaw), 20 * (0.81 + 0.49) / 12 + 40 * (0.81 + 0.49) / 12, 1e-9);
}

TEST(Payload, BlockedJetsMakeTheirCoefficientUnknownAgain) {
  const Vehicle v = WithPayload(Frame(), Skid(), "frame+skid", "the frame with the skid");
  EXPECT_EQ(v.mappings.at(0).open_water, OpenWater::kPositive);
  EXPECT_EQ(v.models.at(Dof::kSway).params.count("eta.sway-all.neg"), 0u);
  EXPECT_EQ(v.models.at(Dof::kSway).sigma.count("eta.sway-all.neg"), 0u);
}

}  // namespace
}  // namespace uuvplan::model
