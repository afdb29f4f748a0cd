// Everything the designs of one DOF share: the DOF's model (the contract's standard model with
// an installation coefficient for every non-open-water direction of its mappings), the box of
// a priori parameter values, the sensors, the pool's free travel, the RK4 step; and the two
// things every design does with a trial: its information at the box's design points, and the
// hard-constraint check by simulation over the box's check grid.
#pragma once

#include <Eigen/Dense>
#include <array>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/excitation.h"
#include "uuvplan/model/pool.h"
#include "uuvplan/model/trial_design.h"
#include "uuvplan/model/vehicle.h"
#include "uuvplan/planner/design/criteria.h"
#include "uuvplan/planner/design/parameter_box.h"
#include "uuvplan/planner/design/solver.h"
#include "uuvplan/planner/design/thrust_limits.h"

namespace uuvplan::planner {

/// Information from earlier trials (or any prior knowledge), absolute units, on named
/// parameters; names the DOF's model does not have are ignored.
struct PriorInformation {
  std::vector<std::string> names;
  Eigen::MatrixXd M;
  /// From a covariance of estimates (M = C⁻¹, pseudo-inverse on its range); an empty
  /// covariance (no estimates yet) gives no information (no names, 0 × 0 M). Throws
  /// std::invalid_argument unless C is square with one row per name.
  static PriorInformation FromCovariance(const std::vector<std::string>& names,
                                         const Eigen::MatrixXd& covariance);
};

struct PlannerOptions {
  BoxOptions box;
  Robustness robustness = Robustness::kMaximin;
  /// Sine designs are multimodal in the frequency (the trial's end phase): NLopt's global
  /// search. Steady-level weights are a smooth concave problem with an analytic gradient:
  /// either backend finds its optimum (tests cross-check them to 1e-7); NLopt's SLSQP does it
  /// in < 1 ms on ROMEO where Ipopt 3.11 (MUMPS, limited-memory BFGS) takes 50-600 ms, a
  /// quarter of the whole schedule's time (docs/performance.md, "Planner").
  SolverBackend sine_backend = SolverBackend::kNlopt;
  SolverBackend steady_backend = SolverBackend::kNlopt;
  /// Budgets tuned on ROMEO surge's sine design (bench/planner_bench --budgets): DIRECT-L with
  /// 150 evaluations, then COBYLA from its best point and from the seed-rule point, 40 each,
  /// reach the criterion of 500-1000-evaluation searches to 0.01 (80 + 30 stop at a local
  /// optimum 0.15 lower, 7% worse in σ).
  SolverOptions solver = [] {
    SolverOptions o;
    o.max_global_evaluations = 150;
    o.max_local_evaluations = 40;
    return o;
  }();
  /// Longest trial (s). CHOSEN: 4 minutes, about a pool team's battery-safe open-loop run;
  /// ref 000's trials last 1-2 minutes.
  double max_trial_duration_s = 240.0;
  /// Pause between trials for pool time (repositioning, s); as the virtual pool's default.
  double pause_s = 60.0;
  /// Largest RK4 step (s); the step is otherwise half the shortest time constant.
  double max_step_s = 0.5;
  /// Shortest time constant (s) over the box the planner simulates; a box reaching below it is
  /// refused (model::InputError naming the time constant), so that a design's work stays bounded:
  /// at most max_trial_duration_s / (least / 2) RK4 steps per simulation. CHOSEN 2 ms: a
  /// BlueROV2's fastest, yaw at full thrust, is about 60 ms; 2 ms is a time constant no vehicle
  /// a pool hosts reaches (a design then runs in minutes, not hours) and one that only a wrong
  /// unit or a diverged estimate gives.
  double least_time_constant_s = 2e-3;
  /// Fewest samples of the DOF's fastest sensor per period of any sinusoid a design holds (a
  /// sine, a switched sine, a multisine's highest harmonic; a square's switches are bounded by
  /// their shortest piece instead); the default's reason at model::kDefaultSamplesPerPeriod.
  double samples_per_period = model::kDefaultSamplesPerPeriod;
  /// Values per box axis in hard-constraint checks (>= 2; 3 adds the axis midpoints).
  int check_grid = 3;
  /// Largest steady speed a design may ask for (0: no limit), at the fastest point of the box.
  /// Translations are limited by the pool. Rotations are not, and the a priori drag fits hold
  /// only where they were measured. CHOSEN 0.35 rad/s: ref 000 Fig. 11 spans ±20 °/s.
  double max_translation_speed = 0.0;
  double max_rotation_rate = 0.35;
  /// Threads that plan independent designs at once (0: one per core): the DOFs of a
  /// schedule, the verdict's box points, the loop's a priori schedules and candidate trials of
  /// several DOFs. The results do not depend on it: each design is planned on its own and
  /// taken in the serial order.
  int threads = 0;
  /// Count each trial's initial state as known (fisher_information.h): the information is then
  /// an upper bound of what the identification can use. Off for every design and predicted σ;
  /// the pool verdict judges "none" on it (pool_verdict.h).
  bool start_known = false;

