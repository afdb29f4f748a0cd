// Combined-mode sine designs for the coupled horizontal model (see coupled_design.h).
#include "uuvplan/planner/design/coupled_design.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>

#include "design/sensor_information.h"
#include "uuvplan/model/coupled_simulator.h"
#include "uuvplan/model/input_error.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/seed.h"
#include "uuvplan/planner/design/centred_travel.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner {
namespace {

using model::CoupledHorizontalModel;
using model::Horizontal;

constexpr double kTwoPi = 2.0 * M_PI;
// m kept free beyond the track at each wall: the planner's 0.2 s RK4 track differs from a
// 0.01 s one by < 1 cm (ASV sway+yaw design, 2026-11-27).
constexpr double kTrackSlack = 0.05;

// τ = [X, Y, N] of a combined trial: each moved DOF's nominal force, η = 1 (the mappings a
// combined design uses work in open water both ways, CombinedMappingOf).
Horizontal Thrust(const model::CoupledTrialDesign& trial, double t) {
  Horizontal tau = Horizontal::Zero();
  for (const model::TrialDesign& in : trial.inputs) {
    tau[model::HorizontalIndex(in.dof)] = in.NominalForce(t);
  }
  return tau;
}

model::CoupledTrajectory Simulate(const CoupledHorizontalModel& model,
                                  const model::CoupledTrialDesign& trial,
                                  const std::vector<double>& t, double step_s) {
  return model::SimulateCoupled(
      model, [&](double s) { return Thrust(trial, s); }, Horizontal::Zero(), t, {}, step_s);
}

// What the vehicle measures of the horizontal DOFs: (DOF index, position or velocity, weight
// per sample of the planner's grid = rate·dt/σ², the information density of the sensor).
struct Output {
  int i = 0;
  bool position = false;
  double weight = 0.0;
};
std::vector<Output> Outputs(const model::Vehicle& vehicle, double dt) {
  std::vector<Output> out;
  for (int i = 0; i < 3; ++i) {
    const auto s = vehicle.sensors.find(model::kHorizontalDofs[i]);
    if (s == vehicle.sensors.end()) continue;
    if (s->second.position) out.push_back({i, true, InformationOver(*s->second.position, dt)});
    if (s->second.velocity) out.push_back({i, false, InformationOver(*s->second.velocity, dt)});
  }
  return out;
}

double Measured(const model::CoupledTrajectory& x, const Output& o, std::size_t k) {
  return o.position ? x.pose[k][o.i] : x.nu[k][o.i];
}

std::vector<double> Grid(double duration, double dt) {
  std::vector<double> t;
  const int n = static_cast<int>(std::floor(duration / dt + 1e-9));
  for (int k = 0; k <= n; ++k) t.push_back(k * dt);
  return t;
}

// The θ indices the criterion covers: every parameter of the DOFs the mode moves.
std::vector<int> CoveredParameters(model::CombinedMode mode) {
  std::vector<int> out;
  for (int i = 0; i < 3; ++i) {
    if (!model::ModeMoves(mode, model::kHorizontalDofs[i])) continue;
    for (const char* p : model::kCoupledDofParameters) out.push_back(model::CoupledIndex(i, p));
  }
  return out;
}

// Fisher information of the covered parameters at `model`, in units scaled by `scale`
// (forward differences of the simulated outputs, relative step 1e-6).
Eigen::MatrixXd Information(const CoupledHorizontalModel& model,
                            const model::CoupledTrialDesign& trial, const std::vector<int>& covered,
                            const Eigen::VectorXd& scale, const std::vector<Output>& outputs,
                            const std::vector<double>& t, double step_s) {
  const model::CoupledTrajectory base = Simulate(model, trial, t, step_s);
  const int p = static_cast<int>(covered.size());
  std::vector<model::CoupledTrajectory> moved;
  std::vector<double> h(p);
  for (int c = 0; c < p; ++c) {
    CoupledHorizontalModel m = model;
    h[c] = 1e-6 * scale[c];
    m.theta[covered[c]] += h[c];
    moved.push_back(Simulate(m, trial, t, step_s));
  }
  Eigen::MatrixXd F = Eigen::MatrixXd::Zero(p, p);
  Eigen::VectorXd g(p);
  for (const Output& o : outputs) {
    for (std::size_t k = 0; k < t.size(); ++k) {
      const double y = Measured(base, o, k);
      for (int c = 0; c < p; ++c) g[c] = (Measured(moved[c], o, k) - y) / h[c] * scale[c];
      F.noalias() += o.weight * g * g.transpose();
    }
  }
  return F;
}

// (1/p)·log det F, or −∞ when F is not positive definite (a parameter the design does not
// excite).
double LogDetPerParameter(const Eigen::MatrixXd& F) {
  const Eigen::LLT<Eigen::MatrixXd> llt(F);
  if (llt.info() != Eigen::Success) return -std::numeric_limits<double>::infinity();
  return 2.0 * llt.matrixLLT().diagonal().array().log().sum() / static_cast<double>(F.rows());
}

// Scale of each covered parameter: its nominal magnitude; a bias's 1% of the DOF's largest
// force (nominal 0).
Eigen::VectorXd Scales(const CoupledHorizontalModel& nominal, const std::vector<int>& covered,
                       const std::array<double, 3>& force_max) {
  Eigen::VectorXd s(covered.size());
  for (std::size_t c = 0; c < covered.size(); ++c) {
    const double v = std::abs(nominal.theta[covered[c]]);
    s[c] = v > 0 ? v : 0.01 * force_max[covered[c] / 4];
  }
  return s;
}

// Largest |φ| the DOF's mapping gives both ways (thrust_limits.h).
double ForceMax(const model::Vehicle& vehicle, int mapping) {
  const ForceRange pos = DirectionForceRange(vehicle, mapping, +1);
  const ForceRange neg = DirectionForceRange(vehicle, mapping, -1);
  return std::min(pos.max_abs, neg.max_abs);
}

// Design variables, each in [0, 1] or [−1, 1], per moved DOF: offset/F, amplitude/F, and
// (ω − ω_min)/(ω_max − ω_min).
model::CoupledTrialDesign TrialOf(const double* x, const std::vector<int>& moved,
                                  const std::array<int, 3>& mapping,
                                  const std::array<double, 3>& force_max,
                                  const model::Vehicle& vehicle, const CoupledDesignOptions& o) {
  model::CoupledTrialDesign trial;
  trial.id = std::string("combined-") + std::string(model::kCombinedModeNames.Name(o.mode));
  trial.mode = o.mode;
  trial.duration = o.duration_s;
  for (std::size_t d = 0; d < moved.size(); ++d) {
    const int i = moved[d];
    model::TrialDesign in;
    in.dof = model::kHorizontalDofs[i];
    in.kind = model::TrialKind::kSine;
    in.mapping = vehicle.mappings[mapping[i]].name;
    in.duration = o.duration_s;
    in.offset = x[3 * d] * force_max[i];
    in.amplitude = x[3 * d + 1] * force_max[i];
    in.omega = o.omega_min + x[3 * d + 2] * (o.omega_max - o.omega_min);
    trial.inputs.push_back(in);
  }
  return trial;
}

// The thrusters with a non-zero share in a mapping the trial uses (the others are idle).
std::vector<bool> WorkingThrusters(const model::Vehicle& vehicle,
                                   const model::CoupledTrialDesign& trial) {
  std::vector<bool> works(vehicle.thrusters.size(), false);
  for (const model::TrialDesign& in : trial.inputs) {
    for (const auto& [ti, share] : vehicle.mappings[vehicle.MappingIndex(in.mapping)].shares) {
      works[ti] = works[ti] || share != 0.0;
    }
  }
  return works;
}

// Thruster side of the envelope: the sign-kept margin over min_thrust and the load, from the
// nominal force profile (the forces do not depend on the vehicle's parameters).
void ThrustEnvelope(const model::Vehicle& vehicle, const model::CoupledTrialDesign& trial,
                    double step_s, CoupledEnvelope* e) {
  const std::size_t n = vehicle.thrusters.size();
  const double inf = std::numeric_limits<double>::infinity();
  std::vector<double> lo(n, inf), hi(n, -inf);
  const std::vector<bool> works = WorkingThrusters(vehicle, trial);
  e->thrust_margin = std::numeric_limits<double>::infinity();
  e->thrust_load = 0.0;
  e->closed_water_force = 0.0;
  for (double t : Grid(trial.duration, step_s)) {
    for (const model::TrialDesign& in : trial.inputs) {
      const double phi = in.NominalForce(t);
      const auto& m = vehicle.mappings[vehicle.MappingIndex(in.mapping)];
      if (phi != 0.0 && !m.IsOpenWater(phi > 0 ? model::Direction::kPos : model::Direction::kNeg)) {
        e->closed_water_force = std::max(e->closed_water_force, std::abs(phi));
      }
    }
    const std::vector<double> tau = ThrusterForces(vehicle, trial, t);
    for (std::size_t i = 0; i < n; ++i) {
      if (!works[i]) continue;
      lo[i] = std::min(lo[i], tau[i]);
      hi[i] = std::max(hi[i], tau[i]);
      const auto& th = vehicle.thrusters[i];
      const double limit = tau[i] >= 0 ? th.MaxForwardThrust() : th.MaxReverseThrust();
      e->thrust_load = std::max(e->thrust_load, std::abs(tau[i]) / limit);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!works[i]) continue;
    // Sign kept: the whole range on one side of zero, min_thrust clear of it.
    const double clear = std::max(lo[i], -hi[i]);
    e->thrust_margin = std::min(e->thrust_margin, clear - vehicle.min_thrust);
  }
}

// The same two figures bounded from the sines' offsets and amplitudes, for the optimiser:
// τ_i = c_i + Σ_ξ share_iξ·a_ξ·sin(ω_ξ t) with c_i = Σ_ξ share_iξ·o_ξ stays within c_i ± w_i,
// w_i = Σ_ξ |share_iξ·a_ξ|, and reaches it when the sines line up (they nearly do over a
// long trial at unrelated frequencies): sign-kept margin |c_i| − w_i − min_thrust, load
// (|c_i| + w_i)/limit.
void ThrustBound(const model::Vehicle& vehicle, const model::CoupledTrialDesign& trial,
                 CoupledEnvelope* e) {
  const std::size_t n = vehicle.thrusters.size();
  std::vector<double> c(n, 0.0), w(n, 0.0);
  const std::vector<bool> works = WorkingThrusters(vehicle, trial);
  for (const model::TrialDesign& in : trial.inputs) {
    for (const auto& [ti, share] : vehicle.mappings[vehicle.MappingIndex(in.mapping)].shares) {
      c[ti] += share * in.offset;
      w[ti] += std::abs(share * in.amplitude);
    }
  }
  e->thrust_margin = std::numeric_limits<double>::infinity();
  e->thrust_load = 0.0;
  e->closed_water_force = 0.0;
  for (const model::TrialDesign& in : trial.inputs) {
    const auto& m = vehicle.mappings[vehicle.MappingIndex(in.mapping)];
    const double a = std::abs(in.amplitude);
    if (!m.IsOpenWater(model::Direction::kPos)) {
      e->closed_water_force = std::max(e->closed_water_force, in.offset + a);
    }
    if (!m.IsOpenWater(model::Direction::kNeg)) {
      e->closed_water_force = std::max(e->closed_water_force, a - in.offset);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!works[i]) continue;
    const auto& th = vehicle.thrusters[i];
    const double limit = c[i] >= 0 ? th.MaxForwardThrust() : th.MaxReverseThrust();
    e->thrust_margin = std::min(e->thrust_margin, std::abs(c[i]) - w[i] - vehicle.min_thrust);
    e->thrust_load = std::max(e->thrust_load, (std::abs(c[i]) + w[i]) / limit);
  }
}

}  // namespace

