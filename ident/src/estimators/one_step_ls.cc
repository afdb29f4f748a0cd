#include "uuvplan/ident/estimators/one_step_ls.h"

#include <Eigen/LU>
#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "options_check.h"
#include "uuvplan/ident/estimators/regression.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/simulator.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {

PhysicalParameters ToPhysical(const SeedCoefficients& c) {
  PhysicalParameters p;
  p.m = 1.0 / c.gamma;
  p.d_L = -c.alpha / c.gamma;
  p.d_Q = -c.beta / c.gamma;
  p.b = -c.delta / c.gamma;
  p.bias = -p.b;
  return p;
}

Eigen::Matrix4d ToPhysicalJacobian(const SeedCoefficients& c) {
  const double g = c.gamma, g2 = g * g;
  Eigen::Matrix4d J = Eigen::Matrix4d::Zero();
  // rows m, d_L, d_Q, bias; columns α, β, γ, δ
  J(0, 2) = -1.0 / g2;
  J(1, 0) = -1.0 / g;
  J(1, 2) = c.alpha / g2;
  J(2, 1) = -1.0 / g;
  J(2, 2) = c.beta / g2;
  J(3, 3) = 1.0 / g;
  J(3, 2) = -c.delta / g2;
  return J;
}

bool OneStepOptions::IsValid(std::string* error) const {
  return Require(max_step_s > 0 && max_condition > 1 && newey_west_lags >= 0,
                 "OneStepOptions: max_step_s > 0, max_condition > 1, newey_west_lags >= 0", error);
}

namespace {

// One run's knots (ref 002 eq. 20's integration intervals): samples of the velocity estimate
// at least `window` apart, as indices; and the trial they belong to.
struct KnotRun {
  std::size_t trial = 0;
  std::vector<std::size_t> knots;
};

std::vector<std::size_t> RunKnots(const SmoothedSignal& v, std::size_t begin, std::size_t end,
                                  double window) {
  std::vector<std::size_t> knots;
  for (std::size_t i = begin; i < end; ++i) {
    if (!knots.empty() && v.t[i] - v.t[knots.back()] < window - 1e-9) continue;
    knots.push_back(i);
  }
  return knots;
}

// Every trial's runs of at least two knots, in order; the knot spacing is one SG window (its
// span in time) unless told otherwise.
std::vector<KnotRun> KnotRuns(const std::vector<const TrialData*>& trials,
                              const OneStepOptions& o) {
  std::vector<KnotRun> out;
  for (std::size_t ti = 0; ti < trials.size(); ++ti) {
    const TrialData& trial = *trials[ti];
    const SmoothedSignal& v = trial.velocity_estimate;
    double window = o.window_s;
    if (window < 0) {
      const double span = v.size() > 1 ? (v.t.back() - v.t.front()) / (v.size() - 1) : 0.0;
      window = span * (trial.sg_window - 1);
    }
    for (const auto& [begin, end] : SmoothRuns(trial, o.split_at_force_jumps)) {
      std::vector<std::size_t> knots = RunKnots(v, begin, end, window);
      if (knots.size() >= 2) out.push_back({ti, std::move(knots)});
    }
  }
  return out;
}

}  // namespace

