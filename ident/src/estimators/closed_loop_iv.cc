#include "uuvplan/ident/estimators/closed_loop_iv.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "options_check.h"
#include "stats/model_selection.h"
#include "uuvplan/ident/estimate.h"
#include "uuvplan/ident/estimators/regression.h"
#include "uuvplan/ident/stats/covariance.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {

bool ClosedLoopIvOptions::IsValid(std::string* error) const {
  return Require(
      min_lag_knots >= 2 && max_lag_knots >= min_lag_knots && knot_s > 0 && instrument_lags >= 1,
      "ClosedLoopIvOptions: min_lag_knots >= 2, max_lag_knots >= min_lag_knots, "
      "knot_s > 0, instrument_lags >= 1",
      error);
}

namespace {

// The one-step rows with the columns nothing excites left out (reported as not excited).
OneStepRows ExcitedRows(const model::DofModel& model, const std::vector<const TrialData*>& trials,
                        const Eigen::VectorXd& theta, const std::vector<int>& linear,
                        const OneStepOptions& o, OneStepDofResult* res) {
  return ExcitedOneStepRows(model, trials, theta, linear, o, &res->not_excited);
}

// Rows k with rows k − d … k − d − L + 1 in the same run: F, Y, the instruments
// Z = [F_{k−d}, …, F_{k−d−L+1}] (L = `lags`), all scaled by √(row weight), and the run of each.
struct LaggedSystem {
  Eigen::MatrixXd F, Z;
  Eigen::VectorXd Y;
  std::vector<int> run;
};
LaggedSystem Lagged(const OneStepRows& R, int d, int lags) {
  const int last = d + lags - 1;
  std::vector<int> keep;
  for (int k = last; k < static_cast<int>(R.Y.size()); ++k) {
    if (R.run[k] == R.run[k - last]) keep.push_back(k);
  }
  const int n = static_cast<int>(keep.size()), p = static_cast<int>(R.F.cols());
  LaggedSystem s{Eigen::MatrixXd(n, p), Eigen::MatrixXd(n, p * lags), Eigen::VectorXd(n), {}};
  for (int i = 0; i < n; ++i) {
    const int k = keep[i];
    const double sw = std::sqrt(R.weight[k]);
    s.F.row(i) = sw * R.F.row(k);
    for (int l = 0; l < lags; ++l) s.Z.row(i).segment(l * p, p) = sw * R.F.row(k - d - l);
    s.Y[i] = sw * R.Y[k];
    s.run.push_back(R.run[k]);
  }
  return s;
}

// Two-stage least squares: the regressors' projection on the instruments,
// X̂ = Z·(ZᵀZ)⁻¹·ZᵀF, is the instrument of the just-identified IV ψ = (X̂ᵀF)⁻¹X̂ᵀY.
Eigen::MatrixXd Projected(const LaggedSystem& s) {
  const Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> zz(s.Z);
  return s.Z * zz.solve(s.F);
}

// ψ of the two-stage least squares, ψ = (X̂ᵀF)⁻¹X̂ᵀY.
Eigen::VectorXd TwoStageSolution(const LaggedSystem& s) {
  const Eigen::MatrixXd X = Projected(s);
  return (X.transpose() * s.F).fullPivLu().solve(X.transpose() * s.Y);
}

// Feasible weights (two-step GLS): each trial's rows weighted by 1/(mean squared residual of
// its rows at the first-pass ψ) instead of 1/(its sensor's noise). On tartan the rows'
// residual variance is 10–500× the sensor's, by a ratio that varies 300× between chunks
// (model error and disturbances the controller fights, not sensor noise): weighted by the
// sensor, a quiet chunk outweighs the informative ones and the halves of the campaign
// disagree. With sensor noise alone (the virtual twin) both weightings agree.
void WeightTrialsByResiduals(const Eigen::VectorXd& psi, OneStepRows* R) {
  std::map<int, std::pair<double, int>> sum;  // trial → (Σ e², rows)
  for (Eigen::Index k = 0; k < R->Y.size(); ++k) {
    const double e = R->Y[k] - R->F.row(k).dot(psi);
    sum[R->group[k]].first += e * e;
    sum[R->group[k]].second += 1;
  }
  for (Eigen::Index k = 0; k < R->Y.size(); ++k) {
    const auto& [sq, n] = sum[R->group[k]];
    if (sq > 0) R->weight[k] = n / sq;
  }
}

// Condition number of A = X̂ᵀF with its rows and columns scaled to unit norm of X̂ and F: the
// columns' units (N·s against s) and the rows' weights do not enter it.
double EquilibratedCondition(const Eigen::MatrixXd& A, const Eigen::MatrixXd& X,
                             const Eigen::MatrixXd& F) {
  Eigen::MatrixXd B = A;
  for (Eigen::Index j = 0; j < B.rows(); ++j) B.row(j) /= std::max(1e-300, X.col(j).norm());
  for (Eigen::Index j = 0; j < B.cols(); ++j) B.col(j) /= std::max(1e-300, F.col(j).norm());
  const Eigen::JacobiSVD<Eigen::MatrixXd> svd(B);
  const Eigen::VectorXd& sv = svd.singularValues();
  return sv[0] / std::max(1e-300, sv[sv.size() - 1]);
}

// d: the correlation length (in knots) of the least-squares residuals + 1, within the bounds.
int InstrumentLag(const OneStepRows& R, const ClosedLoopIvOptions& o) {
  const Eigen::VectorXd sw =
      Eigen::Map<const Eigen::VectorXd>(R.weight.data(), R.weight.size()).cwiseSqrt();
  LeastSquaresOptions lso;
  lso.max_condition = 1e12;
  const LinearFit ls = SolveLeastSquares(sw.asDiagonal() * R.F, sw.cwiseProduct(R.Y), nullptr, lso);
  if (ls.residuals.size() != R.Y.size()) return o.min_lag_knots;
  return std::clamp(CorrelationLength(ls.residuals, R.run) + 1, o.min_lag_knots, o.max_lag_knots);
}

// Physical parameters, estimates and the message of a solved ψ.
void Finish(const model::DofModel& model, const Eigen::VectorXd& theta, const OneStepRows& R,
            ClosedLoopIvResult* out) {
  OneStepDofResult& f = out->fit;
  PsiToPhysical(model, theta, R.free, f.psi, f.psi_covariance, &f.theta, &f.covariance);
  f.state.assign(model.num_parameters(), ParameterState::kFixed);
  f.state[0] = ParameterState::kEstimated;
  for (int j : R.free) f.state[j] = ParameterState::kEstimated;
  const auto all = MakeEstimates(f.names, f.theta, f.covariance, f.state);
  for (std::size_t j = 0; j < all.size(); ++j) {
    if (f.state[j] == ParameterState::kEstimated) f.estimates.push_back(all[j]);
  }
  f.status = FitStatus::kOk;
  f.instrumental = true;
  std::ostringstream os;
  os << "closed-loop instrumental variables (two-stage least squares) on " << f.num_rows
     << " one-step rows, instruments the rows " << out->lag_knots << "–"
     << out->lag_knots + out->instrument_lags - 1 << " knots (from "
     << model::Significant(out->lag_s, 3) << " s) earlier, rows weighted per trial by "
     << (out->residual_weights ? "its residuals" : "its sensor noise")
     << ", σ from an MA(1) sandwich";
  f.message = os.str();
}

}  // namespace