CoupledDesignOptions::CoupledDesignOptions() {
  solver.robustness = Robustness::kMaximin;
  // Local search from a start that keeps every thruster one way (ProblemOf): a global search
  // (DIRECT-L, 200 evaluations) over the 9 variables took 58 s and found no feasible point on
  // the ASV (measured 2026-11-27).
  solver.global = GlobalMethod::kNone;
  solver.max_local_evaluations = 300;
}

int CombinedMappingOf(const model::Vehicle& vehicle, model::Dof dof) {
  const std::vector<int> of_dof = vehicle.MappingsOf(dof);
  for (int m : of_dof) {
    if (vehicle.mappings[m].open_water == model::OpenWater::kBoth) return m;
  }
  return of_dof.empty() ? -1 : of_dof.front();
}

std::vector<double> ThrusterForces(const model::Vehicle& vehicle,
                                   const model::CoupledTrialDesign& trial, double t) {
  std::vector<double> tau(vehicle.thrusters.size(), 0.0);
  for (const model::TrialDesign& in : trial.inputs) {
    const double phi = in.NominalForce(t);
    for (const auto& [ti, share] : vehicle.mappings[vehicle.MappingIndex(in.mapping)].shares) {
      tau[ti] += share * phi;
    }
  }
  return tau;
}

