#include "uuvplan/ident/estimators/coupled_ls.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "estimators/coupled_rows.h"
#include "stats/model_selection.h"
#include "options_check.h"
#include "uuvplan/ident/estimators/least_squares.h"
#include "uuvplan/ident/stats/significance.h"
#include "uuvplan/ident/stats/sub_matrix.h"
#include "uuvplan/model/coupled_model.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {
namespace {

using internal::CoupledRows;
using internal::CoupledTrialData;

// 1/σ² of each equation's rows from residuals r (or, before any fit, from y: its scale).
Eigen::VectorXd EquationWeights(const CoupledRows& rows, const Eigen::VectorXd& r) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  Eigen::Vector3d count = Eigen::Vector3d::Zero();
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

// θ of all 12 parameters from the estimate of `cols` (the dropped ones 0).
Eigen::VectorXd Expand(const Eigen::VectorXd& x, const std::vector<int>& cols) {
  Eigen::VectorXd theta = Eigen::VectorXd::Zero(model::kCoupledParameterCount);
  for (std::size_t c = 0; c < cols.size(); ++c) theta[cols[c]] = x[static_cast<Eigen::Index>(c)];
  return theta;
}

Eigen::MatrixXd Expand(const Eigen::MatrixXd& x, const std::vector<int>& cols) {
  Eigen::MatrixXd cov = Eigen::MatrixXd::Zero(model::kCoupledParameterCount, model::kCoupledParameterCount);
  for (std::size_t a = 0; a < cols.size(); ++a) {
    for (std::size_t b = 0; b < cols.size(); ++b) {
      cov(cols[a], cols[b]) = x(static_cast<Eigen::Index>(a), static_cast<Eigen::Index>(b));
    }
  }
  return cov;
}

model::CoupledHorizontalModel ModelOf(const Eigen::VectorXd& theta) {
  model::CoupledHorizontalModel m;
  m.theta = theta;
  return m;
}

struct Fit {
  std::vector<int> cols;                              // the parameters in the model
  Eigen::VectorXd theta, w;                           // θ of all 12 (dropped ones 0)
  CoupledRows rows;                                   // along the measured velocities
  Eigen::MatrixXd Z;                                  // instruments (= H without them)
};

// The weighted least squares, twice (the second with weights from the first's residuals).
LinearFit LeastSquares(Fit* fit) {
  const CoupledRows& rows = fit->rows;
  fit->w = EquationWeights(rows, rows.y);
  LinearFit lf;
  for (int pass = 0; pass < 2; ++pass) {
    LeastSquaresOptions ls;
    ls.covariance = CovarianceKind::kResidual;
    lf = SolveLeastSquares(SelectedColumns(rows.H, fit->cols), rows.y, &fit->w, ls);
    if (!lf.ok()) return lf;
    fit->w = EquationWeights(rows, lf.residuals);
  }
  fit->theta = Expand(lf.theta, fit->cols);
  fit->Z = rows.H;
  return lf;
}

// Instrumental-variable iterations (coupled_ls.h step 2); false with a note when a simulation
// cannot serve (a non-physical estimate).
void Instrumental(const std::vector<CoupledTrialData>& trials, const CoupledLsOptions& options,
                  Fit* fit, CoupledLsResult* result) {
  for (int it = 0; it < options.iv_iterations; ++it) {
    std::string why;
    const model::CoupledHorizontalModel current = ModelOf(fit->theta);
    if (!current.Admissible(&why)) {
      result->notes.push_back("instrumental variables skipped: the estimate to simulate has " +
                              why);
      return;
    }
    std::vector<std::vector<model::Horizontal>> simulated;
    for (const CoupledTrialData& d : trials) {
      simulated.push_back(internal::SimulatedVelocities(d, current, options.step_s));
    }
    const Eigen::MatrixXd Z = internal::BuildCoupledRows(trials, simulated).H;
    const Eigen::VectorXd theta =
        Expand(InstrumentalSolve(SelectedColumns(fit->rows.H, fit->cols),
                                 SelectedColumns(Z, fit->cols), fit->rows.y, fit->w),
               fit->cols);
    if (!Z.allFinite() || !theta.allFinite()) {
      result->notes.push_back(
          "instrumental variables skipped: the current estimate's simulation or the "
          "instrumental solve is not finite (least-squares estimate kept)");
      return;
    }
    fit->Z = Z;
    fit->theta = theta;
    fit->w = EquationWeights(fit->rows, fit->rows.y - fit->rows.H * fit->theta);
    result->instrumental = true;
  }
}

// The horizontal DOFs whose equation has no thrust in any row ("sway", "surge and yaw"), or "".
std::string UnpushedDofs(const CoupledRows& rows) {
  std::array<bool, 3> pushed = {false, false, false};
  for (Eigen::Index k = 0; k < rows.y.size(); ++k) {
    pushed[rows.equation[k]] = pushed[rows.equation[k]] || rows.y[k] != 0.0;
  }
  std::vector<std::string> names;
  for (int i = 0; i < 3; ++i) {
    if (!pushed[i]) names.emplace_back(model::DofName(model::kHorizontalDofs[i]));
  }
  return model::Join(names, " and ");
}

// Seed 000 §IV-D on each DOF's equation, where the fit is non-physical: the negative drag term
// with the largest percentile error above 51.02% over the three DOFs (never a DOF's last drag
// term), as its θ index; -1 when no drag term is both negative and insignificant. Terms that
// are physical stay: dropping one of two collinear terms moves the other by many of its σ
// (yaw k, kq and bias under a spin that keeps one sign), a model-selection error σ does not
// carry.
int NegativeInsignificantDrag(const CoupledLsResult& r, const std::vector<int>& cols) {
  static const std::vector<std::string> kDrag = {"k", "kq"};
  int worst = -1;
  double worst_pe = 0.0;
  for (int i = 0; i < 3; ++i) {
    std::vector<int> index;
    std::vector<PruneCandidate> candidates;
    for (const std::string& name : kDrag) {
      const int j = model::CoupledIndex(i, name.c_str());
      if (std::find(cols.begin(), cols.end(), j) == cols.end()) continue;
      index.push_back(j);
      candidates.push_back({name, r.theta[j], r.Sigma(j)});
    }
    std::vector<std::string> negative;
    for (const PruneCandidate& c : candidates) {
      if (c.value < 0) negative.push_back(c.name);
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

}  // namespace

bool CoupledLsOptions::IsValid(std::string* error) const {
  return Require(sg_order >= 1 && sg_order <= 8, "CoupledLsOptions::sg_order: 1..8", error) &&
         Require(sg_window == 0 || (sg_window >= sg_order + 2 && sg_window % 2 == 1),
                 "CoupledLsOptions::sg_window: 0 or odd and >= sg_order + 2", error) &&
         Require(iv_iterations >= 0 && iv_iterations <= 20,
                 "CoupledLsOptions::iv_iterations: 0..20", error) &&
         Require(step_s > 0 && step_s <= 1, "CoupledLsOptions::step_s: in (0, 1] s", error);
}

CoupledLsResult CoupledOneStepLeastSquares(const std::vector<const model::TrialLog*>& trials,
                                           const CoupledLsOptions& options) {
  CoupledLsResult result;
  result.names = model::CoupledParameterNames();
  for (int j = 0; j < model::kCoupledParameterCount; ++j) {
    result.units.push_back(model::CoupledParameterUnit(j));
  }
  if (!options.IsValid(&result.message)) return result;
  std::vector<CoupledTrialData> data(trials.size());
  std::vector<std::vector<model::Horizontal>> measured;
  for (std::size_t c = 0; c < trials.size(); ++c) {
    result.message = internal::PrepareCoupledTrial(*trials[c], static_cast<int>(c), options,
                                                   &data[c]);
    if (!result.message.empty()) return result;
    measured.push_back(internal::MeasuredVelocities(data[c]));
  }
  if (trials.empty()) {
    result.message = "no combined-mode trial";
    return result;
  }
  Fit fit;
  fit.rows = internal::BuildCoupledRows(data, measured);
  result.num_rows = static_cast<int>(fit.rows.y.size());
  if (const std::string unpushed = UnpushedDofs(fit.rows); fit.rows.y.size() > 0 && !unpushed.empty()) {
    result.status = CoupledStatus::kTooFewData;
    result.message = "no fit trial pushes " + unpushed +
                     " (its force is 0 throughout): an equation without thrust fixes none of its "
                     "terms' scale, and seed 003's coupled model needs every horizontal DOF "
                     "pushed — a surge+sway+yaw trial, or the surge+yaw and sway+yaw modes together";
    return result;
  }
  for (int j = 0; j < model::kCoupledParameterCount; ++j) fit.cols.push_back(j);
  for (;;) {
    result.notes.clear();
    result.instrumental = false;
    const LinearFit lf = LeastSquares(&fit);
    result.condition_number = lf.condition_number;
    if (!lf.ok()) {
      result.status = lf.status == FitStatus::kTooFewData ? CoupledStatus::kTooFewData
                                                          : CoupledStatus::kIllConditioned;
      result.message = lf.message;
      return result;
    }
    Instrumental(data, options, &fit, &result);
    result.theta = fit.theta;
    // The MA(1) sandwich of the √W-scaled rows (coupled_ls.h).
    const Eigen::VectorXd sw = fit.w.cwiseSqrt();
    const Eigen::VectorXd r = fit.rows.y - fit.rows.H * fit.theta;
    const Eigen::MatrixXd H = sw.asDiagonal() * SelectedColumns(fit.rows.H, fit.cols);
    const Eigen::MatrixXd Z = sw.asDiagonal() * SelectedColumns(fit.Z, fit.cols);
    result.covariance = Expand(Ma1Covariance(H, Z, sw.cwiseProduct(r), fit.rows.group), fit.cols);
    const int drop = options.prune ? NegativeInsignificantDrag(result, fit.cols) : -1;
    if (drop < 0) break;
    result.dropped.push_back({drop, result.theta[drop], result.Sigma(drop)});
    fit.cols.erase(std::find(fit.cols.begin(), fit.cols.end(), drop));
    fit.theta[drop] = 0.0;
  }
  if (!result.theta.allFinite() || !result.covariance.allFinite()) {
    result.status = CoupledStatus::kIllConditioned;
    result.message = "the coupled fit is not finite: the trials do not determine the model";
    return result;
  }
  std::string why;
  if (!ModelOf(fit.theta).Admissible(&why)) {
    result.status = CoupledStatus::kNonPhysical;
    result.message = "the coupled fit is non-physical: " + why;
    return result;
  }
  result.status = CoupledStatus::kOk;
  return result;
}

}  // namespace uuvplan::ident
