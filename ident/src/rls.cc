#include "uuvplan/ident/rls.h"

#include <cmath>

#include "options_check.h"
#include "uuvplan/ident/regression.h"

namespace uuvplan::ident {

bool RlsOptions::IsValid(std::string* error) const {
  return Require(lambda > 0.9 && lambda <= 1.0,
                 "RlsOptions::lambda = " + std::to_string(lambda) +
                     ". Violated constraint: 0.9 < lambda <= 1 (seed 004)",
                 error) &&
         Require(p0 > 0, "RlsOptions::p0 must be > 0", error);
}

RlsTrajectory RecursiveLeastSquares(const Eigen::MatrixXd& F, const Eigen::VectorXd& Y,
                                    const std::vector<double>& t, const RlsOptions& o,
                                    int rows_per_update) {
  const int p = static_cast<int>(F.cols());
  const int q = std::max(1, rows_per_update);
  const int steps = static_cast<int>(F.rows()) / q;
  RlsTrajectory out;
  Eigen::VectorXd theta = o.theta0.size() == p ? o.theta0 : Eigen::VectorXd::Zero(p);
  Eigen::MatrixXd P = Eigen::MatrixXd::Zero(p, p);
  for (int j = 0; j < p; ++j) {
    const double scale = theta[j] != 0 ? std::abs(theta[j]) : 1.0;
    P(j, j) = o.p0 * scale * scale;
  }
  // Column scales of F keep the prior sensible when θ0 is zero: P0 ∝ 1/‖F_j‖² per row.
  if (o.theta0.size() != p) {
    for (int j = 0; j < p; ++j) {
      const double n2 = F.col(j).squaredNorm() / std::max(1, static_cast<int>(F.rows()));
      P(j, j) = n2 > 0 ? o.p0 / n2 : o.p0;
    }
  }
  out.theta.resize(steps, p);
  out.sigma.resize(steps, p);
  out.t.resize(steps);
  // Running s² with the same forgetting: s² = Σ λ^{k−i} e_i² / Σ λ^{k−i}.
  double se = 0.0, sw = 0.0;
  const Eigen::MatrixXd I = Eigen::MatrixXd::Identity(p, p);
  for (int k = 0; k < steps; ++k) {
    const Eigen::MatrixXd Fk = F.middleRows(k * q, q);
    const Eigen::VectorXd Yk = Y.segment(k * q, q);
    const Eigen::VectorXd e = Yk - Fk * theta;  // a-priori error
    const Eigen::MatrixXd S = o.lambda * Eigen::MatrixXd::Identity(q, q) + Fk * P * Fk.transpose();
    const Eigen::MatrixXd Gamma = P * Fk.transpose() * S.inverse();
    theta += Gamma * e;
    P = (I - Gamma * Fk) * P / o.lambda;
    P = 0.5 * (P + P.transpose());
    const Eigen::VectorXd post = Yk - Fk * theta;
    se = o.lambda * se + post.squaredNorm();
    sw = o.lambda * sw + q;
    const double s2 = sw > p ? se / std::max(1.0, sw - p) : 1.0;
    out.theta.row(k) = theta.transpose();
    out.sigma.row(k) = (P.diagonal().cwiseMax(0.0) * s2).cwiseSqrt().transpose();
    out.t[k] = k * q < static_cast<int>(t.size()) ? t[k * q] : 0.0;
  }
  out.P = P;
  return out;
}

RlsDofResult RecursiveOneStep(const model::DofModel& model,
                              const std::vector<const TrialData*>& trials,
                              const Eigen::VectorXd& theta, const std::vector<int>& free_in,
                              const OneStepOptions& ro, const RlsOptions& o) {
  RlsDofResult r;
  const std::vector<int> free = free_in.empty() ? LinearParameters(model) : free_in;
  const OneStepRows rows = BuildOneStepRows(model, trials, theta, free, ro);
  r.coefficient_names.push_back("gamma");
  for (int j : free) r.coefficient_names.push_back(model.parameter_names()[j] + "/m");
  // Times on the campaign clock so that several trials form one history.
  std::vector<double> t(rows.t.size());
  for (std::size_t k = 0; k < rows.t.size(); ++k) {
    double start = 0.0;
    for (const TrialData* trial : trials) {
      if (trial->index == rows.group[k]) start = trial->start_time;
    }
    t[k] = start + rows.t[k];
  }
  r.psi = RecursiveLeastSquares(rows.F, rows.Y, t, o);
  r.names = model.parameter_names();
  const int steps = static_cast<int>(r.psi.theta.rows());
  r.theta.resize(steps, model.num_parameters());
  for (int k = 0; k < steps; ++k) {
    Eigen::VectorXd phys = theta;
    const double g = r.psi.theta(k, 0);
    phys[0] = 1.0 / g;
    for (std::size_t c = 0; c < free.size(); ++c) phys[free[c]] = r.psi.theta(k, 1 + c) / g;
    r.theta.row(k) = phys.transpose();
  }
  return r;
}

}  // namespace uuvplan::ident