CoupledHorizontalModel CoupledBox::At(const std::array<double, 3>& inertia,
                                      const std::array<double, 3>& drag) const {
  CoupledHorizontalModel m = nominal;
  for (int i = 0; i < 3; ++i) {
    m.theta[model::CoupledIndex(i, "m")] *= inertia[i];
    m.theta[model::CoupledIndex(i, "k")] *= drag[i];
    m.theta[model::CoupledIndex(i, "kq")] *= drag[i];
  }
  return m;
}

std::vector<CoupledHorizontalModel> CoupledBox::DesignPoints() const {
  std::vector<CoupledHorizontalModel> out = {nominal};
  for (int v = 0; v < 8; ++v) {
    std::array<double, 3> f;
    for (int i = 0; i < 3; ++i) f[i] = inertia_factor[i][(v >> i) & 1];
    out.push_back(At(f, {1.0, 1.0, 1.0}));
  }
  return out;
}

std::vector<CoupledHorizontalModel> CoupledBox::CheckPoints() const {
  std::vector<CoupledHorizontalModel> out = {nominal};
  for (int v = 0; v < 64; ++v) {
    std::array<double, 3> fi, fd;
    for (int i = 0; i < 3; ++i) {
      fi[i] = inertia_factor[i][(v >> i) & 1];
      fd[i] = drag_factor[i][(v >> (3 + i)) & 1];
    }
    out.push_back(At(fi, fd));
  }
  // The yaw drag swept inside its range: it sets the spin rate, and a surge or sway force
  // at the spin rate seen from the pool frame has a constant part that drives the vehicle
  // across the pool; the vertices alone miss such a resonance inside the box.
  const int kSweep = 17;
  for (int s = 1; s < kSweep - 1; ++s) {
    const double f = drag_factor[2][0] + (drag_factor[2][1] - drag_factor[2][0]) * s / (kSweep - 1);
    out.push_back(At({1.0, 1.0, 1.0}, {1.0, 1.0, f}));
  }
  return out;
}

