// The output error's fit (output_error.h): a coarse start for long records, Levenberg–Marquardt,
// gross errors left out, the covariance, and ref 000 §IV-D's pruning of insignificant
// parameters with refits.
#include "uuvplan/ident/estimators/output_error.h"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "estimators/output_error_covariance.h"
#include "estimators/output_error_levenberg_marquardt.h"
#include "estimators/output_error_problem.h"
#include "options_check.h"
#include "stats/model_selection.h"
#include "uuvplan/ident/estimators/block_least_squares.h"
#include "uuvplan/ident/stats/chi_square.h"
#include "uuvplan/ident/stats/median_abs.h"
#include "uuvplan/ident/stats/significance.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {

bool OutputErrorOptions::IsValid(std::string* error) const {
  return Require(max_iterations >= 1 && tolerance > 0 && step_s > 0 && max_condition > 1 &&
                     bin_s > 0 && grid_s >= 0,
                 "OutputErrorOptions: max_iterations >= 1, tolerance > 0, step_s > 0, bin_s > 0, "
                 "grid_s >= 0, max_condition > 1",
                 error) &&
         Require(use_position || use_velocity,
                 "OutputErrorOptions: use_position or use_velocity must be true", error);
}

std::string_view OutputErrorStatusName(OutputErrorStatus s) {
  static constexpr model::EnumNames<OutputErrorStatus, 4> kNames{{{
      {OutputErrorStatus::kConverged, "converged"},
      {OutputErrorStatus::kMaxIterations, "max_iterations"},
      {OutputErrorStatus::kIllConditioned, "ill_conditioned"},
      {OutputErrorStatus::kFailed, "failed"},
  }}};
  return kNames.Name(s);
}

