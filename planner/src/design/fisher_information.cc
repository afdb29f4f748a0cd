// Fisher information of a trial from the forward sensitivities (see fisher_information.h).
#include "uuvplan/planner/design/fisher_information.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "design/sensor_information.h"
#include "uuvplan/model/simulator.h"
#include "uuvplan/model/util/checked_count.h"

namespace uuvplan::planner {
namespace {

struct Sample {
  double t;
  int channel;    // the state the sensor sees (1-DOF: 0 position, 1 velocity)
  double weight;  // w_k / sigma²
};

void AddSensor(const model::SensorSpec& spec, int channel, double duration,
               std::vector<Sample>* samples) {
  if (!(spec.rate_hz > 0) || !(spec.sigma > 0)) {
    throw std::invalid_argument("sensor rate and sigma must be > 0");
  }
  const double inv_var = SampleInformation(spec);
  const double span = duration * spec.rate_hz;
  const long whole =
      model::CheckedFloor(span, "sensor samples (duration × rate)", model::limits::kMaxTrialRows,
                          "a shorter trial or a lower sensor rate");
  for (long k = 0; k <= whole; ++k) samples->push_back({k / spec.rate_hz, channel, inv_var});
  const double frac = span - whole;
  if (frac > 1e-9) samples->push_back({(whole + 1) / spec.rate_hz, channel, frac * inv_var});
}

// Every sensor sample and the end of the trial (weight 0: for the extremes only), sorted;
// `times` the distinct sample times (the simulation's outputs) and row[i] sample i's among them.
struct SampleGrid {
  std::vector<Sample> samples;
  std::vector<double> times;
  std::vector<int> row;
};

SampleGrid GridOf(std::vector<Sample> samples, double duration) {
  if (samples.empty()) throw std::invalid_argument("the DOF has no position or velocity sensor");
  SampleGrid g;
  g.samples = std::move(samples);
  g.samples.push_back({duration, 0, 0.0});
  std::sort(g.samples.begin(), g.samples.end(),
            [](const Sample& a, const Sample& b) { return a.t < b.t; });
  g.row.resize(g.samples.size());
  for (std::size_t i = 0; i < g.samples.size(); ++i) {
    if (g.times.empty() || g.samples[i].t > g.times.back() + 1e-12)
      g.times.push_back(g.samples[i].t);
    g.row[i] = static_cast<int>(g.times.size()) - 1;
  }
  return g;
}

// Σ_k rowᵀ·row over the first n rows of `weighted` (each √(w_k)/σ times ∂y_k/∂θ).
Eigen::MatrixXd Gram(const Eigen::MatrixXd& weighted, int n) {
  Eigen::MatrixXd full = Eigen::MatrixXd::Zero(weighted.cols(), weighted.cols());
  full.selfadjointView<Eigen::Lower>().rankUpdate(weighted.topRows(n).transpose());
  return full.selfadjointView<Eigen::Lower>();
}

// The position and velocity extremes over [0, duration] and the final velocity.
void AddExtremes(const model::Trajectory& traj, const std::vector<double>& times, double duration,
                 TrialResponse* r) {
  r->position_min = r->position_max = 0.0;
  r->velocity_min = r->velocity_max = 0.0;
  for (std::size_t i = 0; i < times.size() && times[i] <= duration + 1e-12; ++i) {
    r->position_min = std::min(r->position_min, traj.x(i, 0));
    r->position_max = std::max(r->position_max, traj.x(i, 0));
    r->velocity_min = std::min(r->velocity_min, traj.x(i, 1));
    r->velocity_max = std::max(r->velocity_max, traj.x(i, 1));
    if (std::abs(times[i] - duration) < 1e-12) r->final_velocity = traj.x(i, 1);
  }
}

// M = Mθθ − Mθn·Mnn⁺·Mnθ of the information `full` of (θ, nuisance): θ's first np rows.
Eigen::MatrixXd ProfiledOut(const Eigen::MatrixXd& full, int np) {
  const int nn = static_cast<int>(full.rows()) - np;
  const Eigen::MatrixXd Mtn = full.topRightCorner(np, nn);
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> Mnn(full.bottomRightCorner(nn, nn));
  const Eigen::MatrixXd M = full.topLeftCorner(np, np) - Mtn * Mnn.solve(Mtn.transpose());
  return 0.5 * (M + M.transpose());
}

}  // namespace

double ChooseStep(double shortest_time_constant_s, double max_step_s) {
  double h = kStepPerTimeConstant * shortest_time_constant_s;
  if (!(h > 0) || !std::isfinite(h)) h = max_step_s;
  return std::min(h, max_step_s);
}

TrialResponse SimulateTrial(const model::DofModel& model, const Eigen::VectorXd& theta,
                            const model::Excitation& input, const model::DofSensors& sensors,
                            double duration, double step_s, bool with_information,
                            bool start_known) {
  std::vector<Sample> sensor_samples;
  if (sensors.position) AddSensor(*sensors.position, 0, duration, &sensor_samples);
  if (sensors.velocity) AddSensor(*sensors.velocity, 1, duration, &sensor_samples);
  const SampleGrid g = GridOf(std::move(sensor_samples), duration);

  model::TrialConditions conditions;
  conditions.input = &input;
  model::SimulationOptions options;
  options.step_s = step_s;
  options.sensitivities = with_information;
  // ∂y/∂ξ0 (below) as the sensitivities' last column, and each step at most half the local
  // time constant (ChooseStep's rule where the trial is, not at the box's fastest point).
  options.initial_velocity_column = with_information && !start_known;
  options.time_constant_fraction = with_information ? kStepPerTimeConstant : 0.0;
  const model::Trajectory traj =
      model::SimulateMeasured(model, theta, conditions, g.times, options);
  TrialResponse r;
  AddExtremes(traj, g.times, duration, &r);
  if (!with_information) return r;

  // The information the identification can use: its output error
  // (ident/src/estimators/output_error.cc) fits each trial's initial state with θ — the initial
  // position χ0 whenever a position sensor is used, the initial velocity ξ0 unless the log is
  // judged to start at rest — as ref 000's integral method (eqs. 16-19) fits m·ξ0 + k·χ0. Known
  // exactly here, they lent a steady run the position lag v·m/k_L of its whole plateau as
  // information on m (payload60 yaw-next-15: σ(m) predicted 0.053, achieved 0.50 kg·m²). So they
  // are nuisance parameters, profiled out:
  //   M = Mθθ − Mθn·Mnn⁺·Mnθ   of the information of (θ, χ0, ξ0),
  // with ∂y/∂χ0 = (1, 0) (no force depends on the position) and ∂y/∂ξ0 = S_ξ0 from
  // dS_ξ0/dt = A·S_ξ0, S_ξ0(0) = (0, 1) (the simulation's last sensitivity column). ξ0 is profiled
  // out even where the output error would fix it at 0: a start judged at rest is only at rest
  // within the test's resolution, and the information a known ξ0 adds (a steady run's start-up
  // curvature) is what an undetected residual velocity biases (payload60 yaw: 0.01 rad/s moves m
  // by 1.4 σ of that information).
  const int np = model.num_parameters();
  const bool free_chi0 = static_cast<bool>(sensors.position) && !start_known;
  const int nn = start_known ? 0 : (free_chi0 ? 1 : 0) + 1;
  // M = Σ_k w_k/σ² · s_kᵀ s_k, s_k the row of ∂y/∂(theta, χ0, ξ0) of the sample's channel.
  Eigen::MatrixXd weighted(g.samples.size(), np + nn);
  int n = 0;
  for (std::size_t i = 0; i < g.samples.size(); ++i) {
    if (g.samples[i].weight <= 0) continue;
    const double w = std::sqrt(g.samples[i].weight);
    const int c = g.samples[i].channel, k = g.row[i];
    weighted.row(n).head(np) = w * traj.S[c].row(k).head(np);
    int col = np;
    if (free_chi0) weighted(n, col++) = c == 0 ? w : 0.0;
    if (!start_known) weighted(n, col) = w * traj.S[c](k, np);
    ++n;
  }
  Eigen::MatrixXd full = Gram(weighted, n);
  if (start_known) {  // the block of θ: no nuisance column was made
    r.M = std::move(full);
    return r;
  }
  r.M = ProfiledOut(full, np);
  r.M_joint = std::move(full);
  return r;
}

Eigen::MatrixXd JointInformation(const model::MultiDofModel& model, const Eigen::VectorXd& theta,
                                 const model::JointConditions& conditions,
                                 const std::map<model::Dof, model::DofSensors>& sensors,
                                 double duration, double step_s) {
  std::vector<Sample> sensor_samples;
  for (int i = 0; i < model.num_dofs(); ++i) {
    const auto s = sensors.find(model.dof(i));
    if (s == sensors.end()) continue;
    const int position = model.state_offset(i);
    if (s->second.position) AddSensor(*s->second.position, position, duration, &sensor_samples);
    if (s->second.velocity) AddSensor(*s->second.velocity, position + 1, duration, &sensor_samples);
  }
  const SampleGrid g = GridOf(std::move(sensor_samples), duration);
  model::SimulationOptions options;
  options.step_s = step_s;
  options.sensitivities = true;
  const model::Trajectory traj = model::Simulate(model, theta, conditions, g.times, options);
  Eigen::MatrixXd weighted(g.samples.size(), model.num_parameters());
  int n = 0;
  for (std::size_t i = 0; i < g.samples.size(); ++i) {
    if (g.samples[i].weight <= 0) continue;
    weighted.row(n++) = std::sqrt(g.samples[i].weight) * traj.S[g.samples[i].channel].row(g.row[i]);
  }
  return Gram(weighted, n);
}

PositionTrace TracePosition(const model::DofModel& model, const Eigen::VectorXd& theta,
                            const model::Excitation& input, double duration, double dt,
                            double step_s) {
  PositionTrace trace;
  trace.dt = dt;
  const long n = model::CheckedCount(duration / dt, "position trace samples (duration / dt)",
                                     model::limits::kMaxTrialRows, "a shorter trial");
  std::vector<double> times(n + 1);
  for (long i = 0; i <= n; ++i) times[i] = std::min(i * dt, duration);
  model::TrialConditions conditions;
  conditions.input = &input;
  model::SimulationOptions options;
  options.step_s = step_s;
  const model::Trajectory traj = model::Simulate(model, theta, conditions, times, options);
  trace.position.resize(n + 1);
  trace.velocity.resize(n + 1);
  for (long i = 0; i <= n; ++i) {
    trace.position[i] = traj.x(i, 0);
    trace.velocity[i] = traj.x(i, 1);
  }
  return trace;
}

TrialResponse SimulateExcursion(const model::DofModel& model, const Eigen::VectorXd& theta,
                                const model::Excitation& input, double duration, double step_s) {
  const PositionTrace trace = TracePosition(model, theta, input, duration, step_s, step_s);
  TrialResponse r;
  for (std::size_t i = 0; i < trace.position.size(); ++i) {
    r.position_min = std::min(r.position_min, trace.position[i]);
    r.position_max = std::max(r.position_max, trace.position[i]);
    r.velocity_min = std::min(r.velocity_min, trace.velocity[i]);
    r.velocity_max = std::max(r.velocity_max, trace.velocity[i]);
  }
  if (!trace.velocity.empty()) r.final_velocity = trace.velocity.back();
  return r;
}

}  // namespace uuvplan::planner