std::vector<CoupledHorizontalModel> CoupledBox::Sample(int n, std::uint64_t seed) const {
  std::mt19937_64 rng(model::SplitMix64(seed));
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  std::vector<CoupledHorizontalModel> out;
  for (int k = 0; k < n; ++k) {
    std::array<double, 3> fi, fd;
    for (int i = 0; i < 3; ++i) {
      fi[i] = inertia_factor[i][0] + unit(rng) * (inertia_factor[i][1] - inertia_factor[i][0]);
      fd[i] = drag_factor[i][0] + unit(rng) * (drag_factor[i][1] - drag_factor[i][0]);
    }
    out.push_back(At(fi, fd));
  }
  return out;
}

CoupledBox CoupledAPrioriBox(const model::Vehicle& vehicle, const BoxOptions& options,
                             std::vector<std::string>* notes) {
  CoupledBox box;
  const std::vector<std::string> names(model::kCoupledDofParameters.begin(),
                                       model::kCoupledDofParameters.end());
  for (int i = 0; i < 3; ++i) {
    const ParameterBox b = APrioriBox(vehicle, model::kHorizontalDofs[i], names, options, notes);
    for (const std::string& n : names) {
      box.nominal.theta[model::CoupledIndex(i, n.c_str())] = b.Nominal(n);
    }
    for (const BoxAxis& a : b.axes) {
      if (a.name == "m") box.inertia_factor[i] = {a.lo, a.hi};
      if (a.name == "drag") box.drag_factor[i] = {a.lo, a.hi};
    }
  }
  return box;
}

