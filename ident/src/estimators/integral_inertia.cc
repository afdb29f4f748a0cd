#include "uuvplan/ident/estimators/integral_inertia.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "options_check.h"
#include "uuvplan/ident/estimators/regression.h"
#include "uuvplan/ident/stats/covariance.h"
#include "uuvplan/ident/stats/sub_matrix.h"
#include "uuvplan/model/effects.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {

bool IntegralInertiaOptions::IsValid(std::string* error) const {
  return Require(newey_west_windows >= 0 && max_step_s > 0 && max_condition > 1,
                 "IntegralInertiaOptions: newey_west_windows >= 0, max_step_s > 0, "
                 "max_condition > 1",
                 error);
}

namespace {

// One run of usable samples (away from command steps) with its cumulative integrals.
struct Run {
  int trial;
  std::vector<double> t, xi;
  Eigen::MatrixXd Y;       // samples × np cumulative ∫h
  Eigen::VectorXd Y0;      // cumulative ∫h0
  double noise_var = 0.0;  // variance of the filtered velocity's noise
  // Raw measured samples (white noise of variance noise_var, every sample a row): D[s] is the
  // derivative of interval s's known-force integral with respect to a velocity offset.
  bool white = false;
  std::vector<double> D;
  double rho = 0.0;  // AR(1) coefficient of the raw samples' noise (covariance.h)
  // Position-derived velocity: each sample's Savitzky–Golay derivative weights on the raw
  // positions, and its noise variance σ²·wᵀΩw (empty: noise_var for every sample).
  std::vector<SampleWeights> weights;
  std::vector<double> sample_var;
  double position_var = 0.0;
};

// One row of the regression y_i = m·ξ_i − c_run − (t_i − t_s)·b_trial (ref 000 eqs. 16–19).
// Each row has three non-zeros: H_i = ξ_i·e_0 − e_{c(run)} − (t_i − t_s)·e_{b(trial)}.
struct Row {
  double xi, dt, y, noise_var;
  int c, b, group;  // rows are the runs' samples in order: run `group`, its samples
};

double RowDot(const Row& w, const Eigen::VectorXd& v) {
  return w.xi * v[0] - v[w.c] - w.dt * v[w.b];
}

// The known-force integrals of a run of raw samples shifted by ±dv: their central difference
// (exact for the linear and quadratic drag terms) is D.
std::vector<double> WhiteNoiseSensitivity(const model::DofModel& model, const TrialData& trial,
                                          const Run& run, const SmoothedSignal& raw,
                                          const Eigen::VectorXd& theta_known, double max_step_s) {
  double vmax = 0.0;
  for (double x : run.xi) vmax = std::max(vmax, std::abs(x));
  const double dv = 1e-3 * std::max(vmax, 1e-9);
  const IntegratedRegressors ip =
      IntegrateRegressors(model, trial, run.t, theta_known, max_step_s, &raw, dv);
  const IntegratedRegressors im =
      IntegrateRegressors(model, trial, run.t, theta_known, max_step_s, &raw, -dv);
  const Eigen::VectorXd d = ((ip.H - im.H) * theta_known + (ip.h0 - im.h0)) / (2.0 * dv);
  return std::vector<double>(d.data(), d.data() + d.size());
}

// A position-derived run's noise, sample by sample: the derivative weights the filter applied
// at each sample (the window shrinks at a short run, shifts at its ends and follows the actual
// times around a dropped sample), and the derivative's variance σ²·wᵀΩw under the position
// noise's AR(1) ρ (covariance.h). One gain for the whole trial (the first run's) gave a
// 12-fold variance when that run was short, and an errors-in-variables correction that put
// m̂ at 1461 kg for 890.
void PositionSampleNoise(const TrialData& trial, std::size_t begin, std::size_t end, Run* run) {
  run->weights = SavitzkyGolayDerivativeWeights(trial.position, trial.sg_options, begin, end);
  run->rho = trial.position_noise_ar1;
  const double var = trial.position_sigma * trial.position_sigma;
  run->position_var = var;
  for (const SampleWeights& w : run->weights) {
    run->sample_var.push_back(var * std::max(0.0, Ar1QuadraticForm(w.w, run->rho)));
  }
}

// The runs of one trial. Measured velocities: the regression uses the samples themselves, not
// the smoothed ones. Their noise is then white with the sensor's declared σ (gain 1): the
// corrected least squares removes it from HᵀH exactly, and its effect on m̂ — including the
// random walk it makes in the cumulative drag integrals y — is propagated exactly (σ_white),
// which the smoothed samples' correlated noise would not allow. Between samples they are
// joined by cubic Hermite with the filter's accelerations as slopes (linear interpolation
// would bias ∫ξ|ξ| by ~(ωΔt)²/12). Position-derived velocities have no such samples and keep
// the Savitzky–Golay derivative (ref 000 §IV-D) and the Newey–West σ.
void AddRuns(const model::DofModel& model, const TrialData& trial,
             const Eigen::VectorXd& theta_known, std::size_t stride,
             const IntegralInertiaOptions& o, std::vector<Run>* runs) {
  const int np = model.num_parameters();
  const SmoothedSignal& v = trial.velocity_estimate;
  const double input_sigma =
      trial.velocity_from_position ? trial.position_sigma : trial.velocity_sigma;
  const bool raw = o.raw_measured_velocity && !trial.velocity_from_position &&
                   trial.velocity.size() == v.size() &&
                   std::equal(v.t.begin(), v.t.end(), trial.velocity.t.begin());
  SmoothedSignal raw_signal;
  if (raw) {
    raw_signal = v;
    raw_signal.value.assign(trial.velocity.y.begin(), trial.velocity.y.end());
  }
  const SmoothedSignal& src = raw ? raw_signal : v;
  // The sensor's noise colour from its own samples (ρ = 1 + 2·γ_d(1)/γ_d(0) of the differences
  // of raw − smoothed).
  const double rho =
      raw ? NoiseAr1FromDifferences(trial.velocity.y, {v.value.begin(), v.value.end()}) : 0.0;
  for (const auto& [begin, end] : SmoothRuns(trial)) {
    Run run;
    run.trial = trial.index;
    // Raw samples: the sensor's σ (gain 1); else the filter's noise (AR(1)-aware).
    run.noise_var = raw ? (input_sigma > 0 ? std::pow(input_sigma, 2) : 0.0)
                        : std::pow(VelocityNoiseSigma(trial), 2);
    for (std::size_t i = begin; i < end; i += stride) {
      run.t.push_back(src.t[i]);
      run.xi.push_back(src.value[i]);
    }
    if (run.t.size() < 10) continue;
    const IntegratedRegressors ir = IntegrateRegressors(model, trial, run.t, theta_known,
                                                        o.max_step_s, raw ? &raw_signal : nullptr);
    const int k = static_cast<int>(run.t.size());
    run.Y = Eigen::MatrixXd::Zero(k, np);
    run.Y0 = Eigen::VectorXd::Zero(k);
    for (int s = 1; s < k; ++s) {
      run.Y.row(s) = run.Y.row(s - 1) + ir.H.row(s - 1);
      run.Y0[s] = run.Y0[s - 1] + ir.h0[s - 1];
    }
    if (raw && stride == 1 && run.noise_var > 0) {
      run.D = WhiteNoiseSensitivity(model, trial, run, raw_signal, theta_known, o.max_step_s);
      run.white = true;
      run.rho = rho;
    } else if (!raw && stride == 1 && input_sigma > 0) {
      PositionSampleNoise(trial, begin, end, &run);
      run.D = WhiteNoiseSensitivity(model, trial, run, v, theta_known, o.max_step_s);
      run.white = true;
    }
    runs->push_back(std::move(run));
  }
}

// The rows of every run: unknowns m, c of each run, b of each trial (the constant force is
// common to a trial). `trial_ids` lists the trials in the order of their b.
std::vector<Row> BuildRows(const std::vector<Run>& runs, const std::vector<int>& known,
                           const Eigen::VectorXd& theta_known, const std::vector<int>& trial_ids) {
  const int R = static_cast<int>(runs.size());
  std::vector<Row> rows;
  for (int q = 0; q < R; ++q) {
    const Run& run = runs[q];
    const int tb = 1 + R +
                   static_cast<int>(std::find(trial_ids.begin(), trial_ids.end(), run.trial) -
                                    trial_ids.begin());
    for (std::size_t s = 0; s < run.t.size(); ++s) {
      Row row;
      double yk = run.Y0[s];
      for (int j : known) yk += theta_known[j] * run.Y(s, j);
      row.y = yk;
      row.xi = run.xi[s];
      row.dt = run.t[s] - run.t[0];
      row.noise_var = run.sample_var.empty() ? run.noise_var : run.sample_var[s];
      row.c = 1 + q;
      row.b = tb;
      row.group = q;
      rows.push_back(std::move(row));
    }
  }
  return rows;
}

// Normal equations N = HᵀH, Hᵀy accumulated from the sparse rows, and Σ var(e_i).
void NormalEquations(const std::vector<Row>& rows, int p, Eigen::MatrixXd* N, Eigen::VectorXd* hty,
                     double* noise_sum) {
  *N = Eigen::MatrixXd::Zero(p, p);
  *hty = Eigen::VectorXd::Zero(p);
  *noise_sum = 0.0;
  for (const Row& w : rows) {
    const int idx[3] = {0, w.c, w.b};
    const double val[3] = {w.xi, -1.0, -w.dt};
    for (int a1 = 0; a1 < 3; ++a1) {
      (*hty)[idx[a1]] += val[a1] * w.y;
      for (int b1 = 0; b1 < 3; ++b1) (*N)(idx[a1], idx[b1]) += val[a1] * val[b1];
    }
    *noise_sum += w.noise_var;
  }
}

// Condition number of the column-scaled problem.
double ScaledConditionNumber(const Eigen::MatrixXd& N) {
  const Eigen::VectorXd d = N.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::MatrixXd Ns = d.asDiagonal() * N * d.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(Ns);
  const double lo = std::max(es.eigenvalues().minCoeff(), 0.0), hi = es.eigenvalues().maxCoeff();
  return lo > 0 ? std::sqrt(hi / lo) : std::numeric_limits<double>::infinity();
}

// Newey–West sum of the influences ψ_i (Bartlett weights, lags within runs), scaled by n/(n−p).
double NeweyWestVariance(const std::vector<Row>& rows, const std::vector<double>& psi, int lags,
                         int p) {
  const int n = static_cast<int>(rows.size());
  double var_hac = 0.0;
  for (int i = 0; i < n; ++i) var_hac += psi[i] * psi[i];
  for (int l = 1; l <= lags; ++l) {
    const double kappa = 1.0 - static_cast<double>(l) / (lags + 1);
    double c = 0.0;
    for (int i = l; i < n; ++i) {
      if (rows[i].group == rows[i - l].group) c += psi[i] * psi[i - l];
    }
    var_hac += 2.0 * kappa * c;
  }
  return var_hac * (static_cast<double>(n) / std::max(1, n - p));
}

// ∂m̂/∂θ_j = e₀ᵀ Nc⁻¹ Hᵀ Y_j (m̂ is linear in the known parameters through y): the variance
// the known parameters' covariance adds to m̂. Y_j of a row: its run's cumulative integral
// (BuildRows: the rows are the runs' samples in order).
double KnownParameterVariance(const std::vector<Run>& runs, const std::vector<Row>& rows,
                              const Eigen::VectorXd& a0, const std::vector<int>& known,
                              const Eigen::MatrixXd& known_cov) {
  Eigen::VectorXd J = Eigen::VectorXd::Zero(known.size());
  std::size_t i = 0;
  for (const Run& run : runs) {
    for (std::size_t s = 0; s < run.t.size(); ++s, ++i) {
      const double g = RowDot(rows[i], a0);
      for (std::size_t c = 0; c < known.size(); ++c) J[c] += g * run.Y(s, known[c]);
    }
  }
  return J.dot(SubMatrix(known_cov, known) * J);
}

// Σ_s c_s·ξ̃_s's noise for a position-derived run: ξ̃_s = Σ_j w_sj·χ_j, so the sensitivity to
// the raw positions is u_j = Σ_s c_s·w_sj and the variance σ_χ²·uᵀΩu (AR(1) ρ of the positions).
std::vector<double> PositionSensitivity(const Run& run, const std::vector<double>& c) {
  std::size_t lo = std::numeric_limits<std::size_t>::max(), hi = 0;
  for (const SampleWeights& w : run.weights) {
    lo = std::min(lo, w.first);
    hi = std::max(hi, w.first + w.w.size());
  }
  if (hi <= lo) return {};
  std::vector<double> u(hi - lo, 0.0);
  for (std::size_t s = 0; s < run.weights.size() && s < c.size(); ++s) {
    const SampleWeights& w = run.weights[s];
    for (std::size_t j = 0; j < w.w.size(); ++j) u[w.first - lo + j] += c[s] * w.w[j];
  }
  return u;
}

// Var(Σ_s c_s·e_s) of one run's velocity noise: σ²·cᵀΩc for raw measured samples, σ_χ²·uᵀΩu
// through the filter's weights for a position-derived velocity.
double RunNoiseQuadratic(const Run& run, const std::vector<double>& c) {
  if (run.weights.empty()) return run.noise_var * Ar1QuadraticForm(c, run.rho);
  return run.position_var * Ar1QuadraticForm(PositionSensitivity(run, c), run.rho);
}

// Cov(Σ_s a_s·e_s, Σ_s b_s·e_s) by polarisation: (Var(a + b) − Var(a − b))/4.
double RunNoiseBilinear(const Run& run, const std::vector<double>& a,
                        const std::vector<double>& b) {
  std::vector<double> sum(a.size()), diff(a.size());
  for (std::size_t s = 0; s < a.size(); ++s) {
    sum[s] = a[s] + b[s];
    diff[s] = a[s] - b[s];
  }
  return 0.25 * (RunNoiseQuadratic(run, sum) - RunNoiseQuadratic(run, diff));
}

// E eᵀMe = tr(MΣ) = tr(Σ) − tr((XᵀX)⁻¹XᵀΣX), X the nuisance columns (each run's −1, each
// trial's −(t − t_s)), XᵀX the lower-right block of N: the errors-in-variables correction of m
// once c and b are profiled out. tr(Σ) alone over-corrects by the noise of each run's mean and
// trend (incidental parameters, Neyman & Scott 1948): +0.4% in m on URIS yaw's 20 PRBS runs.
double ProjectedNoiseTrace(const std::vector<Run>& runs, const std::vector<Row>& rows,
                           const Eigen::MatrixXd& N, double noise_trace) {
  const int p = static_cast<int>(N.rows());
  Eigen::MatrixXd B = Eigen::MatrixXd::Zero(p - 1, p - 1);
  std::size_t i0 = 0;
  for (const Run& run : runs) {
    const std::size_t k = run.t.size();
    if (k == 0) continue;
    const Row& first = rows[i0];
    std::vector<double> one(k, -1.0), trend(k);
    for (std::size_t s = 0; s < k; ++s) trend[s] = -rows[i0 + s].dt;
    const int c = first.c - 1, b = first.b - 1;
    B(c, c) += RunNoiseQuadratic(run, one);
    const double cb = RunNoiseBilinear(run, one, trend);
    B(c, b) += cb;
    B(b, c) += cb;
    B(b, b) += RunNoiseQuadratic(run, trend);
    i0 += k;
  }
  const Eigen::MatrixXd A = N.bottomRightCorner(p - 1, p - 1);
  return noise_trace - A.ldlt().solve(B).trace();
}

// Known-noise propagation for runs of raw measured samples (white, declared σ): sample s's
// error e_s enters H_s (−m̂·e_s after moving it to the residual) and, through the drag terms,
// every later y_i: by half of each adjacent interval's sensitivity D (the interpolation's
// value basis integrates to ½ on each side). m̂ = Σ_i g_i·y_i (g_i = H_i·Nc⁻¹e₀), so
//   ∂m̂/∂e_s = ½D_{s−1}·Σ_{i≥s} g_i + ½D_s·Σ_{i>s} g_i − m̂·g_s,
//   σ²_white = σ²·Σ_s Σ_t (∂m̂/∂e_s)(∂m̂/∂e_t)·ρ^|s−t|
// for the sensor's AR(1) noise (ρ from its samples, NoiseAr1FromDifferences; ρ = 0: white).
// The integrals make these errors cumulative (a random walk along the run), which a
// Newey–West window of a few filter spans cannot see.
double WhiteNoiseVariance(const std::vector<Run>& runs, const std::vector<Row>& rows,
                          const Eigen::VectorXd& a0, double m) {
  double var_white = 0.0;
  int i0 = 0;
  for (const Run& run : runs) {
    const int k = static_cast<int>(run.t.size());
    std::vector<double> g(k), tail(k + 1, 0.0);
    for (int s2 = 0; s2 < k; ++s2) g[s2] = RowDot(rows[i0 + s2], a0);
    for (int s2 = k - 1; s2 >= 0; --s2) tail[s2] = tail[s2 + 1] + g[s2];
    std::vector<double> c(k);
    for (int s2 = 0; s2 < k; ++s2) {
      c[s2] = -m * g[s2];
      if (s2 > 0) c[s2] += 0.5 * run.D[s2 - 1] * tail[s2];
      if (s2 + 1 < k) c[s2] += 0.5 * run.D[s2] * tail[s2 + 1];
    }
    var_white += RunNoiseQuadratic(run, c);
    i0 += k;
  }
  return var_white;
}

// Σ_ab Cov(e_a, e_b)² = tr(Σ²) of one run's velocity noise. Raw measured samples: Σ = σ²Ω,
// tr(Ω²) = n + 2·Σ_l (n − l)·ρ^{2l}. Position-derived: Cov(e_a, e_b) = σ_χ²·w_aᵀΩw_b (the
// filter's weights), Ωw_a by the two one-sided AR(1) recursions on the span where ρ^d > 1e-6
// (beyond it the covariances are below 1e-6 of the variance and their squares negligible).
double NoiseCovarianceSquaredSum(const Run& run) {
  const double rho = std::clamp(run.rho, 0.0, 0.999);
  const std::size_t reach =
      rho > 0 ? static_cast<std::size_t>(std::ceil(std::log(1e-6) / std::log(rho))) : 0;
  if (run.weights.empty()) {
    const std::size_t n = run.t.size();
    double sum = static_cast<double>(n), r2l = 1.0;
    for (std::size_t l = 1; l < n && l <= reach; ++l) {
      r2l *= rho * rho;
      sum += 2.0 * static_cast<double>(n - l) * r2l;
    }
    return run.noise_var * run.noise_var * sum;
  }
  double sum = 0.0;
  std::vector<double> z, fwd, bwd;
  for (std::size_t a = 0; a < run.weights.size(); ++a) {
    const SampleWeights& wa = run.weights[a];
    if (wa.w.empty()) continue;
    const std::size_t lo = wa.first > reach ? wa.first - reach : 0;
    const std::size_t hi = wa.first + wa.w.size() + reach + 1;
    const std::size_t len = hi - lo;
    fwd.assign(len, 0.0);
    bwd.assign(len, 0.0);
    for (std::size_t j = 0; j < wa.w.size(); ++j)
      fwd[wa.first - lo + j] = bwd[wa.first - lo + j] = wa.w[j];
    z.assign(len, 0.0);
    for (std::size_t j = 1; j < len; ++j) fwd[j] += rho * fwd[j - 1];
    for (std::size_t j = len - 1; j-- > 0;) bwd[j] += rho * bwd[j + 1];
    for (std::size_t j = 0; j < len; ++j) z[j] = fwd[j] + bwd[j];
    for (std::size_t j = 0; j < wa.w.size(); ++j)
      z[wa.first - lo + j] -= wa.w[j];  // Ωw = f + b − w
    for (std::size_t b = a; b < run.weights.size(); ++b) {
      const SampleWeights& wb = run.weights[b];
      if (wb.first >= hi) break;
      double c = 0.0;
      for (std::size_t j = 0; j < wb.w.size(); ++j) {
        const std::size_t idx = wb.first + j;
        if (idx >= lo && idx < hi) c += wb.w[j] * z[idx - lo];
      }
      sum += (b == a ? 1.0 : 2.0) * c * c;
    }
  }
  return run.position_var * run.position_var * sum;
}

// Known parameters whose integrals enter y: linear ones except the constant terms (bias and
// ballast step, which the per-trial b absorbs); theta with those constant terms at 0.
std::vector<int> KnownParameters(const model::DofModel& model, const Eigen::VectorXd& theta,
                                 Eigen::VectorXd* theta_known) {
  const auto& names = model.parameter_names();
  auto constant = [&](int j) {
    return names[j] == model::param::kBias || names[j] == model::param::kBiasStep;
  };
  std::vector<int> known;
  for (int j : LinearParameters(model)) {
    if (!constant(j)) known.push_back(j);
  }
  *theta_known = theta;
  for (int j = 0; j < model.num_parameters(); ++j) {
    if (constant(j)) (*theta_known)[j] = 0.0;
  }
  return known;
}

// Rows: the usable samples, thinned to at most kMaxRows in all (the integrals between kept
// samples still follow every sample of the filtered velocity; only the equations thin out).
std::size_t RowStride(const std::vector<const TrialData*>& trials) {
  constexpr std::size_t kMaxRows = 20000;
  std::size_t usable = 0;
  for (const TrialData* trial : trials) {
    for (const auto& [begin, end] : SmoothRuns(*trial)) usable += end - begin;
  }
  return std::max<std::size_t>(1, (usable + kMaxRows - 1) / kMaxRows);
}

std::vector<int> TrialIds(const std::vector<Run>& runs) {
  std::vector<int> trial_ids;
  for (const Run& run : runs) {
    if (std::find(trial_ids.begin(), trial_ids.end(), run.trial) == trial_ids.end()) {
      trial_ids.push_back(run.trial);
    }
  }
  return trial_ids;
}

// σ of m̂ (r->sigma_eq11, sigma_hac, sigma_known, sigma_white, sigma) from the solved system.
void Uncertainty(const std::vector<Run>& runs, const std::vector<Row>& rows,
                 const Eigen::MatrixXd& N, const Eigen::VectorXd& est, const Eigen::VectorXd& a0,
                 int lags, const std::vector<int>& known, const Eigen::MatrixXd* known_cov,
                 const IntegralInertiaOptions& o, IntegralInertiaResult* r) {
  const int n = static_cast<int>(rows.size()), p = static_cast<int>(est.size());
  // Residuals, the eq. 11–12 σ, and the influence ψ_i = e₀ᵀNc⁻¹(h_i r_i + var(e_i)·m·e₀) of
  // each row on m, whose Newey–West sum (lags spanning `newey_west_windows` filter windows,
  // within runs) is the variance of m.
  std::vector<double> psi(n);
  double rss = 0.0;
  for (int i = 0; i < n; ++i) {
    const Row& w = rows[i];
    const double res = w.y - RowDot(w, est);
    rss += res * res;
    psi[i] = RowDot(w, a0) * res + (o.errors_in_variables ? a0[0] * w.noise_var * r->m : 0.0);
  }
  const Eigen::VectorXd a0_plain = N.ldlt().solve(Eigen::VectorXd::Unit(p, 0));
  r->sigma_eq11 = std::sqrt(std::max(0.0, rss / std::max(1, n - p) * a0_plain[0]));
  r->sigma_hac = std::sqrt(std::max(0.0, NeweyWestVariance(rows, psi, lags, p)));
  double var_known = 0.0;
  if (o.propagate_known_uncertainty && known_cov && !known.empty()) {
    var_known = KnownParameterVariance(runs, rows, a0, known, *known_cov);
  }
  r->sigma_known = std::sqrt(std::max(0.0, var_known));
  bool all_white = !runs.empty();
  for (const Run& run : runs) all_white = all_white && run.white;
  if (all_white) {
    // The second-order term of the errors in variables. m̂ solves the corrected score
    // ψ(m) = ξ̃ᵀM(y − mξ̃) + m·Σvar(e_i) = 0 (M: the runs' c and the trials' b projected out),
    // whose noise part is −m·ξᵀMe − m·(eᵀMe − E eᵀMe): variance m²·ξᵀMΣMξ + 2m²·tr((MΣ)²)
    // under Gaussian noise (Var eᵀAe = 2tr((AΣ)²), Searle 1971 §2.5), over b² (b = 1/[Nc⁻¹]₀₀).
    // WhiteNoiseVariance evaluates the first term at the noisy ξ̃ = ξ + e (g_s), which adds
    // m²·tr((MΣ)²) on average; the other tr(Σ²) is added here (M's share is O(p/n), left out).
    // With short filter windows and few rows per run (URIS yaw PRBS: 11 points at 12.5 Hz, the
    // noise 22% of b) it is half the first-order σ; without it 84% covered.
    double tr2 = 0.0;
    for (const Run& run : runs) tr2 += NoiseCovarianceSquaredSum(run);
    r->sigma_quadratic = std::sqrt(tr2) * std::abs(r->m * a0[0]);
    const double var_first = WhiteNoiseVariance(runs, rows, a0, r->m);
    r->sigma_white = std::sqrt(var_first + r->sigma_quadratic * r->sigma_quadratic);
  }
  // The noise part of σ_m: the exact propagation of the declared white noise when every run is
  // of raw measured samples (VSOR: 0.607 against a Monte Carlo sd of 0.612, while the HAC σ
  // scattered between 0.35 and 0.91 over repetitions), otherwise the Newey–West σ.
  const double sigma_noise = all_white ? r->sigma_white : r->sigma_hac;
  r->sigma = std::sqrt(sigma_noise * sigma_noise + var_known);
}

// The estimate, the per-run constants and the message.
void Report(const std::vector<Run>& runs, const std::vector<int>& trial_ids,
            const Eigen::VectorXd& est, IntegralInertiaResult* r) {
  const int R = static_cast<int>(runs.size());
  for (int q = 0; q < R; ++q) {
    const int tb = 1 + R +
                   static_cast<int>(std::find(trial_ids.begin(), trial_ids.end(), runs[q].trial) -
                                    trial_ids.begin());
    r->run_c.push_back(est[1 + q]);
    r->run_b.push_back(est[tb]);
    r->run_trial.push_back(runs[q].trial);
  }
  r->estimate.name = model::param::kMass;
  r->estimate.value = r->m;
  r->estimate.sigma = r->sigma;
  r->estimate.significant = std::abs(r->m) >= 1.959963984540054 * r->sigma;
  if (!(r->m > 0)) {
    r->notes.push_back("integral method gave a non-positive inertia: the data do not determine m");
  }
  std::ostringstream os;
  os.precision(4);
  os << "integral method on " << r->num_samples << " samples in " << runs.size()
     << " run(s): m = " << r->m << " ± " << r->sigma << " (eqs. 11–12 alone: ± " << r->sigma_eq11
     << ")";
  r->message = os.str();
  r->status = FitStatus::kOk;
}

}  // namespace