namespace {

// The rows of BuildOneStepRows into `F`, and with `rows` Y and the bookkeeping (knot times,
// groups, runs, weights, noise σ); along `instrument` or a shifted velocity as
// OneStepRegressors. Sized once: grown by doubling, a million-sample trial's rows held up to
// twice their size at the one-step stage's peak.
void FillRows(const model::DofModel& model, const std::vector<const TrialData*>& trials,
              const Eigen::VectorXd& theta, const std::vector<int>& free, const OneStepOptions& o,
              const std::vector<SmoothedSignal>* instrument, double velocity_shift,
              Eigen::MatrixXd* F, OneStepRows* rows) {
  std::vector<int> fixed_linear;
  for (int j : LinearParameters(model)) {
    if (std::find(free.begin(), free.end(), j) == free.end()) fixed_linear.push_back(j);
  }
  const std::vector<KnotRun> runs = KnotRuns(trials, o);
  std::size_t n_rows = 0;
  for (const KnotRun& run : runs) n_rows += run.knots.size() - 1;
  F->resize(static_cast<Eigen::Index>(n_rows), static_cast<Eigen::Index>(1 + free.size()));
  Eigen::Index r = 0;
  for (const KnotRun& run : runs) {
    const TrialData* trial = trials[run.trial];
    const SmoothedSignal& v = trial->velocity_estimate;
    std::vector<double> kt(run.knots.size());
    for (std::size_t k = 0; k < run.knots.size(); ++k) kt[k] = v.t[run.knots[k]];
    const IntegratedRegressors ir =
        IntegrateRegressors(model, *trial, kt, theta, o.max_step_s,
                            instrument ? &(*instrument)[run.trial] : nullptr, velocity_shift);
    for (std::size_t k = 0; k + 1 < run.knots.size(); ++k, ++r) {
      double known = ir.h0[k];
      for (int j : fixed_linear) known += theta[j] * ir.H(k, j);
      (*F)(r, 0) = known;
      for (std::size_t c = 0; c < free.size(); ++c) {
        (*F)(r, static_cast<Eigen::Index>(c + 1)) = ir.H(k, free[c]);
      }
    }
  }
  if (!rows) return;
  std::vector<double> row_var(trials.size());
  double noise_var_sum = 0.0;
  int noise_count = 0;
  for (std::size_t ti = 0; ti < trials.size(); ++ti) {
    row_var[ti] = 2.0 * std::pow(VelocityNoiseSigma(*trials[ti]), 2);
    if (row_var[ti] > 0) {
      noise_var_sum += row_var[ti];
      ++noise_count;
    }
  }
  rows->noise_sigma = noise_count > 0 ? std::sqrt(noise_var_sum / noise_count) : 0.0;
  // Rows of trials without a known noise take the mean weight.
  const double mean_w = rows->noise_sigma > 0 ? 1.0 / (rows->noise_sigma * rows->noise_sigma) : 1.0;
  rows->Y.resize(static_cast<Eigen::Index>(n_rows));
  rows->t.reserve(n_rows);
  rows->group.reserve(n_rows);
  rows->run.reserve(n_rows);
  rows->weight.reserve(n_rows);
  r = 0;
  for (std::size_t ri = 0; ri < runs.size(); ++ri) {
    const std::vector<std::size_t>& knots = runs[ri].knots;
    const TrialData* trial = trials[runs[ri].trial];
    const SmoothedSignal& v = trial->velocity_estimate;
    const double var = row_var[runs[ri].trial];
    for (std::size_t k = 0; k + 1 < knots.size(); ++k, ++r) {
      rows->Y[r] =
          static_cast<double>(v.value[knots[k + 1]]) - static_cast<double>(v.value[knots[k]]);
      rows->t.push_back(v.t[knots[k + 1]]);
      rows->group.push_back(trial->index);
      rows->run.push_back(static_cast<int>(ri));
      rows->weight.push_back(var > 0 ? 1.0 / var : mean_w);
    }
  }
}

}  // namespace

OneStepRows BuildOneStepRows(const model::DofModel& model,
                             const std::vector<const TrialData*>& trials,
                             const Eigen::VectorXd& theta, const std::vector<int>& free,
                             const OneStepOptions& o) {
  OneStepRows rows;
  rows.free = free;
  FillRows(model, trials, theta, free, o, nullptr, 0.0, &rows.F, &rows);
  return rows;
}

Eigen::MatrixXd OneStepRegressors(const model::DofModel& model,
                                  const std::vector<const TrialData*>& trials,
                                  const Eigen::VectorXd& theta, const std::vector<int>& free,
                                  const OneStepOptions& o,
                                  const std::vector<SmoothedSignal>* instrument,
                                  double velocity_shift) {
  Eigen::MatrixXd F;
  FillRows(model, trials, theta, free, o, instrument, velocity_shift, &F, nullptr);
  return F;
}

