#include "estimators/joint_rows.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "uuvplan/model/simulator.h"

namespace uuvplan::ident::internal {
namespace {

// ∫_a^b of a force held from each row to the next (the first value before the first row).
double HeldIntegral(const std::vector<double>& t, const std::vector<double>& f, double a,
                    double b) {
  if (t.empty()) return 0.0;
  double sum = 0.0;
  const auto first = std::upper_bound(t.begin(), t.end(), a);
  for (std::size_t k = first == t.begin() ? 0 : first - t.begin() - 1; k < t.size() && t[k] < b;
       ++k) {
    const double lo = k == 0 ? -std::numeric_limits<double>::infinity() : t[k];
    const double hi = k + 1 < t.size() ? t[k + 1] : std::numeric_limits<double>::infinity();
    const double from = std::max(lo, a), to = std::min(hi, b);
    if (to > from) sum += f[k] * (to - from);
  }
  return sum;
}

// The knots: one window span apart over the part of the trial where no DOF's filter is at an
// edge (the end polynomials there are distorted, notes/pitfalls.md).
std::vector<double> Knots(const JointTrialData& d, double span) {
  double start = -std::numeric_limits<double>::infinity();
  double end = std::numeric_limits<double>::infinity();
  for (const SmoothedSignal& s : d.velocity) {
    double first = std::numeric_limits<double>::quiet_NaN(), last = first;
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s.edge[i]) continue;
      if (std::isnan(first)) first = s.t[i];
      last = s.t[i];
    }
    if (std::isnan(first)) return {};
    start = std::max(start, first);
    end = std::min(end, last);
  }
  std::vector<double> knots;
  for (double t = start; t <= end + 1e-9; t += span) knots.push_back(t);
  return knots;
}

// DOF i's logged force rows (times from the log's start); "" or what the log lacks.
std::string ReadForces(const model::TrialLog& log, model::Dof dof, const std::string& where,
                       std::vector<double>* t, std::vector<double>* force) {
  const std::string name(model::DofName(dof));
  if (!log.HasVelocity(dof)) {
    return where + ": no vel_" + name +
           " column (a joint model needs the measured velocity of "
           "each of its DOFs)";
  }
  if (!log.HasForce(dof)) return where + ": no force_" + name + " column";
  for (std::size_t k = 0; k < log.size(); ++k) {
    if (std::isnan(log.force[model::Index(dof)][k])) continue;
    t->push_back(log.t[k] - log.t.front());
    force->push_back(log.force[model::Index(dof)][k]);
  }
  return "";
}

// The grid: every knot and `span / step_s` sub-steps between consecutive ones.
void MakeGrid(const std::vector<double>& knots, double span, double step_s, JointTrialData* d) {
  for (std::size_t k = 0; k < knots.size(); ++k) {
    d->knot.push_back(d->grid.size());
    d->grid.push_back(knots[k]);
    if (k + 1 == knots.size()) break;
    const int n = static_cast<int>(std::ceil(span / step_s));
    for (int j = 1; j < n; ++j) d->grid.push_back(knots[k] + span * j / n);
  }
}

}  // namespace

std::string PrepareJointTrial(const model::TrialLog& log, int index,
                              const model::MultiDofModel& model, const JointLsOptions& options,
                              JointTrialData* out) {
  const std::string where = "trial " + std::to_string(index + 1);
  const int n = model.num_dofs();
  out->force_t.resize(n);
  out->force.resize(n);
  double input_scale = 0.0;
  for (int i = 0; i < n; ++i) {
    const std::string error =
        ReadForces(log, model.dof(i), where, &out->force_t[i], &out->force[i]);
    if (!error.empty()) return error;
    const double scale = InputTimeScale(out->force_t[i], out->force[i]);
    if (scale > 0) input_scale = input_scale > 0 ? std::min(input_scale, scale) : scale;
  }
  double span = 0.0;
  for (int i = 0; i < n; ++i) {
    const model::Dof dof = model.dof(i);
    Signal s;
    for (std::size_t k = 0; k < log.size(); ++k) {
      const double v = log.velocity[model::Index(dof)][k];
      if (!std::isnan(v)) s.t.push_back(log.t[k] - log.t.front()), s.y.push_back(v);
    }
    if (s.size() < 10) {
      return where + ": fewer than 10 samples of vel_" + std::string(model::DofName(dof));
    }
    const double step = MedianStep(s.t, 0, s.size());
    SavitzkyGolayOptions sg;
    sg.order = options.sg_order;
    sg.window = ChosenWindow(options.sg_window, 1.0 / step, input_scale);
    out->velocity.push_back(SavitzkyGolay(s, sg));
    out->window = std::max(out->window, sg.window);
    span = std::max(span, (sg.window - 1) * step);
  }
  const std::vector<double> knots = Knots(*out, span);
  if (knots.size() < 2) return where + ": too short for one row of the one-step least squares";
  MakeGrid(knots, span, options.step_s, out);
  return "";
}

