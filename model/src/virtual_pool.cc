#include "uuvplan/model/virtual_pool.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <random>

#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/io.h"
#include "uuvplan/model/simulator.h"

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

// splitmix64: independent, reproducible seeds per trial and per sensor from one user seed.
std::uint64_t Mix(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

std::vector<double> SampleTimes(double rate_hz, double duration) {
  std::vector<double> t;
  const double dt = 1.0 / rate_hz;
  for (long k = 0; k * dt <= duration + 1e-9; ++k) t.push_back(k * dt);
  return t;
}

double WrapAngle(double a) {
  double w = std::remainder(a, 2 * M_PI);  // (-pi, pi]
  if (w <= -M_PI) w += 2 * M_PI;
  return w;
}

// Noisy samples with drop-outs (NaN) and multipath outliers (seed 000 Fig. 14).
std::vector<double> Corrupt(const Eigen::VectorXd& clean, const SensorSpec& spec,
                            const SensorDefects& defects, std::mt19937_64& rng) {
  std::normal_distribution<double> noise(0.0, spec.sigma);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  const double outlier = defects.outlier_size > 0 ? defects.outlier_size : 20.0 * spec.sigma;
  std::vector<double> y(clean.size());
  for (Eigen::Index i = 0; i < clean.size(); ++i) {
    y[i] = clean[i] + noise(rng);
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

  // Commands at the controller rate, held between rows; every change of a segment is a row.
  const auto designed = MakeExcitation(v, design);
  std::vector<double> cmd_t = SampleTimes(options.command_rate_hz, design.duration);
  for (double b : designed->Breakpoints()) cmd_t.push_back(b);
  std::sort(cmd_t.begin(), cmd_t.end());
  cmd_t.erase(std::unique(cmd_t.begin(), cmd_t.end(),
                          [](double a, double b) { return std::abs(a - b) < 1e-9; }),
              cmd_t.end());
  std::vector<double> cmd_f(cmd_t.size());
  std::vector<int> cmd_m(cmd_t.size());
  for (std::size_t i = 0; i < cmd_t.size(); ++i) {
    cmd_f[i] = designed->Force(cmd_t[i]);
    cmd_m[i] = designed->Mapping(cmd_t[i]);
  }
  const auto held = MakeHeldExcitation(cmd_t, cmd_f, cmd_m, design.duration);
  const SineAux aux(truth_it->second.aux_motion);
  TrialConditions conditions{held.get(), design.ballast_steps, start_time, &aux};
  SimulationOptions sim;
  sim.step_s = truth.integration_step_s;

  std::mt19937_64 rng(Mix(options.seed));
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
  // Other DOFs' velocities that drive coupling terms, measured by their own sensors.
  std::vector<std::pair<Dof, std::vector<double>>> aux_t, aux_y;
  for (const auto& [letter, motion] : truth_it->second.aux_motion) {
    for (Dof d : kAllDofs) {
      if (VelocityLetter(d) != letter || d == dof) continue;
      SensorSpec spec{10.0, 1e-3};
      if (auto s = v.sensors.find(d); s != v.sensors.end() && s->second.velocity) {
        spec = *s->second.velocity;
      }
      std::vector<double> t = SampleTimes(spec.rate_hz, design.duration);
      Eigen::VectorXd clean(t.size());
      for (std::size_t i = 0; i < t.size(); ++i) {
        clean[i] = motion.offset + motion.amplitude * std::sin(motion.omega * t[i]);
      }
      aux_y.push_back({d, Corrupt(clean, spec, SensorDefects{}, rng)});
      aux_t.push_back({d, t});
      grids.push_back(t);
    }
  }

  TrialLog log;
  log.t = MergeTimes(grids);
  log.force[Index(dof)] = OnRows(log.t, cmd_t, cmd_f);
  if (sensors.position) log.position[Index(dof)] = OnRows(log.t, pos_t, pos_y);
  if (sensors.velocity) log.velocity[Index(dof)] = OnRows(log.t, vel_t, vel_y);
  for (std::size_t k = 0; k < aux_t.size(); ++k) {
    log.velocity[Index(aux_t[k].first)] = OnRows(log.t, aux_t[k].second, aux_y[k].second);
  }
  const bool mapping_varies =
      std::any_of(cmd_m.begin(), cmd_m.end(), [&](int m) { return m != cmd_m.front(); });
  if (mapping_varies) {
    for (const auto& m : v.mappings) log.mapping_names.push_back(m.name);
    std::vector<double> as_double(cmd_m.begin(), cmd_m.end());
    const std::vector<double> col = OnRows(log.t, cmd_t, as_double);
    log.mapping.resize(col.size());
    for (std::size_t i = 0; i < col.size(); ++i) {
      log.mapping[i] = std::isnan(col[i]) ? -1 : static_cast<int>(col[i]);
    }
  }
  return log;
}

Campaign SimulateCampaign(const Truth& truth, const std::vector<TrialDesign>& designs,
                          const std::string& out_dir, const VirtualPoolOptions& options,
                          double pause_s) {
  namespace fs = std::filesystem;
  // "dir/" and "dir" are the same directory; the temporary sibling must be beside it.
  fs::path out = fs::path(out_dir).lexically_normal();
  if (out.filename().empty()) out = out.parent_path();
  std::error_code ec;
  if (fs::exists(out) && !fs::is_empty(out, ec)) {
    throw InputError(out_dir, "output directory exists and is not empty; choose a new --out "
                              "(nothing is overwritten)");
  }
  // Everything is written to a sibling temporary directory first, then renamed into place,
  // so a campaign is written whole or not at all.
  const fs::path tmp = out.string() + ".tmp-uuvplan";
  fs::remove_all(tmp, ec);
  fs::create_directories(tmp / "trials", ec);
  if (ec) throw InputError(out_dir, "cannot create directory: " + ec.message());

  Campaign campaign;
  campaign.path = (out / "campaign.yaml").string();
  campaign.vehicle_file = "vehicle.yaml";
  campaign.vehicle = truth.vehicle;
  double clock = 0.0;
  try {
    for (std::size_t i = 0; i < designs.size(); ++i) {
      VirtualPoolOptions o = options;
      o.seed = Mix(options.seed ^ Mix(i + 1));
      TrialEntry e;
      e.file = "trials/" + designs[i].id + ".csv";
      e.path = (out / e.file).string();
      e.dof = designs[i].dof;
      e.mapping = designs[i].mapping;
      e.ballast_steps = designs[i].ballast_steps;
      e.start = clock;
      e.has_start = true;
      e.log = RunVirtualTrial(truth, designs[i], clock, o);
      WriteTrialLog((tmp / e.file).string(), e.log,
                    "uuvplan virtual pool: truth vehicle '" + truth.vehicle.name + "', trial '" +
                        designs[i].id + "', seed " + std::to_string(options.seed));
      campaign.trials.push_back(std::move(e));
      clock += designs[i].duration + pause_s;
    }
    WriteVehicleYaml((tmp / "vehicle.yaml").string(), truth.vehicle);
    WriteCampaignYaml((tmp / "campaign.yaml").string(), campaign);
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
  if (fs::exists(out)) fs::remove(out, ec);
  fs::rename(tmp, out, ec);
  if (ec) {
    fs::remove_all(tmp, ec);
    throw InputError(out_dir, "cannot move the campaign into place: " + ec.message());
  }
  return campaign;
}

}  // namespace uuvplan::model