void PsiToPhysical(const model::DofModel& model, const Eigen::VectorXd& theta_given,
                   const std::vector<int>& free, const Eigen::VectorXd& psi,
                   const Eigen::MatrixXd& psi_cov, Eigen::VectorXd* theta, Eigen::MatrixXd* cov) {
  const int np = model.num_parameters();
  const int P = static_cast<int>(psi.size());
  *theta = theta_given;
  const double g = psi[0];
  (*theta)[0] = 1.0 / g;
  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(np, P);
  J(0, 0) = -1.0 / (g * g);
  for (std::size_t c = 0; c < free.size(); ++c) {
    const int j = free[c];
    (*theta)[j] = psi[1 + c] / g;
    J(j, 1 + c) = 1.0 / g;
    J(j, 0) = -psi[1 + c] / (g * g);
  }
  *cov = J * psi_cov * J.transpose();
}

namespace {

// Whether any column 1 + c of the one-step rows F moves: parameter free[c] is excited.
std::vector<bool> MovedColumns(const Eigen::MatrixXd& F, std::size_t n) {
  std::vector<bool> moved(n, false);
  for (std::size_t c = 0; c < n && F.rows() > 0; ++c)
    moved[c] = F.col(1 + c).cwiseAbs().maxCoeff() > 0;
  return moved;
}

// The same test on the regressors integrated between consecutive velocity samples (the rows'
// columns without the knots), for trials too short for the knots.
std::vector<bool> MovedBetweenSamples(const model::DofModel& model,
                                      const std::vector<const TrialData*>& trials,
                                      const Eigen::VectorXd& theta, const std::vector<int>& free,
                                      const OneStepOptions& o) {
  std::vector<bool> moved(free.size(), false);
  for (const TrialData* d : trials) {
    const Eigen::MatrixXd H =
        IntegrateRegressors(model, *d, d->velocity_estimate.t, theta, o.max_step_s, nullptr).H;
    for (std::size_t c = 0; c < free.size() && H.rows() > 0; ++c) {
      moved[c] = moved[c] || H.col(free[c]).cwiseAbs().maxCoeff() > 0;
    }
  }
  return moved;
}

}  // namespace

OneStepRows ExcitedOneStepRows(const model::DofModel& model,
                               const std::vector<const TrialData*>& trials,
                               const Eigen::VectorXd& theta, std::vector<int> free,
                               const OneStepOptions& o, std::vector<std::string>* not_excited) {
  if (free.empty()) free = LinearParameters(model);
  OneStepRows rows = BuildOneStepRows(model, trials, theta, free, o);
  // Without rows (trials too short for the knots) excitation is read from the regressors
  // between consecutive samples: a direction never pushed is not excited, a trial too short for
  // the least squares still excites what it moves (the output error fits it).
  const std::vector<bool> moved = rows.F.rows() > 0
                                      ? MovedColumns(rows.F, free.size())
                                      : MovedBetweenSamples(model, trials, theta, free, o);
  std::vector<int> keep;
  for (std::size_t c = 0; c < free.size(); ++c) {
    if (moved[c]) {
      keep.push_back(static_cast<int>(c));
    } else {
      not_excited->push_back(model.parameter_names()[free[c]]);
    }
  }
  if (keep.size() != free.size()) {
    std::vector<int> kept_free;
    Eigen::MatrixXd F(rows.F.rows(), 1 + keep.size());
    F.col(0) = rows.F.col(0);
    for (std::size_t c = 0; c < keep.size(); ++c) {
      F.col(1 + c) = rows.F.col(1 + keep[c]);
      kept_free.push_back(free[keep[c]]);
    }
    rows.F = std::move(F);
    rows.free = kept_free;
  }
  return rows;
}

