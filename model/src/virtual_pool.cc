#include "uuvplan/model/virtual_pool.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>
#include <random>
#include <string>

#include "pool_sampling.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/simulator.h"
#include "uuvplan/model/util/checked_count.h"
#include "uuvplan/model/util/seed.h"

namespace uuvplan::model {
namespace {

using internal::Commands;
using internal::Corrupt;
using internal::HeldCommands;
using internal::LogMappingColumn;
using internal::MergeTimes;
using internal::OnRows;
using internal::SampleTimes;
using internal::WrapAngle;

// Exogenous velocities of the other DOFs (truth aux_motion): offset + amplitude·sin(omega·t).
class SineAux final : public AuxVelocities {
 public:
  explicit SineAux(const std::map<char, AuxMotion>& motion) {
    for (const auto& [letter, m] : motion) {
      for (Dof d : kAllDofs) {
        if (VelocityLetter(d) == letter) motions_.push_back({Index(d), m});
      }
    }
  }
  void At(double t, std::array<double, kNumDofs>* v) const override {
    for (const auto& [i, m] : motions_) (*v)[i] = m.offset + m.amplitude * std::sin(m.omega * t);
  }

 private:
  std::vector<std::pair<int, AuxMotion>> motions_;
};

// Other DOFs' velocities that drive coupling terms, measured by their own sensors.
struct MeasuredVelocity {
  Dof dof;
  std::vector<double> t, y;
};
std::vector<MeasuredVelocity> MeasureAuxMotion(const Vehicle& v, Dof dof,
                                               const std::map<char, AuxMotion>& aux_motion,
                                               double duration, std::mt19937_64& rng) {
  std::vector<MeasuredVelocity> out;
  for (const auto& [letter, motion] : aux_motion) {
    for (Dof d : kAllDofs) {
      if (VelocityLetter(d) != letter || d == dof) continue;
      SensorSpec spec{10.0, 1e-3};
      if (auto s = v.sensors.find(d); s != v.sensors.end() && s->second.velocity) {
        spec = *s->second.velocity;
      }
      std::vector<double> t = SampleTimes(spec.rate_hz, duration);
      Eigen::VectorXd clean(t.size());
      for (std::size_t i = 0; i < t.size(); ++i) {
        clean[i] = motion.offset + motion.amplitude * std::sin(motion.omega * t[i]);
      }
      std::vector<double> y = Corrupt(clean, spec, SensorDefects{}, rng);
      out.push_back({d, std::move(t), std::move(y)});
    }
  }
  return out;
}

// One sensor of DOF i of a joint trial: its sample times and corrupted values of the state it
// sees (position: the DOF's position state, an angle wrapped; velocity: its velocity).
struct Sampled {
  std::vector<double> t, y;
};
Sampled MeasureJoint(const MultiDofModel& model, const Eigen::VectorXd& theta,
                     const JointConditions& conditions, int i, bool position,
                     const SensorSpec& spec, const Truth& truth, double duration,
                     std::mt19937_64& rng) {
  Sampled s;
  s.t = SampleTimes(spec.rate_hz, duration);
  SimulationOptions sim;
  sim.step_s = truth.integration_step_s;
  const Trajectory x = Simulate(model, theta, conditions, s.t, sim);
  s.y = Corrupt(x.x.col(model.state_offset(i) + (position ? 0 : 1)), spec, truth.defects, rng);
  if (position && IsRotational(model.dof(i))) {
    for (double& a : s.y) a = std::isnan(a) ? a : WrapAngle(a);
  }
  return s;
}

// The truth's model of a trial's DOF at its parameters (those it does not name at the
// standard model's neutral values), driven by the trial's commands held at the controller's
// rate from rest: what the virtual pool's sensors see before their noise.
class TruthRun {
 public:
  TruthRun(const Truth& truth, const TrialDesign& design, double start_time, double command_rate_hz)
      : model_(truth.vehicle, TruthStructure(truth, design.dof)),
        theta_(model_.Theta(Params(truth, design), &kNeutral)),
        commands_(HeldCommands(truth.vehicle, design, command_rate_hz)),
        held_(MakeHeldExcitation(commands_.t, commands_.force, commands_.mapping, design.duration)),
        aux_(truth.dofs.at(design.dof).aux_motion),
        conditions_{held_.get(), design.ballast_steps, start_time, &aux_} {
    sim_.step_s = truth.integration_step_s;
  }
  TruthRun(const TruthRun&) = delete;  // conditions_ points into it
  TruthRun& operator=(const TruthRun&) = delete;