namespace {

// The P-value below which the starts judged at rest are refuted (RestPValue): 1e-4, about 3.9σ
// on one fixed initial velocity, so that one campaign in 10⁴ that does start at rest is refitted
// with its initial velocities free (which costs precision, not accuracy).
constexpr double kRestRejected = 1e-4;

using internal::Admissible;
using internal::LevenbergMarquardt;
using internal::LmOutcome;
using internal::Problem;
using internal::StoreCovariance;
using internal::TrialProblem;
using internal::WithResiduals;

// The coarse stage of a long record (OutputErrorOptions::coarse_measurements): the same
// unknowns (z layout) fitted on bins ~duration/coarse_measurements long with a longer RK4
// step, the force averaged over pieces of a bin or a step (AveragedInput: a force logged anew
// at every row would otherwise end a step, and a bin, at every row); its answer starts the
// full-size fit. The start `z0` when the record is short or the
// coarse fit fails (the full-size fit then does all the work, as without this stage).
Eigen::VectorXd CoarseStart(const model::DofModel& model,
                            const std::vector<const TrialData*>& trials,
                            const Eigen::VectorXd& theta, const std::vector<int>& free,
                            const std::vector<TrialInitialState>* initial, const Problem& full,
                            const Eigen::VectorXd& z0, const OutputErrorOptions& o) {
  if (o.coarse_measurements <= 0 || full.num_r() <= 2 * o.coarse_measurements) return z0;
  double duration = 0.0;
  for (const TrialProblem& tp : full.trials()) {
    if (!tp.times().empty()) duration += tp.times().back();
  }
  OutputErrorOptions c = o;
  c.bin_s = std::max(o.bin_s, duration / o.coarse_measurements);
  c.step_s = std::min(std::max(o.step_s, 0.1), std::max(o.step_s, 5.0 * o.step_s));
  c.grid_s = 0.0;
  const Problem coarse(model, trials, theta, free, initial, c, std::max(c.bin_s, c.step_s));
  if (coarse.num_z() != full.num_z() || coarse.num_r() <= coarse.num_z()) return z0;
  const LmOutcome lm = LevenbergMarquardt(coarse, z0, c);
  return !lm.failed && lm.z.allFinite() ? lm.z : z0;
}

// Gross errors the data preparation let through (an outlier next to a command step, say)
// would pull a least-squares fit: residuals beyond 6 robust standard deviations (and 5
// declared σ) are left out and the fit repeated once. Returns how many were left out.
int RefitWithoutGrossErrors(Problem* p, const OutputErrorOptions& o, LmOutcome* lm,
                            int* iterations) {
  const double limit = std::max(5.0, 6.0 * 1.4826 * MedianAbs(lm->r));
  const auto gross =
      std::count_if(lm->r.begin(), lm->r.end(), [&](double x) { return std::abs(x) > limit; });
  if (gross == 0 || gross >= lm->r.size() / 100 + 1) return 0;
  std::vector<char> mask(lm->r.size(), 0);
  for (Eigen::Index i = 0; i < lm->r.size(); ++i) mask[i] = std::abs(lm->r[i]) > limit;
  p->Exclude(mask);
  LmOutcome again = LevenbergMarquardt(*p, lm->z, o);
  *iterations += again.iterations;
  if (again.failed || !WithResiduals(*p, &again)) {
    p->Exclude({});
    return 0;
  }
  *lm = std::move(again);
  return static_cast<int>(gross);
}

// Ref 000 §IV-D model selection: the free parameter to drop (the worst insignificant
// prunable one), or -1; its value and σ are kept and a note says why.
int DropWorst(const std::vector<int>& free, const OutputErrorOptions& o, Eigen::VectorXd* theta,
              std::vector<double>* before_value, std::vector<double>* before_sigma,
              OutputErrorResult* res) {
  const std::vector<PruneCandidate> candidates =
      CandidatesOf(res->names, *theta, res->covariance, free);
  double worst_pe = 0.0;
  std::vector<std::string> kept;
  const int c = WorstInsignificant(candidates, o.selection, &worst_pe, &kept);
  if (c < 0 || free.size() <= 1) {  // the final model: say what it kept
    res->notes.insert(res->notes.end(), kept.begin(), kept.end());
    return -1;
  }
  const int worst = free[c];
  (*before_value)[worst] = (*theta)[worst];
  (*before_sigma)[worst] = std::sqrt(res->covariance(worst, worst));
  res->notes.push_back(res->names[worst] + " = " + model::Significant((*theta)[worst], 4) + " ± " +
                       model::Significant((*before_sigma)[worst], 4) + " (" +
                       model::Significant(worst_pe, 3) +
                       "% > 51.02%): insignificant at 95%, dropped and the rest refitted");
  (*theta)[worst] = 0.0;
  res->state[worst] = ParameterState::kDropped;
  return worst;
}

std::string Message(const OutputErrorResult& res) {
  std::ostringstream os;
  os.precision(4);
  os << "output error: " << OutputErrorStatusName(res.status) << " after " << res.iterations
     << " iterations on " << res.num_residuals << " measurements, s² = " << res.sigma2;
  if (!res.not_identifiable.empty())
    os << "; not identifiable: " << model::Join(res.not_identifiable);
  return os.str();
}

// The fit, ref 000 §IV-D's pruning and the notes; `excluded` receives the final problem's
// gross-error mask (Problem::Exclude).
OutputErrorResult FitAndSelect(const model::DofModel& model,
                               const std::vector<const TrialData*>& trials,
                               const Eigen::VectorXd& theta0,
                               const std::vector<ParameterState>& state0,
                               const OutputErrorOptions& o, std::vector<char>* excluded) {
  OutputErrorResult res;
  const int np = model.num_parameters();
  res.names = model.parameter_names();
  res.theta = theta0;
  res.state = state0;
  res.state.resize(np, ParameterState::kEstimated);
  res.covariance = Eigen::MatrixXd::Zero(np, np);
  res.crb = Eigen::MatrixXd::Zero(np, np);
  if (!Admissible(model, theta0)) {
    res.status = OutputErrorStatus::kFailed;
    res.message = "output error: the starting parameters are not admissible (m must be > 0)";
    return res;
  }
  std::vector<double> before_value(np, 0.0), before_sigma(np, 0.0);
  Eigen::VectorXd theta = theta0;
  std::vector<TrialInitialState> initial;  // of the last fit, the next one's start
  int excluded_total = 0;
  // Fit, then drop the worst insignificant parameter and refit from where the fit ended.
  while (true) {
    std::vector<int> free;
    for (int j = 0; j < np; ++j) {
      if (res.state[j] == ParameterState::kEstimated) free.push_back(j);
    }
    Problem p(model, trials, theta, free, initial.empty() ? nullptr : &initial, o);
    if (p.num_r() <= p.num_z()) {
      res.status = OutputErrorStatus::kFailed;
      res.message = "output error: " + std::to_string(p.num_r()) + " measurements for " +
                    std::to_string(p.num_z()) + " unknowns";
      return res;
    }
    LmOutcome lm =
        LevenbergMarquardt(p,
                           CoarseStart(model, trials, theta, free,
                                       initial.empty() ? nullptr : &initial, p, p.InitialZ(), o),
                           o);
    res.iterations += lm.iterations;
    if (lm.failed || !WithResiduals(p, &lm)) {
      res.status = OutputErrorStatus::kFailed;
      res.message =
          "output error: " +
          (lm.failed ? lm.message : std::string("the simulation fails at the fitted parameters"));
      return res;
    }
    const int gross = RefitWithoutGrossErrors(&p, o, &lm, &res.iterations);
    if (gross > 0) excluded_total = gross;
    *excluded = p.excluded();
    theta = p.Theta(lm.z);
    initial = p.Initial(lm.z);
    StoreCovariance(p, lm, free, o, &res);
    if (!o.selection.prune_insignificant || res.status != OutputErrorStatus::kConverged) break;
    if (DropWorst(free, o, &theta, &before_value, &before_sigma, &res) < 0) break;
  }
  res.theta = theta;
  res.initial = initial;
  res.estimates = EstimatedAndDropped(res.names, res.theta, res.covariance, res.state, before_value,
                                      before_sigma);
  if (excluded_total > 0) {
    res.notes.push_back(std::to_string(excluded_total) +
                        " measurement(s) more than 6 robust σ from the fitted model left out as "
                        "gross errors");
  }
  if (res.hac_covariance) {
    res.notes.push_back(
        "output-error residuals are not white (mean lag-1 autocorrelation " +
        model::Significant(res.residual_lag1, 3) +
        "): model error or coloured noise; σ from the scores prewhitened by an "
        "AR(1) of the residuals per trial and sensor, then batch means (a sandwich)");
  }
  res.message = Message(res);
  return res;
}

// The score (Lagrange multiplier) test of "every start judged at rest is at rest": at the fit
// with those trials' ξ0 fixed at 0, the Gauss–Newton decrement gᵀ(JᵀJ)⁻¹g/s² of the problem
// with them free — g = Jᵀr is zero in every other direction at that minimum — is χ²(q) under
// the hypothesis, q the fixed ξ0 (Rao 1948; Seber & Wild, Nonlinear Regression §5.9.1). Its
// P-value, or 1 when no ξ0 was fixed or the evaluation fails.
double RestPValue(const model::DofModel& model, const std::vector<const TrialData*>& trials,
                  const OutputErrorResult& fit, const std::vector<char>& excluded,
                  const OutputErrorOptions& o) {
  std::vector<TrialInitialState> initial = fit.initial;
  int q = 0;
  for (TrialInitialState& s : initial) {
    if (s.xi0_estimated) continue;
    s.xi0_estimated = true;
    s.xi0 = 0.0;
    ++q;
  }
  if (q == 0) return 1.0;
  std::vector<int> free;
  for (int j = 0; j < model.num_parameters(); ++j) {
    if (fit.state[j] == ParameterState::kEstimated) free.push_back(j);
  }
  Problem p(model, trials, fit.theta, free, &initial, o);
  p.Exclude(excluded);
  BlockLeastSquares J(p.num_free());
  double cost = 0.0;
  const int dof = p.num_r() - p.num_excluded() - p.num_z();
  if (dof <= 0 || !p.Evaluate(p.InitialZ(), nullptr, &J, &cost)) return 1.0;
  const double s2 = 2.0 * cost / dof;
  const double score = J.Gradient().dot(J.Solve(J.Gradient(), 0.0)) / s2;
  return std::isfinite(score) && s2 > 0 ? ChiSquareSurvival(score, q) : 1.0;
}

}  // namespace

