// Fisher information of one trial for the parameters theta of a DOF's model (contract
// §Conventions), for the sensors the vehicle really has:
//
//   M(xi, theta) = Σ_k w_k · S_kᵀ Σ⁻¹ S_k,   S_k = ∂y(t_k)/∂theta
//
// y = [position, velocity] as the sensors see them (model::SimulateMeasured), S from the
// forward sensitivity equations integrated with the state (model/simulator.h). Each sensor
// samples at t = i/rate_hz from the trial start (position: sonar, depth-meter, compass; velocity:
// DVL, gyro) with independent Gaussian noise of its sigma, so Σ is diagonal per sample.
//
// Weights w_k are 1, except one extra sample just after the end of the trial, weighted by the
// fraction of a sample interval the trial covers beyond its last whole sample: M is then a
// continuous function of the duration (a solver may move the duration smoothly), and differs
// from the strictly discrete information by at most one sample.
//
// The trial's initial state is not known to the identification: its output error fits the
// initial position (position sensor) and velocity of every trial with θ (ref 000 eqs. 16-19
// fit m·ξ0 + k·χ0 likewise). M is the information on θ with those two profiled out (the Schur
// complement of the information of θ, χ0, ξ0), so that a steady run's constant position lag
// behind its start, which a free χ0 absorbs, is not counted as information on m.
#pragma once

#include <Eigen/Dense>
#include <map>
#include <vector>

#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/excitation.h"
#include "uuvplan/model/multi_dof_model.h"
#include "uuvplan/model/vehicle.h"

namespace uuvplan::planner {

/// What one simulation of a trial at one theta gives the planner.
struct TrialResponse {
  /// Fisher information on theta, the trial's initial state profiled out (see above), absolute
  /// units, rows/cols in DofModel::parameter_names() order (empty when not asked for).
  Eigen::MatrixXd M;
  /// The information of (theta, chi0, xi0) M is the Schur complement of: theta's rows/cols
  /// first, then the initial position (only with a position sensor), then the initial velocity
  /// (empty when not asked for). Linear in the samples' weights, unlike M.
  Eigen::MatrixXd M_joint;
  double position_min = 0.0;  ///< extremes of the position over [0, duration] (m or rad)
  double position_max = 0.0;
  double velocity_min = 0.0;  ///< extremes of the velocity over [0, duration]
  double velocity_max = 0.0;
  double final_velocity = 0.0;  ///< velocity at the end of the trial
};

/// The RK4 step as a fraction of the time constant it resolves: half of it.
inline constexpr double kStepPerTimeConstant = 0.5;

/// The RK4 step of a DOF's plain simulations: half the shortest time constant m/k_L over the
/// box, at most `max_step_s` (steps also end at every sensor sample). SimulateTrial's
/// information applies the rule where the trial is: each step at most half the local time
/// constant (model::SimulationOptions::time_constant_fraction). On ROMEO surge the predicted σ
/// then differ from those at a 0.01 s step by less than 1e-6 relative
/// (tests/planner/fisher_information_test.cc checks the convergence).
double ChooseStep(double shortest_time_constant_s, double max_step_s = 0.5);

/// Simulates `input` from rest for `duration` at `theta` and returns the position/velocity
/// extremes and, if `with_information`, the Fisher information of the DOF's sensors on theta,
/// the initial position and velocity profiled out. `step_s` is the largest step: with
/// information each step is also at most half the local time constant.
/// Throws std::invalid_argument if the DOF has no sensor, or a sensor has rate <= 0 or
/// sigma <= 0 (the vehicle reader rejects those first).
/// With `start_known` M is the information with the initial state known instead (theta's block
/// of the joint information, an upper bound of the profiled M; M_joint is then left empty).
TrialResponse SimulateTrial(const model::DofModel& model, const Eigen::VectorXd& theta,
                            const model::Excitation& input, const model::DofSensors& sensors,
                            double duration, double step_s, bool with_information,
                            bool start_known = false);

/// The Fisher information on the global θ of a joint trial (model/multi_dof_model.h) from
/// rest, of the sensors of each of the model's DOFs (sensors.at(dof): its position state — in
/// the planar model the pool-frame x, y and the heading ψ — and its body-frame velocity), as
/// SimulateTrial's M with the initial state known (`start_known`): one simulation with the
/// forward sensitivities. Throws std::invalid_argument as SimulateTrial.
Eigen::MatrixXd JointInformation(const model::MultiDofModel& model, const Eigen::VectorXd& theta,
                                 const model::JointConditions& conditions,
                                 const std::map<model::Dof, model::DofSensors>& sensors,
                                 double duration, double step_s);

/// The position of the trial on a fine grid (every `step_s`) for constraint checks:
/// returns the extremes over [0, duration] of every simulated step, not only sensor samples.
TrialResponse SimulateExcursion(const model::DofModel& model, const Eigen::VectorXd& theta,
                                const model::Excitation& input, double duration, double step_s);

/// Position trace of a trial on a uniform grid t_i = i·dt, i = 0..n (for duration search).
struct PositionTrace {
  double dt = 0.0;
  std::vector<double> position;
  std::vector<double> velocity;
};
PositionTrace TracePosition(const model::DofModel& model, const Eigen::VectorXd& theta,
                            const model::Excitation& input, double duration, double dt,
                            double step_s);

}  // namespace uuvplan::planner