  const Commands& commands() const { return commands_; }
  /// The state (position, velocity, ...) at `times` (s from the start).
  Trajectory At(const std::vector<double>& times) const {
    return SimulateMeasured(model_, theta_, conditions_, times, sim_);
  }

 private:
  static const std::map<std::string, double>& Params(const Truth& truth,
                                                     const TrialDesign& design) {
    const auto it = truth.dofs.find(design.dof);
    if (it == truth.dofs.end()) {
      throw InputError("truth", "no dofs." + std::string(DofName(design.dof)) +
                                    ".params for trial '" + design.id + "'");
    }
    return it->second.params;
  }
  inline static const std::map<std::string, double> kNeutral = {{param::kBias, 0.0},
                                                                {param::kQuadraticDrag, 0.0},
                                                                {param::kLinearDrag, 0.0},
                                                                {param::kBiasStep, 0.0}};

  DofModel model_;
  Eigen::VectorXd theta_;
  Commands commands_;
  std::unique_ptr<Excitation> held_;
  SineAux aux_;
  TrialConditions conditions_;
  SimulationOptions sim_;
};

}  // namespace

ModelStructure TruthStructure(const Truth& truth, Dof dof) {
  ModelStructure s;
  s.dof = dof;
  const auto it = truth.dofs.find(dof);
  if (it == truth.dofs.end()) return s;
  s.parameters.clear();
  for (const auto& [name, value] : it->second.params) {
    if (name != param::kMass) s.parameters.push_back(name);
  }
  s.settings = it->second.settings;
  return s;
}

TrialLog RunVirtualTrial(const Truth& truth, const TrialDesign& design, double start_time,
                         const VirtualPoolOptions& options) {
  const Vehicle& v = truth.vehicle;
  const Dof dof = design.dof;
  const auto sensors_it = v.sensors.find(dof);
  if (sensors_it == v.sensors.end() ||
      (!sensors_it->second.position && !sensors_it->second.velocity)) {
    throw InputError("vehicle '" + v.name + "'",
                     "sensors." + std::string(DofName(dof)) + ": no position or velocity sensor");
  }
  const DofSensors& sensors = sensors_it->second;
  const TruthRun run(truth, design, start_time, options.command_rate_hz);
  const Commands& cmd = run.commands();
  const std::vector<double>& cmd_t = cmd.t;
  const auto truth_it = truth.dofs.find(dof);

  std::mt19937_64 rng(SplitMix64(options.seed));
  std::vector<std::vector<double>> grids = {cmd_t};
  std::vector<double> pos_t, vel_t, pos_y, vel_y;
  if (sensors.position) {
    pos_t = SampleTimes(sensors.position->rate_hz, design.duration);
    const Trajectory y = run.At(pos_t);
    pos_y = Corrupt(y.x.col(0), *sensors.position, truth.defects, rng);
    if (IsRotational(dof)) {
      for (double& a : pos_y) a = std::isnan(a) ? a : WrapAngle(a);
    }
    grids.push_back(pos_t);
  }
  if (sensors.velocity) {
    vel_t = SampleTimes(sensors.velocity->rate_hz, design.duration);
    const Trajectory y = run.At(vel_t);
    vel_y = Corrupt(y.x.col(1), *sensors.velocity, truth.defects, rng);
    grids.push_back(vel_t);
  }
  const std::vector<MeasuredVelocity> aux_measured =
      MeasureAuxMotion(v, dof, truth_it->second.aux_motion, design.duration, rng);
  for (const auto& a : aux_measured) grids.push_back(a.t);

  TrialLog log;
  log.t = MergeTimes(grids);
  log.force[Index(dof)] = OnRows(log.t, cmd_t, cmd.force);
  if (sensors.position) log.position[Index(dof)] = OnRows(log.t, pos_t, pos_y);
  if (sensors.velocity) log.velocity[Index(dof)] = OnRows(log.t, vel_t, vel_y);
  for (const auto& a : aux_measured) log.velocity[Index(a.dof)] = OnRows(log.t, a.t, a.y);
  LogMappingColumn(v, cmd, &log);
  return log;
}

std::array<double, 2> TrueTravel(const Truth& truth, const TrialDesign& design, double start_time,
                                 double command_rate_hz) {
  const TruthRun run(truth, design, start_time, command_rate_hz);
  constexpr double kSampleHz = 20.0;  // 0.05 s: a few mm of a trial's steepest motion
  const Trajectory x = run.At(SampleTimes(kSampleHz, design.duration));
  return {x.x.col(0).minCoeff(), x.x.col(0).maxCoeff()};
}

TrialLog RunCombinedTrial(const Truth& truth, const MultiDofModel& model,
                          const Eigen::VectorXd& theta, const CombinedTrialDesign& design,
                          const VirtualPoolOptions& options) {
  if (const std::string error = design.Check(); !error.empty()) throw InputError(error);
  const int n = model.num_dofs();
  std::vector<Commands> cmd(n);
  std::vector<std::unique_ptr<Excitation>> held(n);
  JointConditions conditions;
  conditions.inputs.assign(n, nullptr);
  std::vector<std::vector<double>> grids;
  for (const TrialDesign& input : design.inputs) {
    const int i = model.DofIndex(input.dof);
    if (i < 0)
      throw InputError(design.id,
                       "moves " + std::string(DofName(input.dof)) + ", not in the model");
    TrialDesign whole = input;
    whole.duration = design.duration;
    cmd[i] = HeldCommands(truth.vehicle, whole, options.command_rate_hz);
    held[i] = MakeHeldExcitation(cmd[i].t, cmd[i].force, cmd[i].mapping, design.duration);
    conditions.inputs[i] = held[i].get();
  }
  for (const Commands& c : cmd) {
    if (!c.t.empty()) grids.push_back(c.t);
  }
  std::mt19937_64 rng(SplitMix64(options.seed));
  std::vector<Sampled> pos(n), vel(n);
  for (int i = 0; i < n; ++i) {
    const auto sensors = truth.vehicle.sensors.find(model.dof(i));
    if (sensors == truth.vehicle.sensors.end()) continue;
    for (const bool position : {true, false}) {
      const auto& spec = position ? sensors->second.position : sensors->second.velocity;
      if (!spec) continue;
      Sampled& s = position ? pos[i] : vel[i];
      s = MeasureJoint(model, theta, conditions, i, position, *spec, truth, design.duration, rng);
      grids.push_back(s.t);
    }
  }
  TrialLog log;
  log.t = MergeTimes(grids);
  for (int i = 0; i < n; ++i) {
    const int column = Index(model.dof(i));
    log.force[column] = cmd[i].t.empty() ? std::vector<double>(log.t.size(), 0.0)
                                         : OnRows(log.t, cmd[i].t, cmd[i].force);
    if (!pos[i].t.empty()) log.position[column] = OnRows(log.t, pos[i].t, pos[i].y);
    if (!vel[i].t.empty()) log.velocity[column] = OnRows(log.t, vel[i].t, vel[i].y);
  }
  return log;
}

}  // namespace uuvplan::model
