// Combined-mode designs for the coupled horizontal model (seed 003, model/coupled_model.h): one
// sine φ_ξ(t) = o_ξ + a_ξ·sin(ω_ξ·t) per DOF the mode moves, in that DOF's horizontal mapping,
// chosen to maximise the worst case over the a priori box of the D-criterion
//
//   φ_j = (1/p)·log det(S·F_j·S),   F_j = Σ_sensors Σ_k (1/σ²)·(∂y_k/∂θ)ᵀ(∂y_k/∂θ)
//
// (seed 000 §III-B's robust d-optimality, with the coupled model's sensitivities; θ the
// parameters of the moved DOFs, S their nominal scales), subject to, at every point of the box:
//  - each thruster's force τ_i(t) = Σ_ξ share_iξ·φ_ξ(t) keeps its sign and stays above
//    min_thrust (no propeller reversal, seed 000 §III-B) and within the thruster's limit;
//  - the pool-frame track (x, y), from a start pose that the design chooses, keeps the pool's
//    margin from every wall; the heading turns at most the tether's max_turns;
//  - each DOF's force stays in the directions its mapping works in open water (the coupled
//    model has no installation coefficient: η = 1, seed 003 practical model).
// Offsets make this possible: a yaw offset larger than the surge and sway swings keeps every
// thruster pushing one way while X and Y change sign, and the vehicle turns about a point
// instead of crossing the pool.
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "uuvplan/model/coupled_model.h"
#include "uuvplan/model/coupled_trial.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/parameter_box.h"
#include "uuvplan/planner/design/solver.h"

namespace uuvplan::planner {

/// The a priori box of the 12 coupled parameters: per DOF its inertia axis and its drag axis
/// (parameter_box.h, APrioriBox of each horizontal DOF).
struct CoupledBox {
  model::CoupledHorizontalModel nominal;
  std::array<std::array<double, 2>, 3> inertia_factor{};  ///< [lo, hi] on each DOF's m
  std::array<std::array<double, 2>, 3> drag_factor{};     ///< [lo, hi] on each DOF's k and kq
  /// The centre, then the 8 vertices of the inertia axes (drags nominal): where the criterion
  /// is evaluated.
  std::vector<model::CoupledHorizontalModel> DesignPoints() const;
  /// The centre, the 64 vertices of all six axes, then the yaw drag swept at 15 inner values
  /// (the others at the centre): where the constraints are evaluated.
  std::vector<model::CoupledHorizontalModel> CheckPoints() const;
  /// `n` points drawn uniformly from the box (seeded).
  std::vector<model::CoupledHorizontalModel> Sample(int n, std::uint64_t seed) const;
  /// The model at the given factors on each DOF's inertia and drag.
  model::CoupledHorizontalModel At(const std::array<double, 3>& inertia,
                                   const std::array<double, 3>& drag) const;
};

CoupledBox CoupledAPrioriBox(const model::Vehicle& vehicle, const BoxOptions& options,
                             std::vector<std::string>* notes);

struct CoupledDesignOptions {
  model::CombinedMode mode = model::CombinedMode::kSurgeSwayYaw;
  double duration_s = 120.0;
  double start_heading_rad = 0.0;  ///< surge axis along the pool's length
  double omega_min = 0.1, omega_max = 1.5;  ///< rad/s, CHOSEN: periods 4–60 s
  /// RK4 step of the planner's simulations (s): ω·h <= 0.3 at the fastest sine and spin.
  double step_s = 0.2;
  double profile_step_s = 0.05;             ///< thruster forces checked this often
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
  CoupledDesignOptions();
};

/// Where the constraints stand at one design over the check points.
struct CoupledEnvelope {
  std::array<double, 2> x = {0.0, 0.0}, y = {0.0, 0.0};  ///< m, pool frame, from the start
  double turns = 0.0;           ///< largest |ψ(t) − ψ(0)| / 2π over the box
  double thrust_margin = 0.0;   ///< smallest (sign-kept |τ_i| − min_thrust) over t (N)
  double thrust_load = 0.0;     ///< largest |τ_i| / limit_i
  /// Largest |φ| a DOF takes in a direction its mapping does not work in open water (N or
  /// N·m): the coupled model takes η = 1 (coupled_model.h), so this must be 0.
  double closed_water_force = 0.0;
  bool finite = true;
};

/// What the combined trial's Cramér–Rao σ rest on, printed and written beside them.
inline constexpr const char* kCoupledSigmaAssumption =
    "a lower bound: the vehicle file's surge, sway and yaw sensors with white noise, the "
    "trial's initial state known and an efficient estimator; `identify --model coupled` fits "
    "integral least squares with instruments (seed 003), whose σ are larger, and coloured noise "
    "or an unmodelled effect makes them larger still";

struct CoupledDesign {
  model::CoupledTrialDesign trial;
  /// Start pose in the pool: x m from the wall the surge axis faces away from (length), y m from
  /// the wall on the vehicle's port side (width), heading rad from the length axis.
  double start_x = 0.0, start_y = 0.0, start_heading = 0.0;
  CoupledEnvelope envelope;
  std::vector<std::string> parameters;  ///< θ names the criterion covers ("surge.m", …)
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

/// The best combined sine design of `options.mode` for `vehicle` in `pool` (see above).
/// InputError when the vehicle has no mapping of a DOF the mode moves or no horizontal sensor.
CoupledDesign PlanCoupledDesign(const model::Vehicle& vehicle, const model::Pool& pool,
                                const CoupledDesignOptions& options);

/// The horizontal mapping a combined design uses for `dof`: the vehicle's first mapping of that
/// DOF in open water both ways, else its first mapping of that DOF; -1 if it has none.
int CombinedMappingOf(const model::Vehicle& vehicle, model::Dof dof);

/// Thruster forces τ_i(t) = Σ_ξ share_iξ·φ_ξ(t) of a combined trial at time t (N).
std::vector<double> ThrusterForces(const model::Vehicle& vehicle,
                                   const model::CoupledTrialDesign& trial, double t);

/// The envelope of `trial` over `points` (the box's check points), simulated from rest.
CoupledEnvelope EnvelopeOf(const model::Vehicle& vehicle, const model::CoupledTrialDesign& trial,
                           const std::vector<model::CoupledHorizontalModel>& points,
                           double heading, const CoupledDesignOptions& options);

}  // namespace uuvplan::planner
