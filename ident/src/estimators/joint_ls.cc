#include "uuvplan/ident/estimators/joint_ls.h"

#include <algorithm>
#include <cmath>

#include "estimators/joint_rows.h"
#include "options_check.h"
#include "stats/model_selection.h"
#include "uuvplan/ident/estimators/least_squares.h"
#include "uuvplan/ident/stats/significance.h"
#include "uuvplan/ident/stats/sub_matrix.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {
namespace {

using internal::JointRows;
using internal::JointTrialData;

// 1/σ² of each equation's rows from residuals r (or, before any fit, from y: its scale).
Eigen::VectorXd EquationWeights(const JointRows& rows, const Eigen::VectorXd& r, int equations) {
  Eigen::VectorXd sum = Eigen::VectorXd::Zero(equations);
  Eigen::VectorXd count = Eigen::VectorXd::Zero(equations);
  for (Eigen::Index k = 0; k < r.size(); ++k) {
    sum[rows.equation[k]] += r[k] * r[k];
    count[rows.equation[k]] += 1;
  }
  Eigen::VectorXd w(r.size());
  for (Eigen::Index k = 0; k < r.size(); ++k) {
    const int i = rows.equation[k];
    w[k] = sum[i] > 0 ? count[i] / sum[i] : 1.0;
  }
  return w;
}

// θ = (ZᵀWH)⁻¹ZᵀWy with the columns scaled to unit norm (units do not matter).
Eigen::VectorXd InstrumentalSolve(const Eigen::MatrixXd& H, const Eigen::MatrixXd& Z,
                                  const Eigen::VectorXd& y, const Eigen::VectorXd& w) {
  const Eigen::VectorXd scale = H.colwise().norm().cwiseMax(1e-300).cwiseInverse().transpose();
  const Eigen::MatrixXd Hs = H * scale.asDiagonal();
  const Eigen::MatrixXd A = Z.transpose() * w.asDiagonal() * Hs;
  const Eigen::VectorXd b = Z.transpose() * w.asDiagonal() * y;
  return scale.asDiagonal() * A.colPivHouseholderQr().solve(b);
}

// θ of all np parameters from the estimate of `cols` (the dropped ones 0).
Eigen::VectorXd Expand(const Eigen::VectorXd& x, const std::vector<int>& cols, int np) {
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(np);
  for (std::size_t c = 0; c < cols.size(); ++c) theta[cols[c]] = x[static_cast<Eigen::Index>(c)];
  return theta;
}

Eigen::MatrixXd Expand(const Eigen::MatrixXd& x, const std::vector<int>& cols, int np) {
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(np, np);
  for (std::size_t a = 0; a < cols.size(); ++a) {
    for (std::size_t b = 0; b < cols.size(); ++b) {
      cov(cols[a], cols[b]) = x(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
    }
  }
  return cov;
}

struct Fit {
  const model::MultiDofModel* model = nullptr;
  std::vector<int> cols;     // the parameters in the model
  Eigen::VectorXd theta, w;  // θ of all parameters (dropped ones 0)
  JointRows rows;            // along the measured velocities
  Eigen::MatrixXd Z;         // instruments (= H without them)
  int np() const { return model->num_parameters(); }
};

// The weighted least squares, twice (the second with weights from the first's residuals).
LinearFit LeastSquares(Fit* fit) {
  const JointRows& rows = fit->rows;
  const int equations = fit->model->num_dofs();
  fit->w = EquationWeights(rows, rows.y, equations);
  LinearFit lf;
  for (int pass = 0; pass < 2; ++pass) {
    LeastSquaresOptions ls;
    ls.covariance = CovarianceKind::kResidual;
    lf = SolveLeastSquares(SelectedColumns(rows.H, fit->cols), rows.y, &fit->w, ls);
    if (!lf.ok()) return lf;
    fit->w = EquationWeights(rows, lf.residuals, equations);
  }
  fit->theta = Expand(lf.theta, fit->cols, fit->np());
  fit->Z = rows.H;
  return lf;
}

// Instrumental-variable iterations (joint_ls.h step 2); stops with a note when a simulation
// cannot serve (a non-physical estimate).
void Instrumental(const std::vector<JointTrialData>& trials, const JointLsOptions& options,
                  Fit* fit, JointLsResult* result) {
  for (int it = 0; it < options.iv_iterations; ++it) {
    if (const std::string why = fit->model->Inadmissible(fit->theta); !why.empty()) {
      result->notes.push_back("instrumental variables skipped: the estimate to simulate has " +
                              why);
      return;
    }
    std::vector<Eigen::MatrixXd> simulated;
    for (const JointTrialData& d : trials) {
      simulated.push_back(
          internal::SimulatedVelocities(d, *fit->model, fit->theta, options.step_s));
    }
    const Eigen::MatrixXd Z = internal::BuildJointRows(*fit->model, trials, simulated).H;
    const Eigen::VectorXd theta =
        Expand(InstrumentalSolve(SelectedColumns(fit->rows.H, fit->cols),
                                 SelectedColumns(Z, fit->cols), fit->rows.y, fit->w),
               fit->cols, fit->np());
    if (!Z.allFinite() || !theta.allFinite()) {
      result->notes.push_back(
          "instrumental variables skipped: the current estimate's simulation or the "
          "instrumental solve is not finite (least-squares estimate kept)");
      return;
    }
    fit->Z = Z;
    fit->theta = theta;
    fit->w =
        EquationWeights(fit->rows, fit->rows.y - fit->rows.H * fit->theta, fit->model->num_dofs());
    result->instrumental = true;
  }
}

// The DOFs whose equation has no thrust in any row ("sway", "surge and yaw"), or "".
std::string UnpushedDofs(const model::MultiDofModel& model, const JointRows& rows) {
  std::vector<bool> pushed(model.num_dofs(), false);
  for (Eigen::Index k = 0; k < rows.y.size(); ++k) {
    pushed[rows.equation[k]] = pushed[rows.equation[k]] || rows.y[k] != 0.0;
  }
  std::vector<std::string> names;
  for (int i = 0; i < model.num_dofs(); ++i) {
    if (!pushed[i]) names.emplace_back(model::DofName(model.dof(i)));
  }
  return model::Join(names, " and ");
}

// Ref 000 §IV-D on each DOF's equation, where the fit is non-physical: the negative drag term
// with the largest percentile error above 51.02% over the DOFs (never a DOF's last drag term),
// as its θ index; -1 when no drag term is both negative and insignificant. Terms that are
// physical stay: dropping one of two collinear terms moves the other by many of its σ (yaw k,
// kq and bias under a spin that keeps one sign), a model-selection error σ does not carry.
int NegativeInsignificantDrag(const model::MultiDofModel& model, const JointLsResult& r,
                              const std::vector<int>& cols) {
  static const std::vector<std::string> kDrag = {model::param::kLinearDrag,
                                                 model::param::kQuadraticDrag};
  int worst = -1;
  double worst_pe = 0.0;
  for (int i = 0; i < model.num_dofs(); ++i) {
    std::vector<int> index;
    std::vector<PruneCandidate> candidates;  // naming kDrag's strings
    std::vector<std::string> negative;
    for (int j : cols) {
      const auto [dof, local] = model.LocalName(j);
      const auto drag = std::find(kDrag.begin(), kDrag.end(), local);
      if (dof != model.dof(i) || drag == kDrag.end()) continue;
      index.push_back(j);
      candidates.push_back({*drag, r.theta[j], r.Sigma(j)});
      if (r.theta[j] < 0) negative.push_back(*drag);
    }
    double pe = 0.0;
    const int c = WorstInsignificant(candidates, negative, kSeedDropCorrelation, &pe);
    if (c >= 0 && pe > worst_pe) {
      worst_pe = pe;
      worst = index[c];
    }
  }
  return worst;
}

// Steps 1–3 (joint_ls.h) on the prepared trials; false with the status set when a fit fails.
bool FitAndPrune(const std::vector<JointTrialData>& data, const JointLsOptions& options, Fit* fit,
                 JointLsResult* result) {
  for (;;) {
    result->notes.clear();
    result->instrumental = false;
    const LinearFit lf = LeastSquares(fit);
    result->condition_number = lf.condition_number;
    if (!lf.ok()) {
      result->status = lf.status == FitStatus::kTooFewData ? JointLsStatus::kTooFewData
                                                           : JointLsStatus::kIllConditioned;
      result->message = lf.message;
      return false;
    }
    Instrumental(data, options, fit, result);
    result->theta = fit->theta;
    // The MA(1) sandwich of the √W-scaled rows (joint_ls.h).
    const Eigen::VectorXd sw = fit->w.cwiseSqrt();
    const Eigen::VectorXd r = fit->rows.y - fit->rows.H * fit->theta;
    const Eigen::MatrixXd H = sw.asDiagonal() * SelectedColumns(fit->rows.H, fit->cols);
    const Eigen::MatrixXd Z = sw.asDiagonal() * SelectedColumns(fit->Z, fit->cols);
    result->covariance =
        Expand(Ma1Covariance(H, Z, sw.cwiseProduct(r), fit->rows.group), fit->cols, fit->np());
    const int drop =
        options.prune ? NegativeInsignificantDrag(*fit->model, *result, fit->cols) : -1;
    if (drop < 0) return true;
    result->dropped.push_back({drop, result->theta[drop], result->Sigma(drop)});
    fit->cols.erase(std::find(fit->cols.begin(), fit->cols.end(), drop));
    fit->theta[drop] = 0.0;
  }
}

}  // namespace

bool JointLsOptions::IsValid(std::string* error) const {
  return Require(sg_order >= 1 && sg_order <= 8, "JointLsOptions::sg_order: 1..8", error) &&
         Require(sg_window == 0 || (sg_window >= sg_order + 2 && sg_window % 2 == 1),
                 "JointLsOptions::sg_window: 0 or odd and >= sg_order + 2", error) &&
         Require(iv_iterations >= 0 && iv_iterations <= 20, "JointLsOptions::iv_iterations: 0..20",
                 error) &&
         Require(step_s > 0 && step_s <= 1, "JointLsOptions::step_s: in (0, 1] s", error);
}

JointLsResult JointOneStepLeastSquares(const model::MultiDofModel& model,
                                       const std::vector<const model::TrialLog*>& trials,
                                       const JointLsOptions& options) {
  JointLsResult result;
  result.names = model.parameter_names();
  for (int j = 0; j < model.num_parameters(); ++j) result.units.push_back(model.ParameterUnit(j));
  if (!options.IsValid(&result.message)) return result;
  std::vector<JointTrialData> data(trials.size());
  std::vector<Eigen::MatrixXd> measured;
  for (std::size_t c = 0; c < trials.size(); ++c) {
    result.message =
        internal::PrepareJointTrial(*trials[c], static_cast<int>(c), model, options, &data[c]);
    if (!result.message.empty()) return result;
    measured.push_back(internal::MeasuredVelocities(data[c]));
  }
  if (trials.empty()) {
    result.message = "no combined-mode trial";
    return result;
  }
  Fit fit;
  fit.model = &model;
  fit.rows = internal::BuildJointRows(model, data, measured);
  result.num_rows = static_cast<int>(fit.rows.y.size());
  if (const std::string unpushed = UnpushedDofs(model, fit.rows);
      fit.rows.y.size() > 0 && !unpushed.empty()) {
    result.status = JointLsStatus::kTooFewData;
    result.message = "no fit trial pushes " + unpushed +
                     " (its force is 0 throughout): an equation without thrust fixes none of its "
                     "terms' scale, and the joint model needs every one of its DOFs pushed — a "
                     "trial that moves them all, or combined modes that together do";
    return result;
  }
  for (int j = 0; j < model.num_parameters(); ++j) fit.cols.push_back(j);
  if (!FitAndPrune(data, options, &fit, &result)) return result;
  if (!result.theta.allFinite() || !result.covariance.allFinite()) {
    result.status = JointLsStatus::kIllConditioned;
    result.message = "the joint fit is not finite: the trials do not determine the model";
    return result;
  }
  if (const std::string why = model.Inadmissible(fit.theta); !why.empty()) {
    result.status = JointLsStatus::kNonPhysical;
    result.message = "the joint fit is non-physical: " + why;
    return result;
  }
  result.status = JointLsStatus::kOk;
  return result;
}

}  // namespace uuvplan::ident
