#include "support/coupled_campaign.h"

#include <cmath>
#include <random>
#include <string>

#include "uuvplan/model/coupled_model.h"
#include "uuvplan/model/util/seed.h"
#include "uuvplan/model/virtual_pool.h"

namespace uuvplan::testing {

model::Truth RandomCoupledTruth(const model::Truth& base, std::uint64_t seed) {
  model::Truth truth = base;
  std::mt19937_64 rng(model::SplitMix64(seed));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (model::Dof dof : model::kHorizontalDofs) {
    auto& p = truth.dofs[dof].params;
    const auto bounds = truth.vehicle.InertiaBounds(dof);
    p["m"] = bounds[0] + (bounds[1] - bounds[0]) * unit(rng);
    p["k"] *= std::exp(std::log(0.5) + std::log(4.0) * unit(rng));
    p["kq"] *= std::exp(std::log(0.5) + std::log(4.0) * unit(rng));
    p["bias"] = (2 * unit(rng) - 1) * 0.02 * 300.0;
  }
  return truth;
}

namespace {
model::TrialDesign Sine(model::Dof dof, const char* mapping, double amplitude, double omega) {
  model::TrialDesign d;
  d.dof = dof;
  d.kind = model::TrialKind::kSine;
  d.mapping = mapping;
  d.amplitude = amplitude;
  d.omega = omega;
  return d;
}
}  // namespace

std::vector<model::CombinedTrialDesign> CombinedModeDesigns(double duration_s) {
  using model::Dof;
  const auto surge = Sine(Dof::kSurge, "horizontal-all-surge", 100.0, 0.41);
  const auto sway = Sine(Dof::kSway, "horizontal-all-sway", 100.0, 0.53);
  const auto yaw = Sine(Dof::kYaw, "horizontal-all-yaw", 60.0, 0.67);
  return {{"surge-yaw", {Dof::kSurge, Dof::kYaw}, duration_s, {surge, yaw}},
          {"sway-yaw", {Dof::kSway, Dof::kYaw}, duration_s, {sway, yaw}},
          {"all", {Dof::kSurge, Dof::kSway, Dof::kYaw}, duration_s, {surge, sway, yaw}}};
}

std::vector<model::TrialLog> RunCoupledCampaign(
    const model::Truth& truth, const std::vector<model::CombinedTrialDesign>& designs,
    std::uint64_t seed) {
  const model::MultiDofModel coupled = model::CoupledModelOfTruth(truth);
  const Eigen::VectorXd theta = model::CoupledThetaOfTruth(coupled, truth);
  std::vector<model::TrialLog> logs;
  for (std::size_t i = 0; i < designs.size(); ++i) {
    model::VirtualPoolOptions options;
    options.seed = model::StreamSeed(seed, i);
    logs.push_back(model::RunCombinedTrial(truth, coupled, theta, designs[i], options));
  }
  return logs;
}

}  // namespace uuvplan::testing