namespace {

// The rows of one DOF without the parameters no row excites.
OneStepRows DofRows(const OneStepDofInput& in, const OneStepOptions& o, OneStepDofResult* res) {
  return ExcitedOneStepRows(*in.model, in.trials, in.theta, in.free, o, &res->not_excited);
}

// The stacked block-diagonal system of all DOFs (ref 004 eqs. 12–14).
struct StackedSystem {
  Eigen::MatrixXd F;
  Eigen::VectorXd Y, W;
  std::vector<int> groups;
  std::vector<int> row0, col0;  // first row and column of each DOF's block
};

StackedSystem Stack(const std::vector<OneStepDofInput>& dofs,
                    const std::vector<OneStepRows>& rows) {
  std::vector<double> weight(dofs.size(), 1.0);
  int total_rows = 0, total_cols = 0;
  for (std::size_t d = 0; d < dofs.size(); ++d) {
    weight[d] = dofs[d].weight > 0        ? dofs[d].weight
                : rows[d].noise_sigma > 0 ? 1.0 / (rows[d].noise_sigma * rows[d].noise_sigma)
                                          : 1.0;
    total_rows += static_cast<int>(rows[d].Y.size());
    total_cols += static_cast<int>(rows[d].F.cols());
  }
  StackedSystem s{Eigen::MatrixXd::Zero(total_rows, total_cols),
                  Eigen::VectorXd(total_rows),
                  Eigen::VectorXd(total_rows),
                  std::vector<int>(total_rows),
                  std::vector<int>(dofs.size()),
                  std::vector<int>(dofs.size())};
  int r0 = 0, c0 = 0;
  for (std::size_t d = 0; d < dofs.size(); ++d) {
    const OneStepRows& R = rows[d];
    s.row0[d] = r0;
    s.col0[d] = c0;
    s.F.block(r0, c0, R.F.rows(), R.F.cols()) = R.F;
    s.Y.segment(r0, R.Y.size()) = R.Y;
    // Λ of the DOF (ref 004 eq. 13) times each row's relative weight.
    const double mean_row = R.noise_sigma > 0 ? 1.0 / (R.noise_sigma * R.noise_sigma) : 1.0;
    for (int k = 0; k < R.Y.size(); ++k) s.W[r0 + k] = weight[d] * R.weight[k] / mean_row;
    for (int k = 0; k < R.Y.size(); ++k)
      s.groups[r0 + k] = static_cast<int>(d) * 1000003 + R.run[k];
    r0 += static_cast<int>(R.F.rows());
    c0 += static_cast<int>(R.F.cols());
  }
  return s;
}

// The instruments' simulation grid: every simulation_step_s from 0, every input breakpoint, and
// the velocity samples where they are sparser than the step (not `dense`).
std::vector<double> FineGrid(const TrialData& trial, const OneStepOptions& o, bool dense) {
  const SmoothedSignal& v = trial.velocity_estimate;
  std::vector<double> grid;
  const double t_end = v.t.empty() ? 0.0 : v.t.back();
  grid.reserve(static_cast<std::size_t>(t_end / o.simulation_step_s) + 2 +
               trial.breakpoints().size() + (dense ? 0 : v.size()));
  for (double t = 0.0; t < t_end; t += o.simulation_step_s) grid.push_back(t);
  for (double b : trial.breakpoints()) {
    if (b < t_end) grid.push_back(b);
  }
  if (!dense) {
    for (double t : v.t) grid.push_back(std::max(0.0, t));
  }
  std::sort(grid.begin(), grid.end());
  grid.erase(std::unique(grid.begin(), grid.end()), grid.end());
  return grid;
}

// Sample times `t`, `spacing` apart, as a fine grid about `step` apart: every k-th of a uniform
// clock k times denser than the step (a clock: computed, not stored), else all of them (shared,
// not copied).
SharedTimes SampleGrid(const SharedTimes& t, double spacing, double step) {
  const std::size_t k =
      t.uniform() && spacing > 0 ? static_cast<std::size_t>(std::floor(step / spacing + 1e-9)) : 1;
  if (k <= 1) return t;
  return SharedTimes::Of((t.size() - 1) / k + 1, [&t, k](std::size_t i) { return t[i * k]; },
                         t.view().clock()->offset);
}

// The trial simulated by the current estimate from the data's initial state: on a fine grid
// (every input breakpoint, steps <= simulation_step_s) and at the data's samples (left empty
// when they are the fine grid's: velocities from positions, or dense samples). False when a
// simulation diverges.
bool SimulatedVelocities(const model::DofModel& model, const std::vector<const TrialData*>& trials,
                         const Eigen::VectorXd& theta, const OneStepOptions& o,
                         std::vector<SmoothedSignal>* fine, std::vector<SmoothedSignal>* sampled) {
  for (const TrialData* trial : trials) {
    const SmoothedSignal& v = trial->velocity_estimate;
    const double spacing = v.size() > 1 ? (v.t.back() - v.t.front()) / (v.size() - 1) : 0.0;
    const bool dense = spacing <= o.simulation_step_s;
    // A force logged anew at (about) every sample leaves kinks too small for grid points of
    // their own: the samples, from t = 0, are then the fine grid (SampleGrid: no grid of 1.5
    // points a sample).
    const bool samples_as_grid =
        dense && !v.t.empty() && v.t.front() >= 0 && 2 * trial->breakpoints().size() >= v.size();
    SharedTimes grid = samples_as_grid ? SampleGrid(v.t, spacing, o.simulation_step_s)
                                       : SharedTimes(FineGrid(*trial, o, dense));
    model::SimulationOptions so;
    so.step_s = o.simulation_step_s;
    Eigen::VectorXd x0 = Eigen::VectorXd::Zero(model.num_states());
    x0[1] = trial->initial_velocity;
    SmoothedSignal f, s2;
    // Measured velocities are interpolated as the simulated samples are; velocities derived
    // from positions are smooth local polynomials whose error is the filter's, not the
    // interpolation's; and samples denser than the fine grid leave no defect: no correction
    // for those (and only the velocity is kept: a trajectory is 24–32 bytes a point).
    if (!trial->velocity_from_position && !dense) {
      const model::Trajectory tr =
          model::Simulate(model, theta, trial->conditions(), grid, so, &x0);
      if (!tr.x.allFinite()) return false;
      f.value.assign(tr.x.col(1).data(), tr.x.col(1).data() + tr.x.rows());
      s2.t = v.t;
      std::size_t i = 0;
      for (double t : v.t) {
        while (i + 1 < grid.size() && grid[i] < std::max(0.0, t)) ++i;  // t is on the grid
        const double x[3] = {tr.x(i, 0), tr.x(i, 1), model.num_states() > 2 ? tr.x(i, 2) : 0.0};
        double dx[3];
        model.Derivative(grid[i], x, trial->conditions(), theta.data(), dx);
        s2.value.push_back(tr.x(i, 1));
        s2.derivative.push_back(dx[1]);
      }
    } else {
      f.value.resize(grid.size());
      bool finite = true;
      model::SimulateVisiting(model, theta, trial->conditions(), grid, so, &x0, model::Seen::kState,
                              [&](std::size_t i, const double* x, const double*) {
                                f.value[i] = x[1];
                                finite = finite && std::isfinite(x[0]) && std::isfinite(x[1]) &&
                                         (model.num_states() < 3 || std::isfinite(x[2]));
                              });
      if (!finite) return false;
    }
    f.t = std::move(grid);
    fine->push_back(std::move(f));
    sampled->push_back(std::move(s2));
  }
  return true;
}

// Each row's sensitivity to a velocity error held over the row, A_k = (∂F_k/∂ξ)·ψ (central
// difference, exact for the quadratic terms), rows scaled by `sw`: the integral of the
// filtered ξ̃'s error enters row k through A_k (VSOR: A_k = −∫(k + 2kq|ξ|)/m ds grows with the
// speed), the endpoint errors do not. Zero when the perturbed rows do not match.
Eigen::VectorXd RowSensitivity(const OneStepDofInput& in, const OneStepRows& R,
                               const OneStepOptions& o, const Eigen::VectorXd& psi,
                               const Eigen::VectorXd& sw) {
  const int nr = static_cast<int>(R.Y.size());
  double vmax = 0.0;
  for (const TrialData* trial : in.trials) {
    for (double x : trial->velocity_estimate.value) vmax = std::max(vmax, std::abs(x));
  }
  const double dv = 1e-3 * std::max(vmax, 1e-6);
  // The regressors along the velocities shifted by ±dv (not copied: a copy of every trial's
  // estimate was 24 MB for a million samples).
  auto rows_shifted = [&](double shift) {
    return OneStepRegressors(*in.model, in.trials, in.theta, R.free, o, nullptr, shift);
  };
  const Eigen::MatrixXd Fp = rows_shifted(dv);
  const Eigen::MatrixXd Fm = rows_shifted(-dv);
  if (Fp.rows() != nr || Fm.rows() != nr) return Eigen::VectorXd::Zero(nr);
  return sw.cwiseProduct((Fp - Fm) * psi) / (2.0 * dv);
}

}  // namespace