namespace {

// The pool-frame track's extent and the heading's turns over `points`.
CoupledEnvelope TrackEnvelope(const model::CoupledTrialDesign& trial,
                              const std::vector<CoupledHorizontalModel>& points, double heading,
                              const CoupledDesignOptions& o) {
  CoupledEnvelope e;
  const double inf = std::numeric_limits<double>::infinity();
  e.x = {inf, -inf};
  e.y = {inf, -inf};
  const std::vector<double> t = Grid(trial.duration, o.step_s);
  const double c = std::cos(heading), s = std::sin(heading);
  for (const CoupledHorizontalModel& m : points) {
    const model::CoupledTrajectory x = Simulate(m, trial, t, o.step_s);
    for (const Horizontal& p : x.pose) {
      if (!p.allFinite()) e.finite = false;
      const double px = c * p[0] - s * p[1], py = s * p[0] + c * p[1];
      e.x = {std::min(e.x[0], px), std::max(e.x[1], px)};
      e.y = {std::min(e.y[0], py), std::max(e.y[1], py)};
      e.turns = std::max(e.turns, std::abs(p[2]) / kTwoPi);
    }
  }
  return e;
}

}  // namespace

CoupledEnvelope EnvelopeOf(const model::Vehicle& vehicle, const model::CoupledTrialDesign& trial,
                           const std::vector<CoupledHorizontalModel>& points, double heading,
                           const CoupledDesignOptions& o) {
  CoupledEnvelope e = TrackEnvelope(trial, points, heading, o);
  ThrustEnvelope(vehicle, trial, o.profile_step_s, &e);
  return e;
}

