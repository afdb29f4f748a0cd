// Robust optimal sinusoid trial (ref 000 eqs. 13-15): phi_n(t) = offset + amplitude·sin(ω·t)
// in one mapping and one direction, from rest, for a duration T, maximising the robust
// criterion of the FULL nonlinear model's information over the a priori box.
//
// Ref 000 picks ω_opt = 1/(√3·t_c) (eq. 14, Goodwin & Payne for a linear first-order system
// with the velocity measured) at a guessed t_c = m/k_L; that is the starting point here, not the
// answer: the drag is quadratic, only the position may be measured, the pool is finite and m is
// unknown within its bounds.
//
// Design variables (all in [0, 1], so that the no-reversal and thruster limits are bounds):
//   u: |offset| = φ_min + u·(o_max - φ_min),  o_max = (φ_max + ρ·φ_min)/(1 + ρ)
//   r: amplitude = d·(ρ + r·(min(1, (φ_max - |offset|)/d) - ρ)),  d = |offset| - φ_min
//      i.e. ρ·d <= amplitude <= min(d, φ_max - |offset|): no reversal nor dead band
//      (Δφ <= φ̂ - φ_min, eq. 15), within the thrusters, and swinging at least the fraction
//      ρ = min_amplitude_fraction of the way down to the no-reversal limit
//   v: ω = ω_lo·(ω_hi/ω_lo)^v, [ω_lo, ω_hi] = [ω_opt,min/4, 4·ω_opt,max] over the box
// Duration: the longest that keeps the travel over the box inside the pool (information grows
// with every sample, so a shorter trial is never better), at most max_duration_s; or fixed, with
// the pool as a constraint. At least `min_periods` periods must fit.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/schedule.h"

namespace uuvplan::planner {

struct SineDesignOptions {
  Criterion criterion = Criterion::kDs;
  std::vector<std::string> interest = {"m"};  ///< Ds/A/E interest set (D ignores it)
  /// 0: the longest duration that fits the pool (<= max_duration_s); > 0: this duration.
  double fixed_duration_s = 0.0;
  /// Longest sine trial (s), within the context's max_trial_duration_s. CHOSEN 120 s: seed
  /// 000 Fig. 14's sine trial lasts about 100 s. Rotations (no pool limit) run this long.
  double max_duration_s = 120.0;
  /// At least this many periods in the trial. CHOSEN 2: ref 000 §IV-D excites "a couple of
  /// sinusoidal periods". With 1 the optimum on ROMEO surge degenerates into a single slow
  /// swell whose information comes mostly from the start from rest.
  double min_periods = 2.0;
  /// Smallest amplitude as a fraction ρ of |offset| - φ_min (the largest swing without
  /// reversal). CHOSEN 0.5: below it the trial is a steady run with a ripple, which the steady
  /// design already covers; under the standard model most inertia information comes from the
  /// start from rest, and without this bound a schedule whose steady runs are already planned
  /// drives the amplitude to zero (docs/planning.md). Ref 000's designs: 25/(35 - φ_min) and
  /// 4/(5 - φ_min), both above 0.7.
  double min_amplitude_fraction = 0.5;
  /// Only directions where the mapping works in open water (eta = 1 known, ref 000 §IV-D): in
  /// another direction eta scales the force and, without prior information on it, m cannot be
  /// told from eta·phi (the information is singular).
  bool open_water_only = true;
  std::vector<std::string> mappings;  ///< restrict to these mappings (empty: all of the DOF)
  /// Direction of phi: +1 or -1 only, 0 both.
  int sign = 0;
  /// The mapping-switched families the inertia trial may also take (switched_design.h); the
  /// single sine above is always designed (the seed's design, the fallback). Empty: the sine
  /// alone.
  std::vector<model::InputFamily> families = {model::InputFamily::kSwitchedSquare,
                                              model::InputFamily::kSwitchedSine,
                                              model::InputFamily::kMultisine};
  /// A DOF without a switch pair (URIS surge, VSOR yaw, every heave of the cases) may also take
  /// the square one way (family `piecewise`, in the single sine's mapping and direction:
  /// switched_design.h OneWayPairs); the robust criterion chooses (docs/planning.md §1b).
  /// Off by default: on, ROMEO's heave loop misses m by 6σ — its short one-way trials leave an
  /// installation coefficient held at 1 by identification (docs/planning.md §1b).
  bool one_way_families = false;

  bool IsValid(std::string* error) const;
};

enum class DesignStatus { kOk, kInfeasible, kFailed };
std::string_view DesignStatusName(DesignStatus s);

struct SineDesignResult {
  DesignStatus status = DesignStatus::kFailed;
  std::string message;
  PlannedTrial trial;                        ///< the design with its checked travel and thrust_min
  TrialCheck check;                          ///< hard constraints over the check grid
  double criterion = 0.0;                    ///< robust aggregate of the criterion (with the prior)
  std::vector<double> criterion_per_point;   ///< at each design point of the box
  std::vector<Eigen::MatrixXd> information;  ///< the trial's own M at each design point
  SolverSummary summary;                     ///< of the best candidate mapping/direction
  std::vector<std::string> notes;
};

/// Designs the sine trial of ctx's DOF. `prior` (per design point, absolute units, may be
/// empty) is added to the trial's information: e.g. the steady runs of the same schedule, so
/// the sine is designed for what they leave unknown. `id` names the trial.
SineDesignResult DesignSine(const DofPlanningProblem& ctx, const SineDesignOptions& options,
                            const std::vector<Eigen::MatrixXd>& prior, const std::string& id);

/// The frequency range [ω_lo, ω_hi] of the design variable v for a force level: ref 000
/// eq. 14's ω_opt over the box, from a quarter of the least to 4 times the largest; ω_lo
/// raised so that `min_periods` periods fit in `duration` s (ω_hi then at least 2·ω_lo); ω_hi
/// at most that of the shortest period the sensors allow (ctx.ShortestPeriod()) for the
/// highest of `harmonics` harmonics of ω (0: no such bound). Empty (ω_hi < ω_lo) when the
/// sensors resolve no wave of `min_periods` periods in `duration`.
std::array<double, 2> SineFrequencyRange(const DofPlanningProblem& ctx, double force_abs,
                                         double min_periods, double duration, int harmonics = 1);

/// The longest duration (<= t_max) for which a trial keeps its travel over the box inside
/// ctx.available(); t_max when the pool does not limit it (rotations).
double LongestFittingDuration(const DofPlanningProblem& ctx, const model::TrialDesign& design,
                              double t_max);

}  // namespace uuvplan::planner
