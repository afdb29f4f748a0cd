// The output error's least-squares problem (output_error_problem.h): z ↔ θ and the initial
// states, the residuals and the Jacobian's rows, trial by trial, from the simulations with their
// sensitivities (streamed where a trial allows it).
#include "estimators/output_error_problem.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "uuvplan/model/parameter.h"

namespace uuvplan::ident::internal {
namespace {

// dx/dt (position, velocity) at both ends of the grid interval [ta, tb], states xa and xb,
// with the input held at its start (one-sided derivatives at breakpoints): the slopes of the
// cubic Hermite interpolation of the output error's grid.
void HermiteSlopes(const model::DofModel& model, double ta, double tb, const double* xa,
                   const double* xb, const Eigen::VectorXd& theta, const model::TrialConditions& c,
                   double* dl, double* dr) {
  const model::InputSample in = model.SampleInput(ta, c, theta.data());
  double dx[3];
  model.Derivative(ta, xa, in, c, theta.data(), dx);
  dl[0] = dx[0];
  dl[1] = dx[1];
  model.Derivative(tb, xb, in, c, theta.data(), dx);
  dr[0] = dx[0];
  dr[1] = dx[1];
}

// A simulation seen at tp.times: run there (as is), or on tp.grid and interpolated
// (OutputErrorOptions::grid_s): position and velocity by cubic Hermite with dx/dt from the
// model and the interval's input held at both ends (one-sided derivatives at breakpoints),
// other states and the sensitivities linearly. Nothing is materialised at the sample times.
class TrajectoryView {
 public:
  TrajectoryView(const TrialProblem& tp, const model::Trajectory& g, const model::DofModel& model,
                 const Eigen::VectorXd& theta, const model::TrialConditions& c)
      : tp_(tp), g_(g) {
    if (tp.grid.empty() || g.x.rows() == 0) return;
    const int nx = static_cast<int>(g.x.cols());
    const std::size_t ng = tp.grid.size();
    dl_.resize(ng, 2);
    dr_.resize(ng, 2);
    double xa[3] = {0, 0, 0}, xb[3] = {0, 0, 0}, dl[2], dr[2];
    for (std::size_t k = 0; k + 1 < ng; ++k) {
      for (int s = 0; s < nx; ++s) {
        xa[s] = g.x(k, s);
        xb[s] = g.x(k + 1, s);
      }
      HermiteSlopes(model, tp.grid[k], tp.grid[k + 1], xa, xb, theta, c, dl, dr);
      dl_.row(k) << dl[0], dl[1];
      dr_.row(k) << dr[0], dr[1];
    }
  }
  // State s at time index i, in grid interval k (ignored without a grid).
  double x(int i, int k, int s) const {
    if (tp_.grid.empty()) return g_.x(i, s);
    const TrialProblem::Hermite w = tp_.Weights(tp_.times()[i], k);
    if (s >= 2) return (1 - w.u) * g_.x(k, s) + w.u * g_.x(k + 1, s);
    return w.h00 * g_.x(k, s) + w.h10 * dl_(k, s) + w.h01 * g_.x(k + 1, s) + w.h11 * dr_(k, s);
  }
  double S(int i, int k, int s, int j) const {
    if (tp_.grid.empty()) return g_.S[s](i, j);
    const double u = tp_.U(tp_.times()[i], k);
    return (1 - u) * g_.S[s](k, j) + u * g_.S[s](k + 1, j);
  }