namespace {

// The constraints g <= 0 of a design, each scaled to O(1), and their reasons when violated.
std::vector<double> Constraints(const CoupledEnvelope& e, const model::Vehicle& vehicle,
                                const model::Pool& pool) {
  const double free_x = pool.FreeTravel(model::Dof::kSurge);
  const double free_y = pool.FreeTravel(model::Dof::kSway);
  return {-e.thrust_margin / std::max(vehicle.min_thrust, 1.0), e.thrust_load - 1.0,
          (e.x[1] - e.x[0] + 2 * kTrackSlack) / free_x - 1.0,
          (e.y[1] - e.y[0] + 2 * kTrackSlack) / free_y - 1.0,
          e.turns / pool.max_turns - 1.0,
          e.closed_water_force / std::max(vehicle.min_thrust, 1.0)};
}

std::vector<std::string> Reasons(const CoupledEnvelope& e, const model::Vehicle& vehicle,
                                 const model::Pool& pool) {
  std::vector<std::string> out;
  std::ostringstream s;
  const std::vector<double> g = Constraints(e, vehicle, pool);
  if (!e.finite) out.push_back("a simulation over the box diverged");
  if (g[0] > 1e-9) {
    s << "a thruster comes within " << e.thrust_margin + vehicle.min_thrust
      << " N of zero (min_thrust " << vehicle.min_thrust << " N) or reverses";
    out.push_back(s.str());
    s.str("");
  }
  if (g[1] > 1e-9) {
    s << "a thruster is asked " << 100 * e.thrust_load << "% of what it gives";
    out.push_back(s.str());
    s.str("");
  }
  if (g[2] > 1e-9 || g[3] > 1e-9) {
    s << "the track over the box spans " << e.x[1] - e.x[0] << " m × " << e.y[1] - e.y[0]
      << " m, the pool's free area is " << pool.FreeTravel(model::Dof::kSurge) << " m × "
      << pool.FreeTravel(model::Dof::kSway) << " m";
    out.push_back(s.str());
    s.str("");
  }
  if (g[4] > 1e-9) {
    s << "the heading turns " << e.turns << " turns, the tether allows " << pool.max_turns;
    out.push_back(s.str());
    s.str("");
  }
  if (g[5] > 1e-9) {
    s << "a DOF's force reaches " << e.closed_water_force
      << " N (N·m) in a direction its mapping does not work in open water: the coupled model "
         "takes η = 1 (give a mapping with open_water: both)";
    out.push_back(s.str());
  }
  return out;
}

}  // namespace

namespace {

// What every evaluation of one planning run shares.
struct Setup {
  Setup(const model::Vehicle& v, const model::Pool& p, const CoupledDesignOptions& opt)
      : vehicle(v), pool(p), o(opt) {}
  const model::Vehicle& vehicle;
  const model::Pool& pool;
  const CoupledDesignOptions& o;
  std::array<int, 3> mapping{};
  std::array<double, 3> force_max{};
  std::vector<int> moved, covered;
  Eigen::VectorXd scale;
  std::vector<Output> outputs;
  std::vector<double> t;
  std::vector<CoupledHorizontalModel> design_points, check_points;