IntegralInertiaResult IntegralInertiaFit(const model::DofModel& model,
                                         const std::vector<const TrialData*>& trials,
                                         const Eigen::VectorXd& theta,
                                         const Eigen::MatrixXd* known_cov,
                                         const IntegralInertiaOptions& o) {
  IntegralInertiaResult r;
  Eigen::VectorXd theta_known;
  const std::vector<int> known = KnownParameters(model, theta, &theta_known);
  const std::size_t stride = RowStride(trials);
  std::vector<Run> runs;
  int sg_window = 21;
  for (const TrialData* trial : trials) {
    sg_window = trial->sg_window;
    AddRuns(model, *trial, theta_known, stride, o, &runs);
  }
  const std::vector<int> trial_ids = TrialIds(runs);
  const int p = 1 + static_cast<int>(runs.size() + trial_ids.size());
  const std::vector<Row> rows = BuildRows(runs, known, theta_known, trial_ids);
  const int n = static_cast<int>(rows.size());
  r.num_samples = n;
  if (runs.empty() || n < p + 2) {
    r.status = FitStatus::kTooFewData;
    r.message =
        "integral method: no run of at least 10 usable velocity samples away from "
        "command steps";
    return r;
  }
  Eigen::MatrixXd N;
  Eigen::VectorXd hty;
  double noise_sum = 0.0;
  NormalEquations(rows, p, &N, &hty, &noise_sum);
  r.condition_number = ScaledConditionNumber(N);
  if (!(r.condition_number < o.max_condition)) {
    r.status = FitStatus::kIllConditioned;
    r.message = "integral method: ill-conditioned regression (condition number " +
                model::Significant(r.condition_number, 3) +
                ") — the velocity does not vary enough apart from a constant and a trend (excite "
                "the DOF dynamically, e.g. a sine at the d-optimal frequency, seed 000 eq. 14)";
    return r;
  }
  // Errors in variables: ξ̃ in H carries the filter's noise, E[HᵀH] = HᵀH(true) + Σ var(e_i)
  // in the (m, m) entry, which biases m low. Corrected least squares removes it:
  //   θ = (HᵀH − τ·e₀e₀ᵀ)⁻¹ Hᵀy,  τ = E eᵀMe = tr(MΣ)
  // (M projects out the runs' c and the trials' b: m̂ = ξ̃ᵀMy / (ξ̃ᵀMξ̃ − τ)), τ = Σ var(e_i)
  // when the noise's covariance is not known sample by sample (thinned rows).
  Eigen::MatrixXd Nc = N;
  bool exact_noise = true;
  for (const Run& run : runs) exact_noise = exact_noise && run.white;
  if (o.errors_in_variables) {
    Nc(0, 0) -= exact_noise ? ProjectedNoiseTrace(runs, rows, N, noise_sum) : noise_sum;
  }
  Eigen::LDLT<Eigen::MatrixXd> ldlt(Nc);
  if (ldlt.info() != Eigen::Success || !(ldlt.vectorD().minCoeff() > 0)) {
    r.status = FitStatus::kIllConditioned;
    r.message =
        "integral method: the velocity varies less than its noise (errors in variables "
        "dominate); excite the DOF more or use a longer filter window";
    return r;
  }
  const Eigen::VectorXd est = ldlt.solve(hty);
  r.m = est[0];
  const Eigen::VectorXd a0 = ldlt.solve(Eigen::VectorXd::Unit(p, 0));  // row 0 of Nc⁻¹
  const int lags = std::max(1, static_cast<int>(std::lround(o.newey_west_windows * sg_window /
                                                            static_cast<double>(stride))));
  Uncertainty(runs, rows, N, est, a0, lags, known, known_cov, o, &r);
  Report(runs, trial_ids, est, &r);
  return r;
}

}  // namespace uuvplan::ident