 private:
  const TrialProblem& tp_;
  const model::Trajectory& g_;
  Eigen::MatrixXd dl_,
      dr_;  // dx/dt (position, velocity) at the left and right end of each interval
};

// The columns of a simulation's sensitivities: the model's parameters, then ξ0's when asked.
int SensitivityColumns(const model::DofModel& model, const model::SimulationOptions& so) {
  return model.num_parameters() + (so.sensitivities && so.initial_velocity_column ? 1 : 0);
}

// One grid point of a streamed simulation: state, dx/dt (position, velocity) under the
// interval's held input, and S row-major (state s, parameter j at s·P + j).
struct GridPoint {
  double x[3] = {0, 0, 0};
  double dx[2] = {0, 0};
  std::vector<double> S;
};

// The rows of a one-sensor trial at its own times, made while the simulation runs: nothing
// of the simulation is stored (40 bytes a sample of a trial binned to 200k).
template <class Fill>
bool StreamAtOwnTimes(const model::DofModel& model, const TrialProblem& tp,
                      const Eigen::VectorXd& theta, const model::TrialConditions& c,
                      const model::SimulationOptions& so, const Eigen::VectorXd& x0,
                      const Fill& fill) {
  const int s = tp.sensor();
  const TrialProblem::Measurements& m = s == 0 ? tp.pos : tp.vel;
  const int np = SensitivityColumns(model, so);
  std::size_t k = 0;
  bool finite = true;
  const model::OutputVisitor visit = [&](std::size_t i, const double* x, const double* S) {
    if (!finite) return;  // diverged: Evaluate fails, its rows are not wanted
    finite = std::all_of(x, x + model.num_states(), [](double v) { return std::isfinite(v); });
    for (; finite && k < m.size() && static_cast<std::size_t>(m.at(k)) == i; ++k) {
      fill(m, s, k, x[s], [&](int j) { return S[s * np + j]; });
    }
  };
  model::SimulateVisiting(model, theta, c, tp.times(), so, &x0, model::Seen::kBySensors, visit);
  return finite;
}

// The rows of a one-sensor trial on a grid, made while the simulation runs: each grid point
// is kept until the next arrives, and the samples between the two are interpolated as
// TrajectoryView does (the same numbers); the simulation with its sensitivities is never stored
// (16–24 bytes a sample). The samples' times must increase (a log's do).
template <class Fill>
bool Stream(const model::DofModel& model, const TrialProblem& tp, const Eigen::VectorXd& theta,
            const model::TrialConditions& c, const model::SimulationOptions& so,
            const Eigen::VectorXd& x0, const Fill& fill) {
  if (tp.grid.empty()) return StreamAtOwnTimes(model, tp, theta, c, so, x0, fill);
  const int s = tp.sensor();
  const TrialProblem::Measurements& m = s == 0 ? tp.pos : tp.vel;
  const model::TimesView times = tp.times();
  const int np = SensitivityColumns(model, so);
  const std::size_t last = tp.grid.size() - 1;
  GridPoint left, right;
  std::size_t k = 0;
  bool finite = true;
  const model::OutputVisitor visit = [&](std::size_t g, const double* x, const double* S) {
    if (!finite) return;  // diverged: Evaluate fails, its rows are not wanted
    GridPoint& p = g == 0 ? left : right;
    std::copy(x, x + model.num_states(), p.x);
    if (S) p.S.assign(S, S + model.num_states() * np);
    finite = std::all_of(x, x + model.num_states(), [](double v) { return std::isfinite(v); });
    if (g == 0 || !finite) return;
    const int a = static_cast<int>(g - 1);  // the interval [grid[a], grid[g]]
    HermiteSlopes(model, tp.grid[a], tp.grid[g], left.x, right.x, theta, c, left.dx, right.dx);
    for (; k < m.size(); ++k) {
      const int i = m.at(k);
      const double t = times[i];
      if (t > tp.grid[g] && g < last) break;
      const TrialProblem::Hermite w = tp.Weights(t, a);
      const double xs =
          w.h00 * left.x[s] + w.h10 * left.dx[s] + w.h01 * right.x[s] + w.h11 * right.dx[s];
      fill(m, s, k, xs,
           [&](int j) { return (1 - w.u) * left.S[s * np + j] + w.u * right.S[s * np + j]; });
    }
    std::swap(left, right);
  };
  model::SimulateVisiting(model, theta, c, tp.grid, so, &x0, model::Seen::kBySensors, visit);
  return finite;
}

}  // namespace

bool Admissible(const model::DofModel& model, const Eigen::VectorXd& theta) {
  const auto& names = model.parameter_names();
  for (int j = 0; j < model.num_parameters(); ++j) {
    const model::ParameterFamily* family = model::FamilyOf(names[j]);
    if (family ? !family->Fittable(theta[j]) : !std::isfinite(theta[j])) return false;
  }
  return true;
}

Problem::Problem(const model::DofModel& model, const std::vector<const TrialData*>& trials,
                 const Eigen::VectorXd& theta, const std::vector<int>& free,
                 const std::vector<TrialInitialState>* initial, const OutputErrorOptions& o,
                 double average_input_s)
    : model_(model), theta_(theta), free_(free), o_(o) {
  int z = static_cast<int>(free.size());
  int r = 0;
  for (const TrialData* d : trials) {
    std::optional<TrialProblem> tp = MakeTrialProblem(model, *d, initial, o, average_input_s);
    if (!tp) continue;
    if (tp->init.chi0_estimated) tp->z_chi0 = z++;
    if (tp->init.xi0_estimated) tp->z_xi0 = z++;
    tp->r_offset = r;
    r += tp->num_residuals();
    trials_.push_back(std::move(*tp));
  }
  num_z_ = z;
  num_r_ = r;
}

Eigen::VectorXd Problem::InitialZ() const {
  Eigen::VectorXd z(num_z_);
  for (std::size_t c = 0; c < free_.size(); ++c) z[c] = theta_[free_[c]];
  for (const TrialProblem& tp : trials_) {
    if (tp.z_chi0 >= 0) z[tp.z_chi0] = tp.init.chi0;
    if (tp.z_xi0 >= 0) z[tp.z_xi0] = tp.init.xi0;
  }
  return z;
}

Eigen::VectorXd Problem::Theta(const Eigen::VectorXd& z) const {
  Eigen::VectorXd theta = theta_;
  for (std::size_t c = 0; c < free_.size(); ++c) theta[free_[c]] = z[c];
  return theta;
}

std::vector<TrialInitialState> Problem::Initial(const Eigen::VectorXd& z) const {
  std::vector<TrialInitialState> out;
  for (const TrialProblem& tp : trials_) {
    TrialInitialState s = tp.init;
    if (tp.z_chi0 >= 0) s.chi0 = z[tp.z_chi0];
    if (tp.z_xi0 >= 0) s.xi0 = z[tp.z_xi0];
    out.push_back(s);
  }
  return out;
}

// Where Evaluate's rows go: the residual vector (if any), the cost, the Jacobian's sink.
struct Problem::RowWriter {
  Eigen::VectorXd* r;
  BlockRowSink* rows;
  double sum_squares;
  bool finite;
  // Records residual `res` of `row`; the sink's row to fill (the Jacobian's entries, then the
  // residual), or null without a Jacobian.
  double* Add(int row, double res) {
    if (r) (*r)[row] = res;
    sum_squares += res * res;
    finite = finite && std::isfinite(res);
    if (!rows) return nullptr;
    return rows->Row();
  }
  void Commit(double* J, int cols, bool excluded) {
    for (int c = 0; c < cols; ++c) {
      if (excluded) J[c] = 0.0;
      finite = finite && std::isfinite(J[c]);
    }
    rows->Commit();
  }
};

bool Problem::Evaluate(const Eigen::VectorXd& z, Eigen::VectorXd* r, BlockRowSink* rows,
                       double* cost) const {
  const Eigen::VectorXd theta = Theta(z);
  if (!Admissible(model_, theta)) return false;
  if (r) r->resize(num_r_);
  model::SimulationOptions so;
  so.step_s = o_.step_s;
  so.sensitivities = rows != nullptr;
  RowWriter out{r, rows, 0.0, true};
  for (const TrialProblem& tp : trials_) {
    if (!EvaluateTrial(tp, z, theta, so, rows, &out)) return false;
  }
  if (rows) rows->Finish();
  if (cost) *cost = 0.5 * out.sum_squares;
  return out.finite;
}

bool Problem::EvaluateTrial(const TrialProblem& tp, const Eigen::VectorXd& z,
                            const Eigen::VectorXd& theta, const model::SimulationOptions& so,
                            BlockRowSink* rows, RowWriter* out) const {
  Eigen::VectorXd x0 = Eigen::VectorXd::Zero(model_.num_states());
  x0[0] = tp.z_chi0 >= 0 ? z[tp.z_chi0] : tp.init.chi0;
  x0[1] = tp.z_xi0 >= 0 ? z[tp.z_xi0] : tp.init.xi0;
  const model::TrialConditions c = tp.conditions();
  const model::TimesView at = tp.grid.empty() ? tp.times() : tp.grid;
  // ∂ŷ/∂ξ0 as the simulation's last sensitivity column: dS_ξ0/dt = A·S_ξ0, S_ξ0(0) = (0, 1).
  model::SimulationOptions so_trial = so;
  so_trial.initial_velocity_column = rows && tp.z_xi0 >= 0;
  const int xi0_column = model_.num_parameters();
  const bool streamed = tp.streamable(model_);
  const int own = (tp.z_chi0 >= 0 ? 1 : 0) + (tp.z_xi0 >= 0 ? 1 : 0);
  if (rows) rows->StartBlock(tp.z_chi0 >= 0 ? tp.z_chi0 : std::max(tp.z_xi0, 0), own);
  // Row of measurement k of sensor s: ŷ = x, its sensitivities S(j) = ∂x_s/∂θ_j (j = xi0_column:
  // ∂x_s/∂ξ0).
  auto fill = [&](const TrialProblem::Measurements& m, int s, std::size_t k, double x,
                  const auto& S) {
    const int row = tp.r_offset + static_cast<int>(s == 0 ? k : tp.pos.size() + k);
    const double w = m.weight(k);
    const bool excluded = row < static_cast<int>(excluded_.size()) && excluded_[row];
    const double res = excluded ? 0.0 : w * (m.y(k) - x);  // left out: residual and row 0
    double* J = out->Add(row, res);
    if (!J) return;
    int col = 0;
    if (tp.z_chi0 >= 0) J[col++] = s == 0 ? -w : 0.0;
    if (tp.z_xi0 >= 0) J[col++] = -w * S(xi0_column);
    for (int j : free_) J[col++] = -w * S(j);
    J[col] = res;
    out->Commit(J, col, excluded);
  };
  if (streamed) {
    if (!Stream(model_, tp, theta, c, so_trial, x0, fill)) return false;
  } else {
    const model::Trajectory sim = model::SimulateMeasured(model_, theta, c, at, so_trial, &x0);
    if (!sim.x.allFinite()) return false;
    const TrajectoryView tr(tp, sim, model_, theta, c);
    auto sensor = [&](const TrialProblem::Measurements& m, int s) {
      IntervalCursor interval(tp.grid);
      for (std::size_t k = 0; k < m.size(); ++k) {
        const int i = m.at(k);
        const int g = tp.grid.empty() ? 0 : interval(tp.times()[i]);
        fill(m, s, k, tr.x(i, g, s), [&](int j) { return tr.S(i, g, s, j); });
      }
    };
    sensor(tp.pos, 0);
    sensor(tp.vel, 1);
  }
  if (rows) rows->EndBlock();
  return true;
}

}  // namespace uuvplan::ident::internal