Eigen::MatrixXd MeasuredVelocities(const JointTrialData& trial) {
  Eigen::MatrixXd nu(trial.grid.size(), trial.velocity.size());
  for (std::size_t k = 0; k < trial.grid.size(); ++k) {
    for (std::size_t i = 0; i < trial.velocity.size(); ++i) {
      nu(k, i) = Interpolate(trial.velocity[i].t, trial.velocity[i].value, trial.grid[k]);
    }
  }
  return nu;
}

Eigen::MatrixXd SimulatedVelocities(const JointTrialData& trial, const model::MultiDofModel& model,
                                    const Eigen::VectorXd& theta, double step_s) {
  // The clock from the first knot; the thrust held as logged (mapping -1: η = 1).
  const double t0 = trial.grid.front();
  std::vector<double> t_out;
  for (double t : trial.grid) t_out.push_back(t - t0);
  std::vector<std::unique_ptr<model::Excitation>> thrust;
  model::JointConditions c;
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(model.num_states());
  for (int i = 0; i < model.num_dofs(); ++i) {
    std::vector<double> t = trial.force_t[i];
    for (double& s : t) s -= t0;
    thrust.push_back(model::MakeHeldExcitation(t, trial.force[i], std::vector<int>(t.size(), -1),
                                               std::numeric_limits<double>::infinity()));
    c.inputs.push_back(thrust.back().get());
    x0[model.state_offset(i) + 1] = Interpolate(trial.velocity[i].t, trial.velocity[i].value, t0);
  }
  model::SimulationOptions options;
  options.step_s = step_s;
  const model::Trajectory x = model::Simulate(model, theta, c, t_out, options, &x0);
  Eigen::MatrixXd nu(t_out.size(), model.num_dofs());
  for (int i = 0; i < model.num_dofs(); ++i) nu.col(i) = x.x.col(model.state_offset(i) + 1);
  return nu;
}

JointRows BuildJointRows(const model::MultiDofModel& model,
                         const std::vector<JointTrialData>& trials,
                         const std::vector<Eigen::MatrixXd>& nu) {
  const int n = model.num_dofs();
  std::size_t count = 0;
  for (const auto& d : trials) count += n * (d.knot.size() - 1);
  JointRows rows;
  rows.H.setZero(static_cast<Eigen::Index>(count), model.num_parameters());
  rows.y.setZero(static_cast<Eigen::Index>(count));
  Eigen::Index row = 0;
  for (std::size_t c = 0; c < trials.size(); ++c) {
    const JointTrialData& d = trials[c];
    for (int i = 0; i < n; ++i) {
      int mass = -1;  // the global index of m_i (local parameter 0)
      for (const model::TieEntry& e : model.tie(i)) mass = e.local == 0 ? e.global : mass;
      for (std::size_t k = 0; k + 1 < d.knot.size(); ++k, ++row) {
        const std::size_t a = d.knot[k], b = d.knot[k + 1];
        // m_i·Δξ_i + ∫r_i(ν)·θ = ∫φ_i (joint_ls.h; r_i: MultiDofModel::EquationRegressor), ∫
        // by the trapezoid rule on the grid.
        rows.H(row, mass) = nu[c](b, i) - nu[c](a, i);
        for (std::size_t g = a; g < b; ++g) {
          const double h = d.grid[g + 1] - d.grid[g];
          rows.H.row(row) += 0.5 * h *
                             (model.EquationRegressor(i, nu[c].row(g)) +
                              model.EquationRegressor(i, nu[c].row(g + 1)));
        }
        rows.y[row] = HeldIntegral(d.force_t[i], d.force[i], d.grid[a], d.grid[b]);
        rows.equation.push_back(i);
        rows.group.push_back(static_cast<int>(n * c + i));
      }
    }
  }
  return rows;
}

}  // namespace uuvplan::ident::internal
