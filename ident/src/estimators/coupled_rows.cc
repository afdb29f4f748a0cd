#include "estimators/coupled_rows.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "uuvplan/model/coupled_simulator.h"

namespace uuvplan::ident::internal {
namespace {

using model::Horizontal;

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
std::vector<double> Knots(const CoupledTrialData& d, double span) {
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

}  // namespace

std::string PrepareCoupledTrial(const model::TrialLog& log, int index,
                                const CoupledLsOptions& options, CoupledTrialData* out) {
  const std::string where = "trial " + std::to_string(index + 1);
  double input_scale = 0.0;
  for (int i = 0; i < 3; ++i) {
    const model::Dof dof = model::kHorizontalDofs[i];
    const std::string name(model::DofName(dof));
    if (!log.HasVelocity(dof)) return where + ": no vel_" + name + " column (the coupled model "
                                              "needs the measured u, v and r)";
    if (!log.HasForce(dof)) return where + ": no force_" + name + " column";
    for (std::size_t k = 0; k < log.size(); ++k) {
      if (std::isnan(log.force[model::Index(dof)][k])) continue;
      out->force_t[i].push_back(log.t[k] - log.t.front());
      out->force[i].push_back(log.force[model::Index(dof)][k]);
    }
    const double scale = InputTimeScale(out->force_t[i], out->force[i]);
    if (scale > 0) input_scale = input_scale > 0 ? std::min(input_scale, scale) : scale;
  }
  double span = 0.0;
  for (int i = 0; i < 3; ++i) {
    const model::Dof dof = model::kHorizontalDofs[i];
    Signal s;
    for (std::size_t k = 0; k < log.size(); ++k) {
      const double v = log.velocity[model::Index(dof)][k];
      if (!std::isnan(v)) s.t.push_back(log.t[k] - log.t.front()), s.y.push_back(v);
    }
    if (s.size() < 10) return where + ": fewer than 10 samples of vel_" +
                              std::string(model::DofName(dof));
    const double step = MedianStep(s.t, 0, s.size());
    SavitzkyGolayOptions sg;
    sg.order = options.sg_order;
    sg.window = ChosenWindow(options.sg_window, 1.0 / step, input_scale);
    out->velocity[i] = SavitzkyGolay(s, sg);
    out->window = std::max(out->window, sg.window);
    span = std::max(span, (sg.window - 1) * step);
    out->thrust[i] = model::MakeHeldExcitation(out->force_t[i], out->force[i],
                                               std::vector<int>(out->force[i].size(), -1),
                                               s.t.back());
  }
  const std::vector<double> knots = Knots(*out, span);
  if (knots.size() < 2) return where + ": too short for one row of the one-step least squares";
  for (std::size_t k = 0; k < knots.size(); ++k) {
    out->knot.push_back(out->grid.size());
    out->grid.push_back(knots[k]);
    if (k + 1 == knots.size()) break;
    const int n = static_cast<int>(std::ceil(span / options.step_s));
    for (int j = 1; j < n; ++j) out->grid.push_back(knots[k] + span * j / n);
  }
  return "";
}

std::vector<Horizontal> MeasuredVelocities(const CoupledTrialData& trial) {
  std::vector<Horizontal> nu(trial.grid.size());
  for (std::size_t k = 0; k < trial.grid.size(); ++k) {
    for (int i = 0; i < 3; ++i) {
      nu[k][i] = Interpolate(trial.velocity[i].t, trial.velocity[i].value, trial.grid[k]);
    }
  }
  return nu;
}

std::vector<Horizontal> SimulatedVelocities(const CoupledTrialData& trial,
                                            const model::CoupledHorizontalModel& model,
                                            double step_s) {
  const double t0 = trial.grid.front();
  std::vector<double> t_out, breakpoints;
  for (double t : trial.grid) t_out.push_back(t - t0);
  for (const auto& rows : trial.force_t) {
    for (double t : rows) {
      if (t > t0) breakpoints.push_back(t - t0);
    }
  }
  auto thrust = [&](double t) {
    return Horizontal(trial.thrust[0]->Force(t + t0), trial.thrust[1]->Force(t + t0),
                      trial.thrust[2]->Force(t + t0));
  };
  const Horizontal nu0 = MeasuredVelocities(trial).front();
  return model::SimulateCoupled(model, thrust, nu0, t_out, breakpoints, step_s).nu;
}

CoupledRows BuildCoupledRows(const std::vector<CoupledTrialData>& trials,
                             const std::vector<std::vector<Horizontal>>& nu) {
  std::size_t n = 0;
  for (const auto& d : trials) n += 3 * (d.knot.size() - 1);
  CoupledRows rows;
  rows.H.setZero(static_cast<Eigen::Index>(n), model::kCoupledParameterCount);
  rows.y.setZero(static_cast<Eigen::Index>(n));
  Eigen::Index row = 0;
  for (std::size_t c = 0; c < trials.size(); ++c) {
    const CoupledTrialData& d = trials[c];
    for (int i = 0; i < 3; ++i) {
      for (std::size_t k = 0; k + 1 < d.knot.size(); ++k, ++row) {
        const std::size_t a = d.knot[k], b = d.knot[k + 1];
        // m_i·Δν_i + ∫h_i(ν)·θ = ∫τ_i (coupled_ls.h), ∫ by the trapezoid rule on the grid.
        rows.H(row, model::CoupledIndex(i, "m")) = nu[c][b][i] - nu[c][a][i];
        for (std::size_t g = a; g < b; ++g) {
          const double h = d.grid[g + 1] - d.grid[g];
          rows.H.row(row) += 0.5 * h *
                             (model::CoupledRegressor(i, nu[c][g]) +
                              model::CoupledRegressor(i, nu[c][g + 1])).transpose();
        }
        rows.y[row] = HeldIntegral(d.force_t[i], d.force[i], d.grid[a], d.grid[b]);
        rows.equation.push_back(i);
        rows.group.push_back(static_cast<int>(3 * c + i));
      }
    }
  }
  return rows;
}

}  // namespace uuvplan::ident::internal