OutputErrorResult OutputErrorFit(const model::DofModel& model,
                                 const std::vector<const TrialData*>& trials,
                                 const Eigen::VectorXd& theta0,
                                 const std::vector<ParameterState>& state0,
                                 const OutputErrorOptions& o) {
  std::vector<char> excluded;
  OutputErrorResult res = FitAndSelect(model, trials, theta0, state0, o, &excluded);
  // The score test holds at a minimum only.
  if (o.initial_velocity != InitialVelocity::kAuto || res.status != OutputErrorStatus::kConverged)
    return res;
  const double p_value = RestPValue(model, trials, res, excluded, o);
  if (!(p_value < kRestRejected)) return res;
  OutputErrorOptions moving = o;
  moving.initial_velocity = InitialVelocity::kEstimate;
  OutputErrorResult refit = FitAndSelect(model, trials, theta0, state0, moving, &excluded);
  const std::string refuted =
      "the trials whose first samples looked at rest do not start at rest by the whole fit "
      "(score test of their initial velocities at 0: P " +
      (p_value < 1e-16 ? std::string("< 1e-16") : "= " + model::Significant(p_value, 2)) + ")";
  // Moving starts explain the misfit only if freeing them leaves the noise: white residuals of
  // the declared size (s² within 5σ of χ²'s scatter, √(2/n), above 1). A missing effect (a
  // thruster lag delays every start; a lost share of thrust one way) refutes the test too, and
  // free starts would soak part of it up and hide it from the model-error check and from
  // diagnose's likelihood ratios.
  const bool noise_left =
      refit.residual_lag1 <= o.whiteness_threshold &&
      refit.sigma2 <= 1.0 + 5.0 * std::sqrt(2.0 / std::max(refit.num_residuals, 1));
  if (refit.status == OutputErrorStatus::kConverged && noise_left) {
    refit.notes.push_back(refuted + ": every trial's initial velocity estimated");
    return refit;
  }
  res.notes.push_back(refuted + ", but the fit with them free does not explain the data either " +
                      "(its residuals are not white or it did not converge): they are kept at "
                      "rest, and a model error is the likelier cause");
  return res;
}