  bool IsValid(std::string* error) const;
  /// `threads`, or 1 when a backend is Ipopt: its linear solver (MUMPS) is not thread-safe.
  int Threads() const;
};

/// Outcome of the hard-constraint check of one trial (contract §check-pool).
struct TrialCheck {
  bool feasible = true;
  std::vector<std::string> reasons;  ///< each violated constraint, by how much
  /// Which constraints are violated (each with its reason): the travel over the box (the pool's
  /// side or the tether's turns), a thruster's reversal, a thruster below min_thrust or beyond
  /// its range, the duration.
  bool exceeds_travel = false;
  bool reversal = false;
  bool thrust_out_of_range = false;
  bool exceeds_duration = false;
  std::array<double, 2> travel = {0, 0};  ///< excursion from the start over the box [min, max]
  double span = 0.0;                      ///< travel[1] - travel[0]
  double available = 0.0;                 ///< free travel of the pool for this DOF (inf: none)
  double thrust_min = 0.0;
  double thrust_max_ratio = 0.0;
};

class DofPlanningProblem {
 public:
  /// The a priori context of `dof` (box from the vehicle file); notes on assumptions made are
  /// appended to `notes`. Throws model::InputError if the DOF has no sensor or no mapping.
  static std::unique_ptr<DofPlanningProblem> APriori(const model::Vehicle& vehicle,
                                                     const model::Pool& pool, model::Dof dof,
                                                     const PlannerOptions& options,
                                                     std::vector<std::string>* notes);
  /// A context with a given box (e.g. about current estimates).
  DofPlanningProblem(const model::Vehicle& vehicle, const model::Pool& pool, model::Dof dof,
                     ParameterBox box, const PlannerOptions& options);

