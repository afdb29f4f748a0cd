// Recursive least squares with forgetting (ref 004 eq. 15) and its covariance (rls.h).
#include "uuvplan/ident/estimators/rls.h"

#include <algorithm>
#include <cmath>

#include "options_check.h"
#include "uuvplan/ident/estimators/regression.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {
namespace {

// P_0 = p0·diag(θ0²) (1 where θ0 = 0) with a given θ0; otherwise p0/‖F_j‖²·rows per column,
// so that the prior is equally vague whatever the columns' units.
Eigen::MatrixXd InitialP(const Eigen::MatrixXd& F, const RlsOptions& o,
                         const Eigen::VectorXd& theta) {
  const int p = static_cast<int>(F.cols());
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(p, p);
  for (int j = 0; j < p; ++j) {
    if (o.theta0.size() == p) {
      const double scale = theta[j] != 0 ? std::abs(theta[j]) : 1.0;
      P(j, j) = o.p0 * scale * scale;
    } else {
      const double n2 = F.col(j).squaredNorm() / std::max(1, static_cast<int>(F.rows()));
      P(j, j) = n2 > 0 ? o.p0 / n2 : o.p0;
    }
  }
  return P;
}

// The forgetting-weighted sums of the covariance (rls.h): A_k, B_k and the residual
// autocovariances γ0 = Σ λ^{k−i} e_i² / (Σ λ^{k−i} − p), γ1 = Σ λ^{k−i} e_i e_{i−1} / Σ λ^{k−i}
// over consecutive rows of a run (a-posteriori residuals).
struct CovarianceSums {
  Eigen::MatrixXd A, B;
  Eigen::MatrixXd previous_row;  // F_{k−1}, empty at a run's start
  double previous_e = 0.0;
  double se = 0.0, sw = 0.0, s1 = 0.0, w1 = 0.0;

  void Add(const Eigen::MatrixXd& Fk, const Eigen::VectorXd& e, bool continues, double lambda) {
    A = lambda * lambda * A + Fk.transpose() * Fk;
    B *= lambda * lambda;
    se = lambda * se + e.squaredNorm();
    sw = lambda * sw + static_cast<double>(e.size());
    s1 *= lambda;
    w1 *= lambda;
    if (continues && previous_row.size() > 0) {
      B += lambda * (Fk.transpose() * previous_row + previous_row.transpose() * Fk);
      s1 += e[0] * previous_e;
      w1 += 1.0;
    }
    previous_row = continues ? Fk : Eigen::MatrixXd();
    previous_e = e[0];
  }
  double Gamma0(int p) const { return sw > p ? se / std::max(1.0, sw - p) : 1.0; }
  double Gamma1(int p) const {
    const double g1 = w1 > 0 ? s1 / w1 : 0.0;
    return std::clamp(g1, -0.5 * Gamma0(p), 0.5 * Gamma0(p));
  }
  Eigen::MatrixXd Covariance(const Eigen::MatrixXd& P, int p) const {
    return P * (Gamma0(p) * A + Gamma1(p) * B) * P.transpose();
  }
};

}  // namespace

bool RlsOptions::IsValid(std::string* error) const {
  return Require(lambda > 0.9 && lambda <= 1.0,
                 "RlsOptions::lambda = " + std::to_string(lambda) +
                     ". Violated constraint: 0.9 < lambda <= 1 (seed 004)",
                 error) &&
         Require(p0 > 0, "RlsOptions::p0 must be > 0", error) &&
         Require(instrument_iterations >= 0, "RlsOptions::instrument_iterations must be >= 0",
                 error);
}

