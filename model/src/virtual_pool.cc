#include "uuvplan/model/virtual_pool.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/simulator.h"
#include "uuvplan/model/util/checked_count.h"
#include "uuvplan/model/util/seed.h"

namespace uuvplan::model {
namespace {

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

std::vector<double> SampleTimes(double rate_hz, double duration) {
  const long n = CheckedFloor(duration * rate_hz, "virtual pool samples (duration × rate)",
                              limits::kMaxTrialRows, "a shorter trial or a lower sensor rate");
  std::vector<double> t;
  t.reserve(static_cast<std::size_t>(n) + 2);
  const double dt = 1.0 / rate_hz;
  for (long k = 0; k * dt <= duration + 1e-9; ++k) t.push_back(k * dt);
  return t;
}

double WrapAngle(double a) {
  double w = std::remainder(a, 2 * M_PI);  // (-pi, pi]
  if (w <= -M_PI) w += 2 * M_PI;
  return w;
}

// Noisy samples with drop-outs (NaN) and multipath outliers (seed 000 Fig. 14). The noise is
// AR(1), e_i = ρ·e_{i−1} + √(1 − ρ²)·σ·n_i with e_0 = σ·n_0 (stationary; ρ = 0: white, the same
// draws as before the option existed).
std::vector<double> Corrupt(const Eigen::VectorXd& clean, const SensorSpec& spec,
                            const SensorDefects& defects, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, spec.sigma);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double outlier = defects.outlier_size > 0 ? defects.outlier_size : 20.0 * spec.sigma;
  const double rho = defects.noise_ar1;
  const double innovation = std::sqrt(1.0 - rho * rho);
  std::vector<double> y(clean.size());
  double e = 0.0;
  for (Eigen::Index i = 0; i < clean.size(); ++i) {
    e = i == 0 ? noise(rng) : rho * e + innovation * noise(rng);
    y[i] = clean[i] + e;
    if (u(rng) < defects.outlier_probability) y[i] += (u(rng) < 0.5 ? -1 : 1) * outlier;
    if (i > 0 && u(rng) < defects.dropout_probability) y[i] = std::nan("");
  }
  return y;
}

// Merges sorted time grids into the log's rows and returns, for each grid, its row indices.
std::vector<double> MergeTimes(const std::vector<std::vector<double>>& grids) {
  std::vector<double> all;
  for (const auto& g : grids) all.insert(all.end(), g.begin(), g.end());
  std::sort(all.begin(), all.end());
  std::vector<double> rows;
  for (double t : all) {
    if (rows.empty() || t - rows.back() > 1e-9) rows.push_back(t);
  }
  return rows;
}

std::vector<double> OnRows(const std::vector<double>& rows, const std::vector<double>& t,
                           const std::vector<double>& v) {
  std::vector<double> col(rows.size(), std::nan(""));
  std::size_t r = 0;
  for (std::size_t i = 0; i < t.size(); ++i) {
    while (rows[r] < t[i] - 1e-9) ++r;
    col[r] = v[i];
  }
  return col;
}

// The commands as logged: at the controller rate, held between rows; every change of a
// segment is a row.
struct Commands {
  std::vector<double> t, force;
  std::vector<int> mapping;
};
Commands HeldCommands(const Vehicle& v, const TrialDesign& design, double rate_hz) {
  const auto designed = MakeExcitation(v, design);
  Commands cmd;
  cmd.t = SampleTimes(rate_hz, design.duration);
  for (double b : designed->Breakpoints()) cmd.t.push_back(b);
  std::sort(cmd.t.begin(), cmd.t.end());
  cmd.t.erase(std::unique(cmd.t.begin(), cmd.t.end(),
                          [](double a, double b) { return std::abs(a - b) < 1e-9; }),
              cmd.t.end());
  cmd.force.resize(cmd.t.size());
  cmd.mapping.resize(cmd.t.size());
  for (std::size_t i = 0; i < cmd.t.size(); ++i) {
    cmd.force[i] = designed->Force(cmd.t[i]);
    cmd.mapping[i] = designed->Mapping(cmd.t[i]);
  }
  return cmd;
}

// The mapping column, only when the commanded mapping changes during the trial.
void LogMappingColumn(const Vehicle& v, const Commands& cmd, TrialLog* log) {
  const bool mapping_varies = std::any_of(cmd.mapping.begin(), cmd.mapping.end(),
                                          [&](int m) { return m != cmd.mapping.front(); });
  if (!mapping_varies) return;
  for (const auto& m : v.mappings) log->mapping_names.push_back(m.name);
  std::vector<double> as_double(cmd.mapping.begin(), cmd.mapping.end());
  const std::vector<double> col = OnRows(log->t, cmd.t, as_double);
  log->mapping.resize(col.size());
  for (std::size_t i = 0; i < col.size(); ++i) {
    log->mapping[i] = std::isnan(col[i]) ? -1 : static_cast<int>(col[i]);
  }
}

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
  const auto truth_it = truth.dofs.find(dof);
  if (truth_it == truth.dofs.end()) {
    throw InputError("truth", "no dofs." + std::string(DofName(dof)) +
                                  ".params for trial '" + design.id + "'");
  }
  const auto sensors_it = v.sensors.find(dof);
  if (sensors_it == v.sensors.end() ||
      (!sensors_it->second.position && !sensors_it->second.velocity)) {
    throw InputError("vehicle '" + v.name + "'",
                     "sensors." + std::string(DofName(dof)) + ": no position or velocity sensor");
  }
  const DofSensors& sensors = sensors_it->second;

  // The truth model; parameters it does not name take the standard model's neutral values.
  const DofModel model(v, TruthStructure(truth, dof));
  const std::map<std::string, double> neutral = {{param::kBias, 0.0}, {param::kQuadraticDrag, 0.0},
                                                 {param::kLinearDrag, 0.0}, {param::kBiasStep, 0.0}};
  const Eigen::VectorXd theta = model.Theta(truth_it->second.params, &neutral);

  const Commands cmd = HeldCommands(v, design, options.command_rate_hz);
  const std::vector<double>& cmd_t = cmd.t;
  const auto held = MakeHeldExcitation(cmd.t, cmd.force, cmd.mapping, design.duration);
  const SineAux aux(truth_it->second.aux_motion);
  TrialConditions conditions{held.get(), design.ballast_steps, start_time, &aux};
  SimulationOptions sim;
  sim.step_s = truth.integration_step_s;

  std::mt19937_64 rng(SplitMix64(options.seed));
  std::vector<std::vector<double>> grids = {cmd_t};
  std::vector<double> pos_t, vel_t, pos_y, vel_y;
  if (sensors.position) {
    pos_t = SampleTimes(sensors.position->rate_hz, design.duration);
    const Trajectory y = SimulateMeasured(model, theta, conditions, pos_t, sim);
    pos_y = Corrupt(y.x.col(0), *sensors.position, truth.defects, rng);
    if (IsRotational(dof)) {
      for (double& a : pos_y) a = std::isnan(a) ? a : WrapAngle(a);
    }
    grids.push_back(pos_t);
  }
  if (sensors.velocity) {
    vel_t = SampleTimes(sensors.velocity->rate_hz, design.duration);
    const Trajectory y = SimulateMeasured(model, theta, conditions, vel_t, sim);
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

}  // namespace uuvplan::model