namespace {

// One two-stage least-squares fit of the parameters `free` (others at theta).
ClosedLoopIvResult SolveIv(const model::DofModel& model,
                           const std::vector<const TrialData*>& trials,
                           const Eigen::VectorXd& theta, const std::vector<int>& free,
                           const OneStepOptions& one_step, const ClosedLoopIvOptions& o) {
  ClosedLoopIvResult out;
  OneStepDofResult& f = out.fit;
  f.names = model.parameter_names();
  f.theta = theta;
  f.covariance = Eigen::MatrixXd::Zero(model.num_parameters(), model.num_parameters());
  OneStepOptions rows = one_step;
  rows.window_s = o.knot_s;
  rows.split_at_force_jumps = false;
  OneStepRows R = ExcitedRows(model, trials, theta, free, rows, &f);
  const int p = static_cast<int>(R.F.cols());
  out.lag_knots = InstrumentLag(R, o);
  out.instrument_lags = o.instrument_lags;
  LaggedSystem s = Lagged(R, out.lag_knots, o.instrument_lags);
  f.num_rows = static_cast<int>(s.Y.size());
  if (o.weight_by_residuals && f.num_rows >= 3 * p) {
    const Eigen::VectorXd first = TwoStageSolution(s);
    if (first.allFinite()) {
      WeightTrialsByResiduals(first, &R);
      s = Lagged(R, out.lag_knots, o.instrument_lags);
      out.residual_weights = true;
    }
  }
  if (f.num_rows < 3 * p) {
    f.status = FitStatus::kTooFewData;
    f.message = "closed-loop instrumental variables: " + std::to_string(f.num_rows) +
                " rows with an instrument " + std::to_string(out.lag_knots) +
                " knots earlier for " + std::to_string(p) + " unknowns (longer trials)";
    return out;
  }
  const Eigen::MatrixXd X = Projected(s);
  const Eigen::MatrixXd A = X.transpose() * s.F;
  Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
  f.condition_number = EquilibratedCondition(A, X, s.F);
  if (!lu.isInvertible() || !(f.condition_number < one_step.max_condition)) {
    f.status = FitStatus::kIllConditioned;
    f.message =
        "closed-loop instrumental variables: the lagged rows do not determine the "
        "parameters (condition number " +
        model::Significant(f.condition_number, 3) + ")";
    return out;
  }
  f.psi = lu.solve(X.transpose() * s.Y);
  f.residuals = s.Y - s.F * f.psi;
  // The rows' residuals are differences of the velocity's noise at shared knots (lag-1 near
  // −½): the one-step's MA(1) sandwich (least_squares.h Ma1VarianceModelCovariance) keeps the
  // cancellation of consecutive rows. An AR(1) prewhitening or batch means over a few knots
  // miss it (virtual twin: RMS z 0.3–0.7 against 0.58–0.85 with the MA(1)).
  f.psi_covariance =
      Ma1VarianceModelCovariance(s.F, X, f.residuals, s.run, Eigen::MatrixXd(s.F.rows(), 0));
  double spacing = 0.0;
  int pairs = 0;
  for (int k = 1; k < static_cast<int>(R.t.size()); ++k) {
    if (R.run[k] != R.run[k - 1]) continue;
    spacing += R.t[k] - R.t[k - 1];
    ++pairs;
  }
  out.lag_s = pairs > 0 ? spacing / pairs * out.lag_knots : 0.0;
  f.cost = f.residuals.squaredNorm() / f.num_rows;
  if (!(f.psi[0] > 0) || !f.psi.allFinite()) {
    f.status = FitStatus::kIllConditioned;
    f.message = "closed-loop instrumental variables: 1/m is not positive (" +
                model::Significant(f.psi[0], 3) + "): the instruments are too weak";
    return out;
  }
  Finish(model, theta, R, &out);
  return out;
}

}  // namespace

