// Free-run simulation of a DofModel or a MultiDofModel from a given initial state with
// fixed-step RK4, and the forward sensitivity equations dS/dt = A·S + B, S = ∂x/∂theta,
// integrated with the state (the same RK4 stages), for Fisher information and output-error
// fits. One loop serves both models (simulator.cc), instantiated per model so that the 1-DOF
// model's states unroll.
#pragma once

#include <Eigen/Dense>
#include <functional>
#include <vector>

#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/multi_dof_model.h"
#include "uuvplan/model/times_view.h"

namespace uuvplan::model {

struct SimulationOptions {
  double step_s = 0.01;        ///< largest RK4 step (s); steps also end at every breakpoint
  bool sensitivities = false;  ///< also integrate S = ∂x/∂theta
  /// With sensitivities, a last column of S: ∂x/∂ξ0, the sensitivity to the initial velocity
  /// (dS/dt = A·S from S(0) = e_velocity; the 1-DOF model only).
  bool initial_velocity_column = false;
  /// With sensitivities and > 0: each step between outputs at most this fraction of the
  /// shortest local time constant 1/ρ(A), A = ∂f/∂x at the previous step (step_s stays the
  /// largest). 0: every step step_s.
  double time_constant_fraction = 0.0;
};

struct Trajectory {
  std::vector<double> t;  ///< output times (s)
  Eigen::MatrixXd x;      ///< x(i, s): state s at t[i]; s = 0 position, 1 velocity, 2 actuator
  /// With sensitivities: S[s](i, j) = ∂x_s(t_i)/∂theta_j.
  std::vector<Eigen::MatrixXd> S;
};

/// Integrates from x0 (default: rest) at t = 0 and reports the state at `output_times`
/// (sorted, >= 0). Every step ends at breakpoints of the input and at output times.
Trajectory Simulate(const DofModel& model, const Eigen::VectorXd& theta,
                    const TrialConditions& conditions, TimesView output_times,
                    const SimulationOptions& options, const Eigen::VectorXd* x0 = nullptr);

/// The joint model (multi_dof_model.h) from x0 (default: rest), as Simulate above: x(i, s) is
/// joint state s (MultiDofModel::state_offset), S[s](i, j) = ∂x_s(t_i)/∂θ_j of the global θ.
Trajectory Simulate(const MultiDofModel& model, const Eigen::VectorXd& theta,
                    const JointConditions& conditions, TimesView output_times,
                    const SimulationOptions& options, const Eigen::VectorXd* x0 = nullptr);

/// One output of a simulation: its index in the output times, the state x (num_states values)
/// and, with sensitivities, S row-major (S[s·P + j] = ∂x_s/∂theta_j, P = num_parameters), else
/// null. Both are valid during the call only.
using OutputVisitor = std::function<void(std::size_t i, const double* x, const double* S)>;

/// What a visited simulation reports: the state (as Simulate) or what the sensors see (as
/// SimulateMeasured: the model's sensor delay applied).
enum class Seen { kState, kBySensors };

/// Simulate or SimulateMeasured (`seen`), each output handed to `visit` in order instead of
/// stored: memory independent of the number of outputs (a fit streams its residuals from it).
/// Seen by sensors with a sensor delay, only without sensitivities (std::invalid_argument).
void SimulateVisiting(const DofModel& model, const Eigen::VectorXd& theta,
                      const TrialConditions& conditions, TimesView output_times,
                      const SimulationOptions& options, const Eigen::VectorXd* x0, Seen seen,
                      const OutputVisitor& visit);

/// What the sensors see: position and velocity at `times` delayed by the model's
/// sensor_delay tau (y(t) = x(t - tau), rest before t = 0), with sensitivities if asked
/// (∂y/∂tau = -dx/dt(t - tau)). Columns of the result as in Simulate: 0 position,
/// 1 velocity (2 actuator force with thruster lag).
Trajectory SimulateMeasured(const DofModel& model, const Eigen::VectorXd& theta,
                            const TrialConditions& conditions, TimesView times,
                            const SimulationOptions& options, const Eigen::VectorXd* x0 = nullptr);

}  // namespace uuvplan::model