RlsTrajectory RecursiveLeastSquares(const Eigen::MatrixXd& F, const Eigen::VectorXd& Y,
                                    const std::vector<double>& t, const RlsOptions& o,
                                    int rows_per_update, const std::vector<int>* runs,
                                    const Eigen::MatrixXd* instruments) {
  const int p = static_cast<int>(F.cols());
  const int q = std::max(1, rows_per_update);
  const int steps = static_cast<int>(F.rows()) / q;
  RlsTrajectory out;
  Eigen::VectorXd theta = o.theta0.size() == p ? o.theta0 : Eigen::VectorXd::Zero(p);
  Eigen::MatrixXd P = InitialP(F, o, theta);
  out.theta.resize(steps, p);
  out.sigma.resize(steps, p);
  out.t.resize(steps);
  CovarianceSums sums{Eigen::MatrixXd::Zero(p, p), Eigen::MatrixXd::Zero(p, p), {}};
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(p, p);
  Eigen::MatrixXd instrument_rows;
  for (int k = 0; k < steps; ++k) {
    const Eigen::MatrixXd Fk = F.middleRows(k * q, q);
    if (instruments) instrument_rows = instruments->middleRows(k * q, q);
    const Eigen::MatrixXd& Zk = instruments ? instrument_rows : Fk;
    const Eigen::VectorXd Yk = Y.segment(k * q, q);
    const Eigen::MatrixXd S = o.lambda * Eigen::MatrixXd::Identity(q, q) + Fk * P * Zk.transpose();
    const Eigen::MatrixXd Gamma = P * Zk.transpose() * S.inverse();
    theta += Gamma * (Yk - Fk * theta);  // a-priori error
    P = (I - Gamma * Fk) * P / o.lambda;
    if (!instruments) P = 0.5 * (P + P.transpose());  // (ZᵀF)⁻¹ is not symmetric
    const bool continues = q == 1 && runs && k > 0 && (*runs)[k] == (*runs)[k - 1];
    sums.Add(Zk, Yk - Fk * theta, continues, o.lambda);
    // Fewer than 2p weighted rows say little of the residual variance: no σ yet.
    const Eigen::MatrixXd cov =
        sums.sw > 2.0 * p ? sums.Covariance(P, p) : Eigen::MatrixXd::Constant(p, p, std::nan(""));
    out.theta.row(k) = theta.transpose();
    out.sigma.row(k) = cov.diagonal().cwiseMax(0.0).cwiseSqrt().transpose();
    out.t[k] = k * q < static_cast<int>(t.size()) ? t[k * q] : 0.0;
    if (o.keep_covariance) out.covariance.push_back(cov);
    if (k + 1 == steps) out.final_covariance = cov;
  }
  out.P = P;
  out.gamma0 = sums.Gamma0(p);
  out.gamma1 = sums.Gamma1(p);
  return out;
}

namespace {

// The rows' times on the campaign clock (trial start + knot time), so that several trials
// form one history.
std::vector<double> CampaignTimes(const OneStepRows& rows,
                                  const std::vector<const TrialData*>& trials) {
  std::vector<double> t(rows.t.size());
  for (std::size_t k = 0; k < rows.t.size(); ++k) {
    double start = 0.0;
    for (const TrialData* trial : trials) {
      if (trial->index == rows.group[k]) start = trial->start_time;
    }
    t[k] = start + rows.t[k];
  }
  return t;
}

// The rows' scales: √ of their relative noise weight (Λ_k, ref 004 eq. 16; mean weight 1).
Eigen::VectorXd RowScales(const OneStepRows& rows) {
  Eigen::VectorXd s = Eigen::VectorXd::Ones(rows.Y.size());
  if (rows.weight.empty()) return s;
  double mean = 0.0;
  for (double w : rows.weight) mean += w;
  mean /= static_cast<double>(rows.weight.size());
  if (!(mean > 0)) return s;
  for (int k = 0; k < rows.Y.size(); ++k) s[k] = std::sqrt(rows.weight[k] / mean);
  return s;
}

// The final ψ of a recursion in physical parameters (model layout).
Eigen::VectorXd FinalPhysical(const model::DofModel& model, const Eigen::VectorXd& theta,
                              const std::vector<int>& free, const RlsTrajectory& psi) {
  Eigen::VectorXd phys;
  Eigen::MatrixXd cov;
  const Eigen::MatrixXd none = Eigen::MatrixXd::Zero(psi.theta.cols(), psi.theta.cols());
  PsiToPhysical(model, theta, free, psi.theta.bottomRows(1).transpose(), none, &phys, &cov);
  return phys;
}

// Recursive IV (rls.h) against the errors in variables of the filtered velocity in F: the
// instruments are the rows along the velocity the current estimate simulates, F is corrected
// for the interpolation defect (OneStepInstruments), iterated until no coefficient moves by
// more than 5% of its σ (at most `iterations`). False when the instruments cannot be built;
// `psi` is then left as it was.
bool InstrumentalRecursion(const model::DofModel& model,
                           const std::vector<const TrialData*>& trials,
                           const Eigen::VectorXd& theta, const OneStepRows& rows,
                           const Eigen::VectorXd& scales, const std::vector<double>& times,
                           const OneStepOptions& ro, const RlsOptions& o, int iterations,
                           RlsTrajectory* psi) {
  OneStepDofInput in;
  in.model = &model;
  in.trials = trials;
  in.theta = theta;
  in.free = rows.free;
  const Eigen::VectorXd Yw = scales.cwiseProduct(rows.Y);
  bool done = false;
  for (int it = 0; it < iterations; ++it) {
    Eigen::MatrixXd Z, Fc;
    if (!OneStepInstruments(in, rows, ro, FinalPhysical(model, theta, rows.free, *psi), &Z, &Fc)) {
      return done;
    }
    const Eigen::MatrixXd Zw = scales.asDiagonal() * Z;
    RlsTrajectory next =
        RecursiveLeastSquares(scales.asDiagonal() * Fc, Yw, times, o, 1, &rows.run, &Zw);
    const Eigen::VectorXd now = next.theta.bottomRows(1).transpose();
    if (!now.allFinite() || !(now[0] > 0)) return done;
    const Eigen::VectorXd before = psi->theta.bottomRows(1).transpose();
    const bool settled = MovedLessThan(before, now, next.final_covariance, 0.05);
    *psi = std::move(next);
    done = true;
    if (settled) break;
  }
  return done;
}

}  // namespace

