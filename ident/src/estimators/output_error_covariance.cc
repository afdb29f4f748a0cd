// The output error's covariance at its answer (output_error_covariance.h): white, or the
// AR(1)-prewhitened sandwich when the residuals are coloured.
#include "estimators/output_error_covariance.h"

#include <algorithm>
#include <cmath>
#include <optional>

#include "uuvplan/ident/estimators/least_squares.h"
#include "uuvplan/ident/stats/covariance.h"

namespace uuvplan::ident::internal {
namespace {

// Mean lag-1 autocorrelation of the residuals within each trial's position and velocity parts.
double ResidualLag1(const Problem& p, const Eigen::VectorXd& r) {
  double sum = 0.0;
  int count = 0;
  for (const TrialProblem& tp : p.trials()) {
    int off = tp.r_offset;
    for (std::size_t len : {tp.pos.size(), tp.vel.size()}) {
      if (len >= 10) {  // read in place (copies would take 16 bytes a measurement)
        const auto seg = r.segment(off, len);
        const double mean = seg.mean();
        double den = 0.0, num = 0.0;
        for (Eigen::Index i = 0; i < seg.size(); ++i) {
          const double c = seg[i] - mean;
          den += c * c;
          if (i > 0) num += (seg[i - 1] - mean) * c;
        }
        if (den > 0) {
          sum += num / den;
          ++count;
        }
      }
      off += static_cast<int>(len);
    }
  }
  return count > 0 ? sum / count : 0.0;
}

// The whitened score sums of the trials (covariance.h's WhitenedScoreSum over each trial's
// groups, in its local columns [own, θ]), fed by a second evaluation at the solution.
class TrialScoreSums : public BlockRowSink {
 public:
  TrialScoreSums(const Prewhitening& plan, int shared) : plan_(plan), shared_(shared) {}
  void StartBlock(int first_own, int own) override {
    sum_.emplace(own + shared_, plan_.block);
    row_.resize(own + shared_ + 1);
    blocks_.push_back({first_own, own, {}});
  }
  double* Row() override { return row_.data(); }
  void Commit() override {
    if (run_ < plan_.runs.size() && next_ == plan_.runs[run_].first)
      sum_->StartGroup(plan_.rho[run_++]);
    sum_->Add(row_.data(), row_.back());
    ++next_;
  }
  void EndBlock() override {
    blocks_.back().top = sum_->Sum();
    batches_ += sum_->batches();
  }
  /// Per trial: its first own column, own count and S_t (in `top`).
  const std::vector<BlockLeastSquares::Block>& sums() const { return blocks_; }
  int batches() const { return batches_; }

 private:
  const Prewhitening& plan_;
  int shared_;
  std::optional<WhitenedScoreSum> sum_;
  std::vector<double> row_;
  std::vector<BlockLeastSquares::Block> blocks_;
  std::size_t run_ = 0;
  int next_ = 0, batches_ = 0;
};

// Residuals correlated over the record (model error or coloured noise): the AR(1)-prewhitened
// sandwich of z (covariance.h; ρ per trial and sensor), each σ floored at its white-noise value
// (below). The scores are summed trial by trial (C·S·C = Σ_t C_t·S_t·C_tᵀ, S_t in the trial's
// columns); with the analysis' θ block only (many trials), C_t = SharedResponse.
Eigen::MatrixXd RobustCovariance(const Problem& p, const LmOutcome& lm, double sigma2,
                                 const BlockAnalysis& fa) {
  std::vector<int> groups(p.num_r());
  for (const TrialProblem& tp : p.trials()) {
    const int npos = static_cast<int>(tp.pos.size());
    for (int k = 0; k < tp.num_residuals(); ++k) {
      groups[tp.r_offset + k] = 2 * tp.trial->index + (k < npos ? 0 : 1);
    }
  }
  const Prewhitening plan = PlanPrewhitening(lm.r, groups);
  const int shared = p.num_free(), P = p.num_z();
  TrialScoreSums sums(plan, shared);
  if (!p.Evaluate(lm.z, nullptr, &sums)) return sigma2 * fa.unit_covariance;
  const double correction =
      sums.batches() > P ? double(sums.batches()) / (sums.batches() - P) : 1.0;
  const Eigen::MatrixXd& crb = fa.unit_covariance;
  Eigen::MatrixXd hac = Eigen::MatrixXd::Zero(crb.rows(), crb.cols());
  for (std::size_t t = 0; t < sums.sums().size(); ++t) {
    const BlockLeastSquares::Block& st = sums.sums()[t];
    Eigen::MatrixXd K(crb.rows(), st.own + shared);  // C_t: crb's columns [own, θ]
    if (fa.dense) {
      K << crb.middleCols(st.first, st.own), crb.leftCols(shared);
    } else {
      K = SharedResponse(lm.rows.blocks()[t], crb, shared);
    }
    hac.noalias() += K * st.top * K.transpose();
  }
  hac *= correction;
  // Each σ at least its white-noise value, the sandwich's correlations kept: D·HAC·D with
  // D_jj = max(1, √(s²·crb_jj / HAC_jj)). Replacing the whole matrix by the white one when any
  // entry (an initial state) falls below it would throw away the colour of every other entry
  // (the coverage figures are in docs/validation.md).
  Eigen::VectorXd d(hac.rows());
  for (int j = 0; j < hac.rows(); ++j) {
    if (!(hac(j, j) > 0)) return sigma2 * crb;  // a degenerate sandwich: the white matrix
    d[j] = std::max(1.0, std::sqrt(sigma2 * crb(j, j) / hac(j, j)));
  }
  return d.asDiagonal() * hac * d.asDiagonal();
}

}  // namespace

void StoreCovariance(const Problem& p, const LmOutcome& lm, const std::vector<int>& free,
                     const OutputErrorOptions& o, OutputErrorResult* res) {
  res->num_residuals = p.num_r() - p.num_excluded();
  res->cost = 0.5 * lm.r.squaredNorm();
  res->sigma2 = lm.r.squaredNorm() / (res->num_residuals - p.num_z());
  LeastSquaresOptions lso;
  lso.max_condition = o.max_condition;
  const BlockAnalysis fa = AnalyseBlocks(lm.rows, lso);
  res->condition_number = fa.condition_number;
  res->not_identifiable.clear();
  for (int c : fa.not_identifiable) {
    res->not_identifiable.push_back(c < static_cast<int>(free.size()) ? res->names[free[c]]
                                                                      : "initial state");
  }
  const Eigen::MatrixXd& crb_z = fa.unit_covariance;
  res->residual_lag1 = ResidualLag1(p, lm.r);
  res->hac_covariance = res->residual_lag1 > o.whiteness_threshold;
  const Eigen::MatrixXd cov_z =
      res->hac_covariance ? RobustCovariance(p, lm, res->sigma2, fa) : res->sigma2 * crb_z;
  res->covariance.setZero();
  res->crb.setZero();
  for (std::size_t a = 0; a < free.size(); ++a) {
    for (std::size_t b = 0; b < free.size(); ++b) {
      res->covariance(free[a], free[b]) = cov_z(a, b);
      res->crb(free[a], free[b]) = crb_z(a, b);
    }
  }
  const bool ill = fa.condition_number > o.max_condition || !fa.not_identifiable.empty();
  res->status = ill            ? OutputErrorStatus::kIllConditioned
                : lm.converged ? OutputErrorStatus::kConverged
                               : OutputErrorStatus::kMaxIterations;
  if (!lm.converged) res->notes.push_back(lm.message);
}

}  // namespace uuvplan::ident::internal
