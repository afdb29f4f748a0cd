#include "uuvplan/ident/coupled_ls.h"

#include <cmath>

#include "coupled_rows.h"
#include "options_check.h"
#include "uuvplan/ident/least_squares.h"
#include "uuvplan/model/coupled_model.h"

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

model::CoupledHorizontalModel ModelOf(const Eigen::VectorXd& theta) {
  model::CoupledHorizontalModel m;
  m.theta = theta;
  return m;
}

struct Fit {
  Eigen::VectorXd theta, w;
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
    lf = SolveLeastSquares(rows.H, rows.y, &fit->w, ls);
    if (!lf.ok()) return lf;
    fit->w = EquationWeights(rows, lf.residuals);
  }
  fit->theta = lf.theta;
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
    fit->Z = internal::BuildCoupledRows(trials, simulated).H;
    fit->theta = InstrumentalSolve(fit->rows.H, fit->Z, fit->rows.y, fit->w);
    fit->w = EquationWeights(fit->rows, fit->rows.y - fit->rows.H * fit->theta);
    result->instrumental = true;
  }
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
  result.covariance = Ma1Covariance(sw.asDiagonal() * fit.rows.H, sw.asDiagonal() * fit.Z,
                                    sw.cwiseProduct(r), fit.rows.group);
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