RlsDofResult RecursiveOneStep(const model::DofModel& model,
                              const std::vector<const TrialData*>& trials,
                              const Eigen::VectorXd& theta, const std::vector<int>& free,
                              const OneStepOptions& ro, const RlsOptions& o) {
  RlsDofResult r;
  r.lambda = o.lambda;
  r.names = model.parameter_names();
  OneStepRows rows = ExcitedOneStepRows(model, trials, theta, free, ro, &r.not_excited);
  r.free = rows.free;
  r.coefficient_names.push_back("gamma");
  for (int j : r.free) r.coefficient_names.push_back(r.names[j] + "/m");
  const int p = static_cast<int>(r.free.size()) + 1;
  if (rows.Y.size() <= 2 * p) {
    r.status = rows.Y.size() == 0 ? FitStatus::kNoData : FitStatus::kTooFewData;
    r.message = "RLS: " + std::to_string(rows.Y.size()) + " one-step rows for " +
                std::to_string(p) +
                " unknowns (more than twice as many needed for the residual "
                "variance; longer trials)";
    return r;
  }
  const Eigen::VectorXd scales = RowScales(rows);
  const std::vector<double> times = CampaignTimes(rows, trials);
  RlsOptions with_covariance = o;
  with_covariance.keep_covariance = true;
  r.psi = RecursiveLeastSquares(scales.asDiagonal() * rows.F, scales.cwiseProduct(rows.Y), times,
                                with_covariance, 1, &rows.run);
  r.instrumental = o.instrument_iterations > 0 &&
                   InstrumentalRecursion(model, trials, theta, rows, scales, times, ro,
                                         with_covariance, o.instrument_iterations, &r.psi);
  const int steps = static_cast<int>(r.psi.theta.rows());
  r.theta.resize(steps, model.num_parameters());
  r.sigma.resize(steps, model.num_parameters());
  for (int k = 0; k < steps; ++k) {
    Eigen::VectorXd phys;
    Eigen::MatrixXd cov;
    PsiToPhysical(model, theta, r.free, r.psi.theta.row(k).transpose(), r.psi.covariance[k], &phys,
                  &cov);
    r.theta.row(k) = phys.transpose();
    r.sigma.row(k) = cov.diagonal().cwiseMax(0.0).cwiseSqrt().transpose();
    if (k + 1 == steps) {
      r.final_theta = phys;
      r.covariance = cov;
    }
  }
  r.psi.covariance.clear();
  r.state.assign(model.num_parameters(), ParameterState::kFixed);
  r.state[0] = ParameterState::kEstimated;
  for (int j : r.free) r.state[j] = ParameterState::kEstimated;
  r.status = FitStatus::kOk;
  r.message = "RLS (seed 004 eq. 15, λ = " + model::Significant(o.lambda, 6) + ") on " +
              std::to_string(steps) + " one-step rows" +
              (r.instrumental ? ", instruments from the simulated velocity (recursive IV)"
                              : ", plain least squares (no instruments)");
  return r;
}

}  // namespace uuvplan::ident
