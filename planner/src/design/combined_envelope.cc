// The constraints side of a combined design (combined_envelope.h).
#include "design/combined_envelope.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "uuvplan/model/simulator.h"
#include "uuvplan/model/util/numbers.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner {
namespace {

constexpr double kTwoPi = 2.0 * M_PI;
using model::kInf;
// m kept free beyond the travel at each wall: the planner's 0.2 s RK4 track differs from a
// 0.01 s one by < 1 cm on the ASV (docs/planning.md §5).
constexpr double kTrackSlack = 0.05;

const model::ThrustMapping& MappingOf(const model::Vehicle& vehicle, const model::TrialDesign& in) {
  return vehicle.mappings[vehicle.MappingIndex(in.mapping)];
}

// The thrusters with a non-zero share in a mapping the trial uses (the others are idle).
std::vector<bool> WorkingThrusters(const model::Vehicle& vehicle,
                                   const model::CombinedTrialDesign& trial) {
  std::vector<bool> works(vehicle.thrusters.size(), false);
  for (const model::TrialDesign& in : trial.inputs) {
    for (const auto& [ti, share] : MappingOf(vehicle, in).shares)
      works[ti] = works[ti] || share != 0.0;
  }
  return works;
}

// Thruster side of the envelope: the sign-kept margin over min_thrust and the load, from the
// nominal force profile (the forces do not depend on the vehicle's parameters).
void ThrustEnvelope(const model::Vehicle& vehicle, const model::CombinedTrialDesign& trial,
                    double step_s, CombinedEnvelope* e) {
  const std::size_t n = vehicle.thrusters.size();
  std::vector<double> lo(n, kInf), hi(n, -kInf);
  const std::vector<bool> works = WorkingThrusters(vehicle, trial);
  e->thrust_margin = kInf;
  e->thrust_load = 0.0;
  e->closed_water_force = 0.0;
  for (double t : internal::Grid(trial.duration, step_s)) {
    for (const model::TrialDesign& in : trial.inputs) {
      const double phi = in.NominalForce(t);
      if (phi != 0.0 &&
          !MappingOf(vehicle, in)
               .IsOpenWater(phi > 0 ? model::Direction::kPos : model::Direction::kNeg)) {
        e->closed_water_force = std::max(e->closed_water_force, std::abs(phi));
      }
    }
    const std::vector<double> tau = ThrusterForcesAt(vehicle, trial, t);
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
    e->thrust_margin = std::min(e->thrust_margin, clear - vehicle.WorkingThrustFloor());
  }
}

}  // namespace

int CombinedMappingOf(const model::Vehicle& vehicle, model::Dof dof) {
  const std::vector<int> of_dof = vehicle.MappingsOf(dof);
  for (int m : of_dof) {
    if (vehicle.mappings[m].open_water == model::OpenWater::kBoth) return m;
  }
  return of_dof.empty() ? -1 : of_dof.front();
}

std::vector<double> ThrusterForcesAt(const model::Vehicle& vehicle,
                                     const model::CombinedTrialDesign& trial, double t) {
  std::vector<double> tau(vehicle.thrusters.size(), 0.0);
  for (const model::TrialDesign& in : trial.inputs) {
    const double phi = in.NominalForce(t);
    for (const auto& [ti, share] : MappingOf(vehicle, in).shares) tau[ti] += share * phi;
  }
  return tau;
}

Eigen::VectorXd ThetaAt(const model::MultiDofModel& model, const ParameterValues& point) {
  Eigen::VectorXd theta(model.num_parameters());
  for (int j = 0; j < model.num_parameters(); ++j) theta[j] = point.at(model.parameter_names()[j]);
  return theta;
}

CombinedEnvelope EnvelopeOf(const model::MultiDofModel& model, const model::Vehicle& vehicle,
                            const model::CombinedTrialDesign& trial,
                            const std::vector<Eigen::VectorXd>& thetas,
                            const CombinedDesignOptions& options) {
  const internal::CombinedInputs inputs = internal::InputsOf(model, vehicle, trial);
  CombinedEnvelope e = internal::TrackEnvelope(model, inputs, trial, thetas, options);
  ThrustEnvelope(vehicle, trial, options.profile_step_s, &e);
  return e;
}

