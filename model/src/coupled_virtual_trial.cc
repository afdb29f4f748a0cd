#include "uuvplan/model/coupled_virtual_trial.h"

#include <array>
#include <cmath>
#include <memory>
#include <random>

#include "pool_sampling.h"
#include "uuvplan/model/coupled_simulator.h"
#include "uuvplan/model/excitation.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/mapping.h"
#include "uuvplan/model/util/seed.h"

namespace uuvplan::model {
namespace {

// The held commands of each horizontal DOF (none for a DOF the mode does not move) and the
// thrust they make: τ_ξ = η_ξ(mapping, sign φ)·φ_ξ (seed 003 practical model, η per mapping).
struct HorizontalCommands {
  std::array<internal::Commands, 3> commands;
  std::array<std::unique_ptr<Excitation>, 3> held;
  std::array<std::vector<double>, 3> eta_pos, eta_neg;  // by vehicle mapping index

  Horizontal Thrust(double t) const {
    Horizontal tau = Horizontal::Zero();
    for (int i = 0; i < 3; ++i) {
      if (!held[i]) continue;
      double phi = 0.0;
      int mapping = -1;
      held[i]->Sample(t, &phi, &mapping);
      const auto& eta = phi >= 0 ? eta_pos[i] : eta_neg[i];
      tau[i] = (mapping >= 0 ? eta[mapping] : 1.0) * phi;
    }
    return tau;
  }
};

double EtaOf(const Truth& truth, Dof dof, const std::string& mapping, Direction d) {
  const auto it = truth.dofs.find(dof);
  if (it == truth.dofs.end()) return 1.0;
  const auto eta = it->second.params.find(EtaName(mapping, d));
  return eta == it->second.params.end() ? 1.0 : eta->second;
}

HorizontalCommands Command(const Truth& truth, const CoupledTrialDesign& design,
                           double rate_hz) {
  const Vehicle& v = truth.vehicle;
  HorizontalCommands c;
  for (const TrialDesign& input : design.inputs) {
    const int i = HorizontalIndex(input.dof);
    TrialDesign whole = input;
    whole.duration = design.duration;
    c.commands[i] = internal::HeldCommands(v, whole, rate_hz);
    c.held[i] = MakeHeldExcitation(c.commands[i].t, c.commands[i].force,
                                   c.commands[i].mapping, design.duration);
    for (const ThrustMapping& m : v.mappings) {
      c.eta_pos[i].push_back(EtaOf(truth, input.dof, m.name, Direction::kPos));
      c.eta_neg[i].push_back(EtaOf(truth, input.dof, m.name, Direction::kNeg));
    }
  }
  return c;
}

// One sensor of horizontal DOF i: its times and corrupted values; `state` picks ν_i or the
// pose entry i (x, y, ψ).
struct Sampled {
  std::vector<double> t, y;
};
Sampled Measure(const CoupledHorizontalModel& model, const HorizontalCommands& c,
                const SensorSpec& spec, const SensorDefects& defects, double duration, int i,
                bool position, double step_s, std::mt19937_64& rng) {
  Sampled s;
  s.t = internal::SampleTimes(spec.rate_hz, duration);
  std::vector<double> breakpoints;
  for (const auto& cmd : c.commands) breakpoints.insert(breakpoints.end(), cmd.t.begin(), cmd.t.end());
  const CoupledTrajectory x = SimulateCoupled(
      model, [&](double t) { return c.Thrust(t); }, Horizontal::Zero(), s.t, breakpoints, step_s);
  Eigen::VectorXd clean(x.t.size());
  for (std::size_t k = 0; k < x.t.size(); ++k) clean[k] = position ? x.pose[k][i] : x.nu[k][i];
  s.y = internal::Corrupt(clean, spec, defects, rng);
  if (position && i == 2) {
    for (double& a : s.y) a = std::isnan(a) ? a : internal::WrapAngle(a);
  }
  return s;
}

}  // namespace

TrialLog RunCoupledVirtualTrial(const Truth& truth, const CoupledTrialDesign& design,
                                const VirtualPoolOptions& options) {
  if (const std::string error = design.Check(); !error.empty()) throw InputError(error);
  const CoupledHorizontalModel model = CoupledModelOfTruth(truth);
  const HorizontalCommands c = Command(truth, design, options.command_rate_hz);
  std::mt19937_64 rng(SplitMix64(options.seed));
  std::vector<std::vector<double>> grids;
  for (const auto& cmd : c.commands) {
    if (!cmd.t.empty()) grids.push_back(cmd.t);
  }
  std::array<Sampled, 3> pos, vel;
  for (int i = 0; i < 3; ++i) {
    const auto sensors = truth.vehicle.sensors.find(kHorizontalDofs[i]);
    if (sensors == truth.vehicle.sensors.end()) continue;
    if (sensors->second.position) {
      pos[i] = Measure(model, c, *sensors->second.position, truth.defects, design.duration, i,
                       true, truth.integration_step_s, rng);
      grids.push_back(pos[i].t);
    }
    if (sensors->second.velocity) {
      vel[i] = Measure(model, c, *sensors->second.velocity, truth.defects, design.duration, i,
                       false, truth.integration_step_s, rng);
      grids.push_back(vel[i].t);
    }
  }
  TrialLog log;
  log.t = internal::MergeTimes(grids);
  for (int i = 0; i < 3; ++i) {
    const int column = Index(kHorizontalDofs[i]);
    log.force[column] = c.commands[i].t.empty()
                            ? std::vector<double>(log.t.size(), 0.0)
                            : internal::OnRows(log.t, c.commands[i].t, c.commands[i].force);
    if (!pos[i].t.empty()) log.position[column] = internal::OnRows(log.t, pos[i].t, pos[i].y);
    if (!vel[i].t.empty()) log.velocity[column] = internal::OnRows(log.t, vel[i].t, vel[i].y);
  }
  return log;
}

}  // namespace uuvplan::model
