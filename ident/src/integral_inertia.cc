#include "uuvplan/ident/integral_inertia.h"

#include <algorithm>
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
    double noise_var = 0.0;  // variance of the filtered velocity's noise
  };
  std::vector<Run> runs;
  int sg_window = 21;
  for (const TrialData* trial : trials) {
    const SmoothedSignal& v = trial->velocity_estimate;
    sg_window = trial->sg_window;
    const double input_sigma = trial->velocity_from_position ? trial->position_sigma : trial->velocity_sigma;
    const double gain = trial->velocity_from_position ? v.derivative_gain : v.value_gain;
    for (const auto& [begin, end] : SmoothRuns(*trial)) {
      Run run;
      run.trial = trial->index;
      run.noise_var = input_sigma > 0 ? std::pow(gain * input_sigma, 2) : 0.0;
      for (std::size_t i = begin; i < end; ++i) {
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
  std::vector<int> trial_ids;
  for (const Run& run : runs) {
    n += static_cast<int>(run.t.size());
    if (std::find(trial_ids.begin(), trial_ids.end(), run.trial) == trial_ids.end()) {
      trial_ids.push_back(run.trial);
    }
  }
  // Unknowns: m, c of each run, b of each trial (the constant force is common to a trial).
  const int R = static_cast<int>(runs.size());
  const int p = 1 + R + static_cast<int>(trial_ids.size());
  r.num_samples = n;
  if (runs.empty() || n < p + 2) {
    r.status = FitStatus::kTooFewData;
    r.message = "integral method: no run of at least 10 usable velocity samples away from "
                "command steps";
    return r;
  }
  Eigen::MatrixXd H = Eigen::MatrixXd::Zero(n, p);
  Eigen::VectorXd y(n);
  Eigen::VectorXd noise_var(n);  // variance of the filtered-velocity noise in H(:, 0)
  std::vector<int> groups(n);
  Eigen::MatrixXd Yk(n, static_cast<int>(known.size()));
  int row = 0;
  for (int q = 0; q < R; ++q) {
    const Run& run = runs[q];
    const int tb = 1 + R + static_cast<int>(std::find(trial_ids.begin(), trial_ids.end(), run.trial) - trial_ids.begin());
    for (std::size_t s = 0; s < run.t.size(); ++s) {
      double yk = run.Y0[s];
      for (std::size_t c = 0; c < known.size(); ++c) {
        Yk(row, c) = run.Y(s, known[c]);
        yk += theta_known[known[c]] * run.Y(s, known[c]);
      }
      y[row] = yk;
      H(row, 0) = run.xi[s];                 // m      (eq. 18)
      H(row, 1 + q) = -1.0;                  // c = m·ξ_s + k·χ_s of the run
      H(row, tb) = -(run.t[s] - run.t[0]);   // b
      noise_var[row] = run.noise_var;
      groups[row] = q;
      ++row;
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
  r.sigma_eq11 = std::sqrt(fit.covariance(0, 0));
  // Errors in variables: ξ̃ in H carries the filter's noise, E[HᵀH] = HᵀH(true) + Σ var(e_i)
  // in the (m, m) entry, which biases m low. Corrected least squares removes it:
  //   θ = (HᵀH − Σ_i var(e_i)·e₀e₀ᵀ)⁻¹ Hᵀy.
  Eigen::MatrixXd N = H.transpose() * H;
  if (o.errors_in_variables) N(0, 0) -= noise_var.sum();
  Eigen::LDLT<Eigen::MatrixXd> ldlt(N);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0)) {
    r.status = FitStatus::kIllConditioned;
    r.message = "integral method: the velocity varies less than its noise (errors in variables "
                "dominate); excite the DOF more or use a longer filter window";
    return r;
  }
  const Eigen::VectorXd est = ldlt.solve(H.transpose() * y);
  const Eigen::VectorXd res = y - H * est;
  r.m = est[0];
  // Sandwich covariance of the corrected estimating equations Σ_i [h_i r_i + var(e_i)·θ_m·e₀]
  // with Newey–West lags spanning `newey_west_windows` filter windows.
  const int lags = std::max(1, static_cast<int>(std::lround(o.newey_west_windows * sg_window)));
  Eigen::MatrixXd G(n, p);
  for (int i = 0; i < n; ++i) {
    G.row(i) = H.row(i) * res[i];
    if (o.errors_in_variables) G(i, 0) += noise_var[i] * r.m;
  }
  Eigen::MatrixXd S = G.transpose() * G;
  for (int l = 1; l <= lags; ++l) {
    const double kappa = 1.0 - static_cast<double>(l) / (lags + 1);
    Eigen::MatrixXd C = Eigen::MatrixXd::Zero(p, p);
    for (int i = l; i < n; ++i) {
      if (groups[i] != groups[i - l]) continue;
      C.noalias() += G.row(i).transpose() * G.row(i - l);
    }
    S += kappa * (C + C.transpose());
  }
  const Eigen::MatrixXd Ninv = ldlt.solve(Eigen::MatrixXd::Identity(p, p));
  const Eigen::MatrixXd hac = static_cast<double>(n) / std::max(1, n - p) * Ninv * S * Ninv;
  r.sigma_hac = std::sqrt(std::max(0.0, hac(0, 0)));
  // ∂m̂/∂θ_j = e_0ᵀ N⁻¹ Hᵀ Y_j (m̂ is linear in the known parameters through y).
  double var_known = 0.0;
  if (o.propagate_known_uncertainty && known_cov && !known.empty()) {
    const Eigen::VectorXd g = H * Ninv.col(0);
    Eigen::VectorXd J(known.size());
    for (std::size_t c = 0; c < known.size(); ++c) J[c] = g.dot(Yk.col(c));
    Eigen::MatrixXd Sk(known.size(), known.size());
    for (std::size_t a1 = 0; a1 < known.size(); ++a1) {
      for (std::size_t b1 = 0; b1 < known.size(); ++b1) Sk(a1, b1) = (*known_cov)(known[a1], known[b1]);
    }
    var_known = J.dot(Sk * J);
  }
  r.sigma_known = std::sqrt(std::max(0.0, var_known));
  r.sigma = std::sqrt(r.sigma_hac * r.sigma_hac + var_known);
  for (int q = 0; q < R; ++q) {
    const int tb = 1 + R + static_cast<int>(std::find(trial_ids.begin(), trial_ids.end(), runs[q].trial) - trial_ids.begin());
    r.run_c.push_back(est[1 + q]);
    r.run_b.push_back(est[tb]);
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