  model::CoupledTrialDesign Trial(const double* x) const {
    return TrialOf(x, moved, mapping, force_max, vehicle, o);
  }
  Eigen::MatrixXd InformationAt(const CoupledHorizontalModel& m,
                                const model::CoupledTrialDesign& trial) const {
    return Information(m, trial, covered, scale, outputs, t, o.step_s);
  }
};

Setup MakeSetup(const model::Vehicle& vehicle, const model::Pool& pool,
                const CoupledDesignOptions& o, const CoupledBox& box) {
  Setup s(vehicle, pool, o);
  for (int i = 0; i < 3; ++i) {
    const model::Dof dof = model::kHorizontalDofs[i];
    s.mapping[i] = CombinedMappingOf(vehicle, dof);
    if (!model::ModeMoves(o.mode, dof)) continue;
    if (s.mapping[i] < 0) {
      throw model::InputError("vehicle '" + vehicle.name + "' has no mapping of " +
                              std::string(model::DofName(dof)) + " for a combined design");
    }
    s.force_max[i] = ForceMax(vehicle, s.mapping[i]);
    s.moved.push_back(i);
  }
  s.covered = CoveredParameters(o.mode);
  s.scale = Scales(box.nominal, s.covered, s.force_max);
  s.outputs = Outputs(vehicle, o.step_s);
  if (s.outputs.empty()) {
    throw model::InputError("vehicle '" + vehicle.name + "' declares no sensor of surge, sway or "
                            "yaw: a combined design has nothing to measure (sensors.<dof> in the "
                            "vehicle file)");
  }
  s.t = Grid(o.duration_s, o.step_s);
  s.design_points = box.DesignPoints();
  s.check_points = box.CheckPoints();
  return s;
}

// Variables per moved DOF (offset/F, amplitude/F, ω scaled), the criterion at the design
// points, the constraints at the check points (the thrusters bounded from the sines).
DesignProblem ProblemOf(const Setup& s) {
  DesignProblem problem;
  problem.num_variables = static_cast<int>(3 * s.moved.size());
  for (int i : s.moved) {
    problem.lower.insert(problem.lower.end(), {-1.0, 0.0, 0.0});
    problem.upper.insert(problem.upper.end(), {1.0, 1.0, 1.0});
    // Start: yaw pushed one way harder than all swings together (every thruster one way:
    // on the ASV 60 N of yaw offset against 36 N of swings a thruster), the vehicle spinning
    // at ~0.6–1 rad/s over the box, surge and sway swung well below that (0.24, 0.31 rad/s:
    // CheckPoints' resonance).
    const bool yaw = i == 2;
    const double omega = yaw ? 0.5 : i == 0 ? 0.1 : 0.15;
    problem.x0.insert(problem.x0.end(), {yaw ? 0.5 : 0.0, 0.1, omega});
  }
  problem.num_scenarios = static_cast<int>(s.design_points.size());
  problem.num_constraints = 6;
  problem.evaluate = [&s](const double* x, double* phi, double* g) {
    const model::CoupledTrialDesign trial = s.Trial(x);
    CoupledEnvelope e = TrackEnvelope(trial, s.check_points, s.o.start_heading_rad, s.o);
    if (!e.finite) return false;
    ThrustBound(s.vehicle, trial, &e);
    const std::vector<double> c = Constraints(e, s.vehicle, s.pool);
    std::copy(c.begin(), c.end(), g);
    for (std::size_t j = 0; j < s.design_points.size(); ++j) {
      const double v = LogDetPerParameter(s.InformationAt(s.design_points[j], trial));
      phi[j] = std::isfinite(v) ? v : -1e3;
    }
    return true;
  };
  return problem;
}

// The start: the track's envelope centred in the pool's free area.
void PlaceStart(const model::Pool& pool, double heading, CoupledDesign* d) {
  const double free_x = pool.FreeTravel(model::Dof::kSurge);
  const double free_y = pool.FreeTravel(model::Dof::kSway);
  const CoupledEnvelope& e = d->envelope;
  d->start_x = pool.margin + CentreTravel(free_x - (e.x[1] - e.x[0]), e.x).start;
  d->start_y = pool.margin + CentreTravel(free_y - (e.y[1] - e.y[0]), e.y).start;
  d->start_heading = heading;
}

// Cramér–Rao bounds over the design points: σ_j = √(F⁻¹)_jj (in θ's units); infinite, with a
// reason, where F is singular (the trial does not determine every parameter).
void AddCramerRao(const Setup& s, CoupledDesign* d) {
  const std::vector<std::string> names = model::CoupledParameterNames();
  for (int c : s.covered) d->parameters.push_back(names[c]);
  d->worst_sigma.assign(s.covered.size(), 0.0);
  d->worst_relative_sigma.assign(s.covered.size(), 0.0);
  for (const CoupledHorizontalModel& m : s.design_points) {
    const Eigen::MatrixXd F = s.InformationAt(m, d->trial);
    const Eigen::LLT<Eigen::MatrixXd> llt(F);
    if (llt.info() != Eigen::Success) {
      const double inf = std::numeric_limits<double>::infinity();
      d->worst_sigma.assign(s.covered.size(), inf);
      d->worst_relative_sigma.assign(s.covered.size(), inf);
      d->reasons.push_back("the trial does not determine every parameter of the DOFs it moves "
                           "(singular Fisher information at a point of the box)");
      return;
    }
    const Eigen::MatrixXd cov = llt.solve(Eigen::MatrixXd::Identity(F.rows(), F.cols()));
    for (std::size_t c = 0; c < s.covered.size(); ++c) {
      const double sigma = std::sqrt(std::max(cov(c, c), 0.0)) * s.scale[c];
      const double value = std::abs(m.theta[s.covered[c]]);
      d->worst_sigma[c] = std::max(d->worst_sigma[c], sigma);
      d->worst_relative_sigma[c] =
          value > 0 ? std::max(d->worst_relative_sigma[c], sigma / value)
                    : std::numeric_limits<double>::quiet_NaN();
    }
  }
}

// Exchange step of semi-infinite programming (the constraints hold for every θ of the box, a
// continuum): the check set's vertices and sweep miss interior extremes of the track (a
// spin-rate resonance peaks inside the box), so the probes that reach farther than the check
// set in x, y or turns join it. Returns how many joined.
std::size_t AddExtremes(const model::CoupledTrialDesign& trial,
                        const std::vector<CoupledHorizontalModel>& probes,
                        const CoupledDesignOptions& o,
                        std::vector<CoupledHorizontalModel>* check_points) {
  const CoupledEnvelope have = TrackEnvelope(trial, *check_points, o.start_heading_rad, o);
  std::array<double, 5> reach = {-have.x[0], have.x[1], -have.y[0], have.y[1], have.turns};
  std::array<int, 5> best = {-1, -1, -1, -1, -1};
  for (std::size_t k = 0; k < probes.size(); ++k) {
    const CoupledEnvelope e = TrackEnvelope(trial, {probes[k]}, o.start_heading_rad, o);
    const std::array<double, 5> r = {-e.x[0], e.x[1], -e.y[0], e.y[1], e.turns};
    for (int c = 0; c < 5; ++c) {
      if (r[c] > reach[c] + 1e-3) {
        reach[c] = r[c];
        best[c] = static_cast<int>(k);
      }
    }
  }
  std::vector<int> add(best.begin(), best.end());
  std::sort(add.begin(), add.end());
  add.erase(std::unique(add.begin(), add.end()), add.end());
  std::size_t added = 0;
  for (int k : add) {
    if (k < 0) continue;
    check_points->push_back(probes[k]);
    ++added;
  }
  return added;
}

}  // namespace