namespace internal {

CombinedInputs InputsOf(const model::MultiDofModel& model, const model::Vehicle& vehicle,
                        const model::CombinedTrialDesign& trial) {
  CombinedInputs in;
  in.conditions.inputs.assign(model.num_dofs(), nullptr);
  for (const model::TrialDesign& d : trial.inputs) {
    in.excitations.push_back(model::MakeExcitation(vehicle, d));
    in.conditions.inputs[model.DofIndex(d.dof)] = in.excitations.back().get();
  }
  return in;
}

std::vector<double> Grid(double duration, double dt) {
  std::vector<double> t;
  const int n = static_cast<int>(std::floor(duration / dt + 1e-9));
  for (int k = 0; k <= n; ++k) t.push_back(k * dt);
  return t;
}

CombinedEnvelope TrackEnvelope(const model::MultiDofModel& model, const CombinedInputs& inputs,
                               const model::CombinedTrialDesign& trial,
                               const std::vector<Eigen::VectorXd>& thetas,
                               const CombinedDesignOptions& o) {
  const int n = model.num_dofs();
  CombinedEnvelope e;
  e.travel.assign(n, {kInf, -kInf});
  const std::vector<double> t = Grid(trial.duration, o.step_s);
  model::SimulationOptions sim;
  sim.step_s = o.step_s;
  const double c = std::cos(o.start_heading_rad), s = std::sin(o.start_heading_rad);
  const int ix = model.planar() ? model.DofIndex(model::Dof::kSurge) : -1;
  const int iy = model.planar() ? model.DofIndex(model::Dof::kSway) : -1;
  for (const Eigen::VectorXd& theta : thetas) {
    const model::Trajectory x = model::Simulate(model, theta, inputs.conditions, t, sim);
    for (std::size_t k = 0; k < t.size(); ++k) {
      for (int i = 0; i < n; ++i) {
        double p = x.x(k, model.state_offset(i));
        if (!std::isfinite(p)) e.finite = false;
        if (i == ix || i == iy) {  // the pool frame of the start's heading
          const double px = x.x(k, model.state_offset(ix)), py = x.x(k, model.state_offset(iy));
          p = i == ix ? c * px - s * py : s * px + c * py;
        }
        e.travel[i] = {std::min(e.travel[i][0], p), std::max(e.travel[i][1], p)};
        if (model::IsRotational(model.dof(i))) e.turns = std::max(e.turns, std::abs(p) / kTwoPi);
      }
    }
  }
  return e;
}

// The same two figures bounded from the sines' offsets and amplitudes, for the optimiser:
// τ_i = c_i + Σ_ξ share_iξ·a_ξ·sin(ω_ξ t) with c_i = Σ_ξ share_iξ·o_ξ stays within c_i ± w_i,
// w_i = Σ_ξ |share_iξ·a_ξ|, and reaches it when the sines line up (they nearly do over a
// long trial at unrelated frequencies): sign-kept margin |c_i| − w_i − min_thrust, load
// (|c_i| + w_i)/limit.
void ThrustBound(const model::Vehicle& vehicle, const model::CombinedTrialDesign& trial,
                 CombinedEnvelope* e) {
  const std::size_t n = vehicle.thrusters.size();
  std::vector<double> c(n, 0.0), w(n, 0.0);
  const std::vector<bool> works = WorkingThrusters(vehicle, trial);
  for (const model::TrialDesign& in : trial.inputs) {
    for (const auto& [ti, share] : MappingOf(vehicle, in).shares) {
      c[ti] += share * in.offset;
      w[ti] += std::abs(share * in.amplitude);
    }
  }
  e->thrust_margin = kInf;
  e->thrust_load = 0.0;
  e->closed_water_force = 0.0;
  for (const model::TrialDesign& in : trial.inputs) {
    const double a = std::abs(in.amplitude);
    if (!MappingOf(vehicle, in).IsOpenWater(model::Direction::kPos)) {
      e->closed_water_force = std::max(e->closed_water_force, in.offset + a);
    }
    if (!MappingOf(vehicle, in).IsOpenWater(model::Direction::kNeg)) {
      e->closed_water_force = std::max(e->closed_water_force, a - in.offset);
    }
  }
  for (std::size_t i = 0; i < n; ++i) {
    if (!works[i]) continue;
    const auto& th = vehicle.thrusters[i];
    const double limit = c[i] >= 0 ? th.MaxForwardThrust() : th.MaxReverseThrust();
    e->thrust_margin =
        std::min(e->thrust_margin, std::abs(c[i]) - w[i] - vehicle.WorkingThrustFloor());
    e->thrust_load = std::max(e->thrust_load, (std::abs(c[i]) + w[i]) / limit);
  }
}

std::vector<double> Constraints(const model::MultiDofModel& model, const CombinedEnvelope& e,
                                const model::Vehicle& vehicle, const model::Pool& pool) {
  std::vector<double> g = {-e.thrust_margin / std::max(vehicle.WorkingThrustFloor(), 1.0),
                           e.thrust_load - 1.0};
  for (int i = 0; i < model.num_dofs(); ++i) {
    const model::Dof d = model.dof(i);
    const auto& span = e.travel[i];
    g.push_back(model::IsRotational(d)
                    ? e.turns / pool.max_turns - 1.0
                    : (span[1] - span[0] + 2 * kTrackSlack) / pool.FreeTravel(d) - 1.0);
  }
  g.push_back(e.closed_water_force / std::max(vehicle.WorkingThrustFloor(), 1.0));
  return g;
}

std::vector<std::string> Reasons(const model::MultiDofModel& model, const CombinedEnvelope& e,
                                 const model::Vehicle& vehicle, const model::Pool& pool) {
  std::vector<std::string> out;
  std::ostringstream s;
  const std::vector<double> g = Constraints(model, e, vehicle, pool);
  auto add = [&] {
    out.push_back(s.str());
    s.str("");
  };
  if (!e.finite) out.push_back("a simulation over the box diverged");
  if (g[0] > 1e-9) {
    const double floor = vehicle.WorkingThrustFloor();
    s << "a thruster comes within " << e.thrust_margin + floor << " N of zero ("
      << FloorName(vehicle) << " " << floor << " N) or reverses";
    add();
  }
  if (g[1] > 1e-9) {
    s << "a thruster is asked " << 100 * e.thrust_load << "% of what it gives";
    add();
  }
  for (int i = 0; i < model.num_dofs(); ++i) {
    const model::Dof d = model.dof(i);
    if (g[2 + i] <= 1e-9) continue;
    if (model::IsRotational(d)) {
      s << "the " << model::DofName(d) << " turns " << e.turns << " turns, the tether allows "
        << pool.max_turns;
    } else {
      s << "the " << model::DofName(d) << " travel over the box spans "
        << e.travel[i][1] - e.travel[i][0] << " m, the pool's free " << model::DofName(d)
        << " travel is " << pool.FreeTravel(d) << " m";
    }
    add();
  }
  if (g.back() > 1e-9) {
    s << "a DOF's force reaches " << e.closed_water_force
      << " N (N·m) in a direction its mapping does not work in open water: the joint model "
         "takes η = 1 (give a mapping with open_water: both)";
    add();
  }
  return out;
}

}  // namespace internal
}  // namespace uuvplan::planner