bool MovedLessThan(const Eigen::VectorXd& before, const Eigen::VectorXd& after,
                   const Eigen::MatrixXd& covariance, double fraction) {
  const Eigen::ArrayXd sigma = covariance.diagonal().cwiseMax(0.0).cwiseSqrt().array();
  return ((after - before).cwiseAbs().array() <= fraction * sigma).all();
}

bool OneStepInstruments(const OneStepDofInput& in, const OneStepRows& R, const OneStepOptions& o,
                        const Eigen::VectorXd& theta_now, Eigen::MatrixXd* Z,
                        Eigen::MatrixXd* F_corrected) {
  std::vector<SmoothedSignal> fine, sampled;
  if (!SimulatedVelocities(*in.model, in.trials, theta_now, o, &fine, &sampled)) return false;
  Eigen::MatrixXd Zr = OneStepRegressors(*in.model, in.trials, in.theta, R.free, o, &fine);
  // The interpolation defect Z − Zs is zero where the samples are the fine grid (empty).
  const bool defect = std::any_of(sampled.begin(), sampled.end(),
                                  [](const SmoothedSignal& s) { return !s.t.empty(); });
  for (std::size_t i = 0; defect && i < sampled.size(); ++i) {
    if (sampled[i].t.empty()) sampled[i] = std::move(fine[i]);
  }
  fine = {};  // 12 bytes a fine-grid point, gone before Zs is built
  // Without a defect Zs is Z itself (not a copy: its rows are 40 bytes a row).
  const Eigen::MatrixXd Zs_built =
      defect ? OneStepRegressors(*in.model, in.trials, in.theta, R.free, o, &sampled)
             : Eigen::MatrixXd();
  const Eigen::MatrixXd& Zs = defect ? Zs_built : Zr;
  if (Zr.rows() != R.F.rows() || Zs.rows() != R.F.rows()) return false;
  *F_corrected = R.F + (Zr - Zs);
  *Z = std::move(Zr);
  return true;
}

