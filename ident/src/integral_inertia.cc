#include "uuvplan/ident/integral_inertia.h"

#include <cmath>
#include <sstream>

#include "uuvplan/ident/regression.h"
#include "uuvplan/model/effects.h"

namespace uuvplan::ident {

bool IntegralInertiaOptions::IsValid(std::string* error) const {
  if (!(newey_west_windows >= 0) || !(max_step_s > 0) || !(max_condition > 1)) {
    if (error) *error = "IntegralInertiaOptions: newey_west_windows >= 0, max_step_s > 0, max_condition > 1";
    return false;
  }
  return true;
}

IntegralInertiaResult IntegralInertiaFit(const model::DofModel& model,
                                         const std::vector<const TrialData*>& trials,
                                         const Eigen::VectorXd& theta,
                                         const Eigen::MatrixXd* known_cov,
                                         const IntegralInertiaOptions& o) {
  IntegralInertiaResult r;
  const int np = model.num_parameters();
  const auto& names = model.parameter_names();
  // Known parameters whose integrals enter y: linear ones except the constant terms.
  std::vector<int> known;
  for (int j : LinearParameters(model)) {
    if (names[j] != model::param::kBias && names[j] != model::param::kBiasStep) known.push_back(j);
  }
  Eigen::VectorXd theta_known = theta;
  for (int j = 0; j < np; ++j) {
    if (names[j] == model::param::kBias || names[j] == model::param::kBiasStep) theta_known[j] = 0.0;
  }
  // Per run: samples, cumulative integrals.
  struct Run {
    int trial;
    std::vector<double> t, xi;
    Eigen::MatrixXd Y;  // samples × np cumulative ∫h
    Eigen::VectorXd Y0; // cumulative ∫h0
  };
  std::vector<Run> runs;
  int sg_window = 21;
  for (const TrialData* trial : trials) {
    const SmoothedSignal& v = trial->velocity_estimate;
    sg_window = trial->sg_window;
    std::size_t i = 0;
    while (i < v.size()) {
      const int run_id = v.run[i];
      Run run;
      run.trial = trial->index;
      for (; i < v.size() && v.run[i] == run_id; ++i) {
        if (v.edge[i] || std::isnan(v.value[i])) continue;
        run.t.push_back(v.t[i]);
        run.xi.push_back(v.value[i]);
      }
      if (run.t.size() < 10) continue;
      const IntegratedRegressors ir = IntegrateRegressors(model, *trial, run.t, theta_known, o.max_step_s);
      const int k = static_cast<int>(run.t.size());
      run.Y = Eigen::MatrixXd::Zero(k, np);
      run.Y0 = Eigen::VectorXd::Zero(k);
      for (int s = 1; s < k; ++s) {
        run.Y.row(s) = run.Y.row(s - 1) + ir.H.row(s - 1);
        run.Y0[s] = run.Y0[s - 1] + ir.h0[s - 1];
      }
      runs.push_back(std::move(run));
    }
  }
  int n = 0;
  for (const Run& run : runs) n += static_cast<int>(run.t.size());
  const int p = 1 + 2 * static_cast<int>(runs.size());
  r.num_samples = n;
  if (runs.empty() || n < p + 2) {
    r.status = FitStatus::kTooFewData;
    r.message = "integral method: no run of at least 10 usable velocity samples";
    return r;
  }
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, p);
  Eigen::VectorXd y(n);
  std::vector<int> groups(n);
  Eigen::MatrixXd Yk(n, static_cast<int>(known.size()));
  int row = 0;
  for (std::size_t q = 0; q < runs.size(); ++q) {
    const Run& run = runs[q];
    for (std::size_t s = 0; s < run.t.size(); ++s, ++row) {
      double yk = run.Y0[s];
      for (std::size_t c = 0; c < known.size(); ++c) {
        Yk(row, c) = run.Y(s, known[c]);
        yk += theta_known[known[c]] * run.Y(s, known[c]);
      }
      y[row] = yk;
      H(row, 0) = run.xi[s];                       // m      (eq. 18)
      H(row, 1 + 2 * q) = -1.0;                    // c = m·ξ_s + k·χ_s
      H(row, 2 + 2 * q) = -(run.t[s] - run.t[0]);  // b
      groups[row] = static_cast<int>(q);
    }
  }
  LeastSquaresOptions lso;
  lso.covariance = CovarianceKind::kResidual;  // eqs. 11–12
  lso.max_condition = o.max_condition;
  const LinearFit fit = SolveLeastSquares(H, y, nullptr, lso);
  r.condition_number = fit.condition_number;
  if (fit.status != FitStatus::kOk) {
    r.status = fit.status;
    r.message = "integral method: " + fit.message +
                (fit.status == FitStatus::kIllConditioned
                     ? " — the velocity does not vary enough apart from a constant and a trend "
                       "(excite the DOF dynamically, e.g. a sine at the d-optimal frequency, seed 000 eq. 14)"
                     : "");
    return r;
  }
  r.m = fit.theta[0];
  r.sigma_eq11 = std::sqrt(fit.covariance(0, 0));
  const int lags = std::max(1, static_cast<int>(std::lround(o.newey_west_windows * sg_window)));
  const Eigen::MatrixXd hac = NeweyWestCovariance(H, fit.residuals, nullptr, lags, &groups);
  r.sigma_hac = std::sqrt(std::max(0.0, hac(0, 0)));
  // ∂m̂/∂θ_j = e_0ᵀ (HᵀH)⁻¹ Hᵀ Y_j.
  double var_known = 0.0;
  if (o.propagate_known_uncertainty && known_cov && !known.empty()) {
    const Eigen::MatrixXd N = H.transpose() * H;
    const Eigen::VectorXd a = N.ldlt().solve(Eigen::VectorXd::Unit(p, 0));
    const Eigen::VectorXd g = H * a;
    Eigen::VectorXd J(known.size());
    for (std::size_t c = 0; c < known.size(); ++c) J[c] = g.dot(Yk.col(c));
    Eigen::MatrixXd S(known.size(), known.size());
    for (std::size_t a1 = 0; a1 < known.size(); ++a1) {
      for (std::size_t b1 = 0; b1 < known.size(); ++b1) S(a1, b1) = (*known_cov)(known[a1], known[b1]);
    }
    var_known = J.dot(S * J);
  }
  r.sigma_known = std::sqrt(std::max(0.0, var_known));
  r.sigma = std::sqrt(r.sigma_hac * r.sigma_hac + var_known);
  for (std::size_t q = 0; q < runs.size(); ++q) {
    r.run_c.push_back(fit.theta[1 + 2 * q]);
    r.run_b.push_back(fit.theta[2 + 2 * q]);
    r.run_trial.push_back(runs[q].trial);
  }
  r.estimate.name = model::param::kMass;
  r.estimate.value = r.m;
  r.estimate.sigma = r.sigma;
  r.estimate.significant = std::abs(r.m) >= 1.959963984540054 * r.sigma;
  if (!(r.m > 0)) {
    r.notes.push_back("integral method gave a non-positive inertia: the data do not determine m");
  }
  std::ostringstream os;
  os.precision(4);
  os << "integral method on " << n << " samples in " << runs.size() << " run(s): m = " << r.m
     << " ± " << r.sigma << " (eqs. 11–12 alone: ± " << r.sigma_eq11 << ")";
  r.message = os.str();
  r.status = FitStatus::kOk;
  return r;
}

}  // namespace uuvplan::ident
