// A combined sine trial for a multi-DOF model (model/multi_dof_model.h; ref 003's coupled
// horizontal model, coupled_design.h): one sine φ_ξ(t) = o_ξ + a_ξ·sin(ω_ξ·t) per DOF the trial
// moves, in that DOF's mapping, chosen to maximise the robust aggregate over the a priori box
// (parameter_box.h JointAPrioriBox) of the D-criterion
//
//   φ_j = (1/p)·log det(S·F_j·S)
//
// (ref 000 §III-B's robust d-optimality; F_j the Fisher information of the moved DOFs'
// parameters at box point j, fisher_information.h JointInformation, initial state known; S
// their nominal scales), subject to, at every check point of the box:
//  - each thruster's force τ_i(t) = Σ_ξ share_iξ·φ_ξ(t) keeps its sign and stays above
//    min_thrust (no propeller reversal, ref 000 §III-B) and within the thruster's limit;
//  - each DOF's travel from its start keeps the pool's margin from every wall (translational:
//    in the pool frame of the start's heading; StartOf then centres it), and a rotation turns
//    at most the tether's max_turns;
//  - each DOF's force stays in the directions its mapping works in open water (the joint
//    model's thrust takes η = 1, ref 003 practical model).
// The criterion is evaluated at the box's design points (the inertia axes' vertices, the drags
// nominal), the constraints at its check points: the centre, every vertex, one axis swept
// inside (`swept_axis`) and the probes the exchange rounds add.
#pragma once

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "uuvplan/model/multi_dof_model.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/parameter_box.h"
#include "uuvplan/planner/design/solver.h"

namespace uuvplan::planner {

struct CombinedDesignOptions {
  std::vector<model::Dof> dofs;  ///< the DOFs the trial moves (its mode)
  double duration_s = 120.0;
  double start_heading_rad = 0.0;           ///< surge axis along the pool's length
  double omega_min = 0.1, omega_max = 1.5;  ///< rad/s, CHOSEN: periods 4–60 s
  /// A moved DOF's ω at most 2π/(its sensors' shortest period at this many samples per period).
  double samples_per_period = model::kDefaultSamplesPerPeriod;
  /// RK4 step of the planner's simulations (s): ω·h <= 0.3 at the fastest sine and spin.
  double step_s = 0.2;
  double profile_step_s = 0.05;  ///< thruster forces checked this often
  /// The optimiser's start per moved DOF, in the design variables (offset/F, amplitude/F,
  /// (ω − ω_min)/(ω_max − ω_min), ω_max the DOF's own: less than omega_max where its sensors
  /// are slow); a DOF not listed starts at {0, 0.1, 0.1}.
  std::map<model::Dof, std::array<double, 3>> start;
  /// The box axis swept at 15 inner values (the others at the centre) among the check points
  /// ("yaw.drag": the yaw drag sets the spin rate, and a resonance inside the box is missed by
  /// the vertices); empty: none.
  std::string swept_axis;
  /// Exchange rounds: after a solve, `probe_points` points of the box (seeded) are simulated
  /// and those reaching farther than the check points join them; solved again from there
  /// (`exchange_evaluations` at most), at most `exchange_rounds` times. The verdict (`fits`)
  /// is over the check points and every probe.
  int exchange_rounds = 3;
  int exchange_evaluations = 80;
  int probe_points = 256;
  std::uint64_t probe_seed = 2003;
  BoxOptions box;
  SolverOptions solver;
  CombinedDesignOptions();
};

/// Where the constraints stand at one design over the check points.
struct CombinedEnvelope {
  /// Per DOF of the model: its position's extremes over the box from the start (m in the pool
  /// frame of the start's heading; rad).
  std::vector<std::array<double, 2>> travel;
  double turns = 0.0;          ///< largest |rotation| / 2π of a rotational DOF over the box
  double thrust_margin = 0.0;  ///< smallest (sign-kept |τ_i| − min_thrust) over t (N)
  double thrust_load = 0.0;    ///< largest |τ_i| / limit_i
  /// Largest |φ| a DOF takes in a direction its mapping does not work in open water (N or
  /// N·m): the thrust takes η = 1, so this must be 0.
  double closed_water_force = 0.0;
  bool finite = true;
};

struct CombinedDesign {
  model::CombinedTrialDesign trial;
  /// Per DOF of the model, where it starts (m from the wall behind it, StartOf; a rotation:
  /// the start heading, rad from the pool's length axis).
  std::vector<double> start;
  CombinedEnvelope envelope;
  std::vector<std::string> parameters;  ///< θ names the criterion covers ("surge.m", …)
  std::vector<std::string> units;       ///< theirs
  /// Worst case over the design points of the Cramér–Rao σ(θ_j) (θ's units), and of
  /// σ(θ_j)/|θ_j| at that point (NaN for a parameter whose nominal is 0: the biases).
  std::vector<double> worst_sigma, worst_relative_sigma;
  double criterion = 0.0;  ///< the robust aggregate of φ_j (maximin by default: the worst case)
  /// Every constraint holds at every check point and probe, and the trial determines every
  /// parameter it covers.
  bool fits = false;
  std::vector<std::string> reasons;  ///< why it does not fit, with figures
  std::vector<std::string> notes;    ///< the assumptions behind the box
  SolverSummary solver;
};

/// The best combined sine design of `options.dofs` for `model` on `vehicle` in `pool` (above).
/// InputError when the vehicle has no mapping of a DOF the trial moves or no sensor of the
/// model's DOFs.
CombinedDesign PlanCombinedDesign(const model::MultiDofModel& model, const model::Vehicle& vehicle,
                                  const model::Pool& pool, const CombinedDesignOptions& options);

/// The mapping a combined design uses for `dof`: the vehicle's first mapping of that DOF in
/// open water both ways, else its first mapping of that DOF; -1 if it has none.
int CombinedMappingOf(const model::Vehicle& vehicle, model::Dof dof);

/// Thruster forces τ_i(t) = Σ_ξ share_iξ·φ_ξ(t) of a combined trial at time t (N).
std::vector<double> ThrusterForcesAt(const model::Vehicle& vehicle,
                                     const model::CombinedTrialDesign& trial, double t);

/// The envelope of `trial` over the box points `thetas`, simulated from rest (the travel and
/// turns), and of its thrusters from its profile every `options.profile_step_s`.
CombinedEnvelope EnvelopeOf(const model::MultiDofModel& model, const model::Vehicle& vehicle,
                            const model::CombinedTrialDesign& trial,
                            const std::vector<Eigen::VectorXd>& thetas,
                            const CombinedDesignOptions& options);

/// θ of the model at a point of its box (names the model's global ones).
Eigen::VectorXd ThetaAt(const model::MultiDofModel& model, const ParameterValues& point);

}  // namespace uuvplan::planner