namespace {

// One instrumental-variables iteration against the errors in variables of ξ̃ in F: the
// instruments Z are the rows along the velocity simulated by the current estimate, F is
// corrected for the interpolation defect seen on the simulated path (OneStepInstruments).
// Returns whether to iterate again (false: converged, or the step failed and the previous
// answer stands).
bool InstrumentalStep(const OneStepDofInput& in, const OneStepRows& R, const OneStepOptions& o,
                      OneStepDofResult* res) {
  Eigen::VectorXd theta_now;
  Eigen::MatrixXd unused;
  PsiToPhysical(*in.model, in.theta, R.free, res->psi, res->psi_covariance, &theta_now, &unused);
  Eigen::MatrixXd Z, F;
  if (!OneStepInstruments(in, R, o, theta_now, &Z, &F)) return false;
  // Rows scaled by 1/σ of their noise (Ω keeps its form: the weight is constant in a run).
  const Eigen::VectorXd sw =
      Eigen::Map<const Eigen::VectorXd>(R.weight.data(), R.weight.size()).cwiseSqrt();
  const Eigen::MatrixXd Fc = sw.asDiagonal() * F;
  const Eigen::MatrixXd Zw = sw.asDiagonal() * Z;
  const Eigen::VectorXd Yw = sw.cwiseProduct(R.Y);
  const Eigen::MatrixXd A = Zw.transpose() * Fc;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  if (!lu.isInvertible()) return false;
  const Eigen::VectorXd psi = lu.solve(Zw.transpose() * Yw);
  if (!psi.allFinite() || !(psi[0] > 0)) return false;
  // Cov = A⁻¹ZᵀΩZA⁻ᵀ with Ω a heteroscedastic MA(1) of the (weighted) residuals within runs:
  // the rows share their endpoints (ref 002 eqs. 20–26: Y_k = ξ̃(t_k) − ξ̃(t_{k−1})), and the
  // integrals add errors that grow with the row's sensitivity to the velocity. White's
  // per-row r_k² (HC) was tried: with ~50 rows and 4 unknowns (URIS yaw, pitch) its σ
  // scattered by a factor 2 and covered 68–81%; the fitted variance model pools them.
  const Eigen::VectorXd r = Yw - Fc * psi;
  const Eigen::VectorXd Ak = RowSensitivity(in, R, o, psi, sw);
  Eigen::MatrixXd features(Ak.size(), 2);  // of the variance model: [A_k, A_k²]
  features.col(0) = Ak;
  features.col(1) = Ak.cwiseAbs2();
  const Eigen::MatrixXd cov = Ma1VarianceModelCovariance(Fc, Zw, r, R.run, features);
  // Converged when no coefficient moved by more than 5% of its σ.
  const bool converged = MovedLessThan(res->psi, psi, cov, 0.05);
  res->psi = psi;
  res->psi_covariance = cov;
  res->residuals = R.Y - F * psi;
  res->cost = res->residuals.squaredNorm() / static_cast<int>(R.Y.size());
  res->instrumental = true;
  return !converged;
}

// Seed coefficients (ref 002: α, β, γ, δ) when the model is the standard one.
void StoreSeedCoefficients(const OneStepRows& R, OneStepDofResult* res) {
  auto find_free = [&](const char* name) {
    for (std::size_t c = 0; c < R.free.size(); ++c) {
      if (res->names[R.free[c]] == name) return static_cast<int>(c) + 1;
    }
    return -1;
  };
  const int ik = find_free(model::param::kLinearDrag), iq = find_free(model::param::kQuadraticDrag),
            ib = find_free(model::param::kBias);
  if (ik <= 0 || iq <= 0 || ib <= 0) return;
  res->standard = true;
  res->seed.alpha = -res->psi[ik];
  res->seed.beta = -res->psi[iq];
  res->seed.gamma = res->psi[0];
  res->seed.delta = res->psi[ib];
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(4, R.F.cols());  // [α β γ δ] = S·ψ
  S(0, ik) = -1;
  S(1, iq) = -1;
  S(2, 0) = 1;
  S(3, ib) = 1;
  res->seed_covariance = S * res->psi_covariance * S.transpose();
}

// The DOF's conditioning, its physical parameters from ψ, estimates and status.
void FinishDof(const OneStepDofInput& in, const OneStepRows& R, const LeastSquaresOptions& lso,
               OneStepDofResult* res) {
  const model::DofModel& model = *in.model;
  res->cost = res->residuals.squaredNorm() / res->num_rows;
  // This DOF's own conditioning and non-identifiable parameters.
  const LinearFit own = SolveLeastSquares(R.F, R.Y, nullptr, lso);
  res->condition_number = own.condition_number;
  for (int c : own.not_identifiable) {
    res->not_identifiable.push_back(c == 0 ? std::string(model::param::kMass)
                                           : res->names[R.free[c - 1]]);
  }
  if (!(res->psi[0] > 0) || own.status != FitStatus::kOk) {
    res->status = FitStatus::kIllConditioned;
    std::string why = own.status != FitStatus::kOk ? own.message : "gamma = 1/m is not positive";
    if (R.F.col(0).cwiseAbs().maxCoeff() == 0) {
      why =
          "no force with a known installation coefficient: the model is homogeneous in its "
          "parameters, η must be known (open water) for at least one mapping (seed 000 §II-A)";
    }
    res->message = "one-step LS: " + why +
                   (res->not_identifiable.empty()
                        ? std::string()
                        : "; not identifiable: " + model::Join(res->not_identifiable));
    return;
  }
  PsiToPhysical(model, in.theta, R.free, res->psi, res->psi_covariance, &res->theta,
                &res->covariance);
  res->state[0] = ParameterState::kEstimated;
  for (int j : R.free) res->state[j] = ParameterState::kEstimated;
  const std::vector<ParameterEstimate> all =
      MakeEstimates(res->names, res->theta, res->covariance, res->state);
  for (std::size_t j = 0; j < all.size(); ++j) {
    if (res->state[j] == ParameterState::kEstimated) res->estimates.push_back(all[j]);
  }
  StoreSeedCoefficients(R, res);
  res->status = FitStatus::kOk;
  std::ostringstream os;
  os.precision(4);
  os << "one-step integral LS on " << res->num_rows << " rows, condition number "
     << res->condition_number;
  res->message = os.str();
}

// One DOF's answer from the stacked fit: its block of ψ, refined by instrumental variables.
void SolveDof(const OneStepDofInput& in, const OneStepRows& R, const LinearFit& fit, int row0,
              int col0, const OneStepOptions& o, const LeastSquaresOptions& lso,
              OneStepDofResult* res) {
  const model::DofModel& model = *in.model;
  const int P = static_cast<int>(R.F.cols());
  res->num_rows = static_cast<int>(R.Y.size());
  res->names = model.parameter_names();
  res->state.assign(model.num_parameters(), ParameterState::kFixed);
  res->theta = in.theta;
  res->covariance = Eigen::MatrixXd::Zero(model.num_parameters(), model.num_parameters());
  res->coefficient_names.push_back("gamma");
  for (int j : R.free) res->coefficient_names.push_back(res->names[j] + "/m");
  if (res->num_rows < P + 1) {
    res->status = FitStatus::kTooFewData;
    res->message = "one-step LS: " + std::to_string(res->num_rows) + " rows for " +
                   std::to_string(P) + " unknowns (the trials are too short for the knot spacing)";
    return;
  }
  res->psi = fit.theta.segment(col0, P);
  res->psi_covariance = fit.covariance.block(col0, col0, P, P);
  res->residuals = fit.residuals.segment(row0, res->num_rows);
  if (o.covariance == CovarianceKind::kDifferenced) {
    // Per DOF (the blocks are independent; the DOF's weight cancels).
    const Eigen::VectorXd sw =
        Eigen::Map<const Eigen::VectorXd>(R.weight.data(), R.weight.size()).cwiseSqrt();
    res->psi_covariance =
        DifferencedCovariance(sw.asDiagonal() * R.F, sw.cwiseProduct(res->residuals), R.run);
  }
  for (int it = 0; it < o.iv_iterations && res->psi[0] > 0 && res->psi.allFinite(); ++it) {
    if (!InstrumentalStep(in, R, o, res)) break;
  }
  FinishDof(in, R, lso, res);
}

}  // namespace

std::vector<OneStepDofResult> OneStepLeastSquares(const std::vector<OneStepDofInput>& dofs,
                                                  const OneStepOptions& o) {
  std::vector<OneStepDofResult> results(dofs.size());
  std::vector<OneStepRows> rows(dofs.size());
  for (std::size_t d = 0; d < dofs.size(); ++d) rows[d] = DofRows(dofs[d], o, &results[d]);
  LeastSquaresOptions lso;
  lso.covariance = o.covariance;
  lso.newey_west_lags = o.newey_west_lags;
  lso.truncated_kernel = true;  // consecutive rows share an endpoint: MA(1), weight 1
  lso.max_condition = o.max_condition;
  LinearFit fit;
  std::vector<int> row0, col0;
  {  // the stacked copy of the rows gone before the IV iterations (their peak)
    const StackedSystem s = Stack(dofs, rows);
    fit = SolveLeastSquares(s.F, s.Y, &s.W, lso, &s.groups);
    row0 = s.row0;
    col0 = s.col0;
  }
  for (std::size_t d = 0; d < dofs.size(); ++d) {
    SolveDof(dofs[d], rows[d], fit, row0[d], col0[d], o, lso, &results[d]);
  }
  return results;
}

}  // namespace uuvplan::ident