CoupledDesign PlanCoupledDesign(const model::Vehicle& vehicle, const model::Pool& pool,
                                const CoupledDesignOptions& o) {
  CoupledDesign out;
  const CoupledBox box = CoupledAPrioriBox(vehicle, o.box, &out.notes);
  Setup s = MakeSetup(vehicle, pool, o, box);
  const std::vector<CoupledHorizontalModel> probes = box.Sample(o.probe_points, o.probe_seed);
  DesignProblem problem = ProblemOf(s);
  SolverOptions solver = o.solver;
  for (int round = 0; round <= o.exchange_rounds; ++round) {
    out.solver = Solve(SolverBackend::kNlopt, problem, solver);
    if (out.solver.x.empty()) {
      out.reasons.push_back("the optimiser found no design: " + out.solver.message);
      return out;
    }
    const std::size_t added = AddExtremes(s.Trial(out.solver.x.data()), probes, o, &s.check_points);
    if (added == 0) break;
    problem.x0 = out.solver.x;  // warm start on the larger check set: a polish
    solver.max_local_evaluations = o.exchange_evaluations;
  }
  out.trial = s.Trial(out.solver.x.data());
  out.criterion = out.solver.objective;
  // The verdict over the check set and every probe.
  std::vector<CoupledHorizontalModel> verdict_points = s.check_points;
  verdict_points.insert(verdict_points.end(), probes.begin(), probes.end());
  out.envelope = EnvelopeOf(vehicle, out.trial, verdict_points, o.start_heading_rad, o);
  out.reasons = Reasons(out.envelope, vehicle, pool);
  PlaceStart(pool, o.start_heading_rad, &out);
  AddCramerRao(s, &out);
  out.fits = out.reasons.empty();
  return out;
}

}  // namespace uuvplan::planner