Eigen::MatrixXd CramerRaoBound(const model::DofModel& model,
                               const std::vector<const TrialData*>& trials,
                               const Eigen::VectorXd& theta,
                               const std::vector<ParameterState>& state,
                               const std::vector<TrialInitialState>& initial,
                               const OutputErrorOptions& o) {
  const int np = model.num_parameters();
  std::vector<int> free;
  for (int j = 0; j < np; ++j) {
    if (j >= static_cast<int>(state.size()) || state[j] == ParameterState::kEstimated)
      free.push_back(j);
  }
  const Problem p(model, trials, theta, free, initial.empty() ? nullptr : &initial, o);
  BlockLeastSquares J(p.num_free());
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(np, np);
  if (!p.Evaluate(p.InitialZ(), nullptr, &J)) return out;
  // The θ block of M⁻¹, M = JᵀJ the Fisher information with r scaled by 1/σ.
  for (std::size_t a = 0; a < free.size(); ++a) {
    const Eigen::VectorXd column = J.Solve(Eigen::VectorXd::Unit(p.num_z(), a), 0.0);
    for (std::size_t b = 0; b < free.size(); ++b) out(free[b], free[a]) = column[b];
  }
  return out;
}

Eigen::VectorXd FittedMovingStart(const OutputErrorResult& fit, int trial) {
  for (const TrialInitialState& s : fit.initial) {
    if (s.trial == trial && s.xi0_estimated) return Eigen::Vector2d(s.chi0, s.xi0);
  }
  return {};
}

}  // namespace uuvplan::ident