  const model::Vehicle& vehicle() const { return vehicle_; }
  const model::Pool& pool() const { return pool_; }
  model::Dof dof() const { return dof_; }
  const model::DofModel& model() const { return *model_; }
  const ParameterBox& box() const { return box_; }
  const PlannerOptions& options() const { return options_; }
  const model::DofSensors& sensors() const { return sensors_; }
  /// The sensors as the optimisers see them: a sensor faster than one sample per RK4 step is
  /// replaced by one at 1/step_s with σ·sqrt(rate'/rate), the same information per unit time
  /// (a coarser Riemann sum of ∫ SᵀS dt; the optimum moves by far less than the solver's
  /// tolerance, and every reported figure uses the real sensors).
  const model::DofSensors& design_sensors() const { return design_sensors_; }
  /// Parameter vectors at the design points (centre first) and the check grid.
  const std::vector<Eigen::VectorXd>& design_thetas() const { return design_thetas_; }
  const std::vector<Eigen::VectorXd>& check_thetas() const { return check_thetas_; }
  /// Free travel along the DOF: m within the pool's walls less the margins, or for a rotation
  /// rad within the tether's twist (2π·max_turns).
  double available() const { return pool_.FreeTravel(dof_); }
  double step_s() const { return step_s_; }
  /// Shortest and longest linearised time constants m/k_L over the box (s).
  double shortest_time_constant() const { return tc_min_; }
  /// The shortest period (s) a design's wave may have: options().samples_per_period samples of
  /// the DOF's fastest sensor.
  double ShortestPeriod() const;
  double longest_time_constant() const { return tc_max_; }
  /// The model of one trial: the DOF's model with only the installation coefficients of the
  /// (mapping, direction) pairs the trial uses (the others have no sensitivity; leaving them
  /// out makes the sensitivity simulation cheaper), and the map back to the DOF's parameters.
  struct TrialModel {
    std::unique_ptr<model::DofModel> model;
    std::vector<int> to_dof;  ///< to_dof[i]: index in the DOF's theta of trial parameter i
    std::vector<Eigen::VectorXd> design_thetas, check_thetas;
    /// The trial's information (trial parameters) as the DOF's (np × np, zeros elsewhere).
    Eigen::MatrixXd Embed(const Eigen::MatrixXd& M, int np) const;
  };
  /// Cached by the set of installation coefficients; thread-safe (the families of an inertia
  /// trial are optimised on several threads, switched_design.cc).
  const TrialModel& ModelFor(const model::TrialDesign& design) const;

  /// Admissible |phi_n| of a mapping in one direction (thrust_limits.h), capped so that the
  /// steady speed at the fastest box point stays within the options' speed limit.
  ForceRange ForceRangeFor(int mapping, int sign) const;

  /// Index of a parameter, -1 if absent.
  int Index(const std::string& name) const { return model_->ParameterIndex(name); }
  std::vector<int> Indices(const std::vector<std::string>& names) const;
  /// The prior information in this model's parameter order (zero if none). Throws
  /// std::invalid_argument when prior->M is not square with one row per name.
  Eigen::MatrixXd PriorMatrix(const PriorInformation* prior) const;

  /// Fisher information of a trial (absolute units) at every design point.
  std::vector<Eigen::MatrixXd> Information(const model::TrialDesign& design) const;
  /// As Information, as the optimisers see it: the trial `input` of `duration` s in its model
  /// `tm` with the design sensors; *travel gets the span [min, max] of its position from the
  /// start over the design points (at least [0, 0]).
  std::vector<Eigen::MatrixXd> DesignInformation(const TrialModel& tm,
                                                 const model::Excitation& input, double duration,
                                                 std::array<double, 2>* travel) const;
  /// Criterion values at every design point of (trial information + extra), relative units.
  std::vector<double> CriterionValues(const std::vector<Eigen::MatrixXd>& M, Criterion c,
                                      const std::vector<int>& interest,
                                      bool* any_singular = nullptr) const;
  /// Hard constraints of a trial: thrusters (sign, min_thrust, limits), travel over the check
  /// grid within the pool's free length/width/depth or the tether's turns, duration limit.
  /// The one place these limits are checked.
  TrialCheck Check(const model::TrialDesign& design) const;

 private:
  const model::Vehicle& vehicle_;
  model::Pool pool_;
  model::Dof dof_;
  ParameterBox box_;
  PlannerOptions options_;
  std::unique_ptr<model::DofModel> model_;
  model::DofSensors sensors_, design_sensors_;
  std::vector<Eigen::VectorXd> design_thetas_, check_thetas_;
  mutable std::map<std::string, std::unique_ptr<TrialModel>> trial_models_;
  mutable std::mutex trial_models_mutex_;
  double step_s_ = 0.1, tc_min_ = 1.0, tc_max_ = 1.0;
};

/// Per design point, a trial's `information` plus the `prior` (a schedule's other trials, in
/// the same layout) where the prior has that point at the same size.
std::vector<Eigen::MatrixXd> WithPrior(std::vector<Eigen::MatrixXd> information,
                                       const std::vector<Eigen::MatrixXd>& prior);

}  // namespace uuvplan::planner