// Ref 000 §IV-D model selection on the instrumental-variable fit: drop the worst
// insignificant prunable parameter (at 0) and refit, as the other estimators do.
ClosedLoopIvResult ClosedLoopInstrumentalFit(const model::DofModel& model,
                                             const std::vector<const TrialData*>& trials,
                                             const Eigen::VectorXd& theta,
                                             const OneStepOptions& one_step,
                                             const ClosedLoopIvOptions& o) {
  const int np = model.num_parameters();
  const auto& names = model.parameter_names();
  std::vector<int> free = LinearParameters(model);
  Eigen::VectorXd theta_now = theta;
  std::vector<double> before_value(np, 0.0), before_sigma(np, 0.0);
  std::vector<int> dropped;
  ClosedLoopIvResult out = SolveIv(model, trials, theta_now, free, one_step, o);
  std::vector<std::string> kept_notes;
  while (o.selection.prune_insignificant && out.ok()) {
    std::vector<int> estimated;  // m and the free parameters, in the model's layout
    for (const ParameterEstimate& e : out.fit.estimates) {
      estimated.push_back(model.ParameterIndex(e.name));
    }
    const std::vector<PruneCandidate> candidates =
        CandidatesOf(names, out.fit.theta, out.fit.covariance, estimated);
    double pe = 0.0;
    kept_notes.clear();
    const int worst = WorstInsignificant(candidates, o.selection, &pe, &kept_notes);
    if (worst < 0) break;
    const int j = model.ParameterIndex(candidates[worst].name);
    before_value[j] = candidates[worst].value;
    before_sigma[j] = candidates[worst].sigma;
    theta_now[j] = 0.0;
    free.erase(std::remove(free.begin(), free.end(), j), free.end());
    dropped.push_back(j);
    ClosedLoopIvResult next = SolveIv(model, trials, theta_now, free, one_step, o);
    if (!next.ok()) break;  // keep the last fit that worked
    out = std::move(next);
  }
  out.notes = kept_notes;
  if (!out.ok() || dropped.empty()) return out;
  for (int j : dropped) {
    if (out.fit.state[j] == ParameterState::kFixed && out.fit.theta[j] == 0.0) {
      out.fit.state[j] = ParameterState::kDropped;
    }
  }
  std::vector<ParameterEstimate> kept;
  for (const ParameterEstimate& e : EstimatedAndDropped(
           names, out.fit.theta, out.fit.covariance, out.fit.state, before_value, before_sigma)) {
    kept.push_back(e);
  }
  out.fit.estimates = std::move(kept);
  return out;
}

}  // namespace uuvplan::ident
