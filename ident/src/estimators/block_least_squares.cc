#include "uuvplan/ident/estimators/block_least_squares.h"

#include <cmath>

namespace uuvplan::ident {

BlockLeastSquares::BlockLeastSquares(int shared)
    : shared_(shared), columns_(shared), shared_r_(Eigen::MatrixXd::Zero(shared + 1, shared + 1)) {}

void BlockLeastSquares::StartBlock(int first_own, int own) {
  open_ = Block{first_own, own, {}};
  const int w1 = own + shared_ + 1;
  if (chunk_.cols() != w1) chunk_.resize(kChunkRows, w1);
  r_.setZero(w1, w1);
  filled_ = 0;
}

void BlockLeastSquares::Commit() {
  if (++filled_ == kChunkRows) Fold();
}

// R ← the triangular factor of [R; the chunk's rows] (Householder, in place).
void BlockLeastSquares::Fold() {
  if (filled_ == 0) return;
  const Eigen::Index w1 = r_.cols();
  Eigen::MatrixXd stack(w1 + filled_, w1);
  stack.topRows(w1) = r_;
  stack.bottomRows(filled_) = chunk_.topRows(filled_);
  Eigen::HouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr(stack);
  r_ = stack.topRows(w1).triangularView<Eigen::Upper>();
  filled_ = 0;
}

void BlockLeastSquares::FoldShared(const Eigen::MatrixXd& rows) {
  const Eigen::Index w1 = shared_r_.cols();
  Eigen::MatrixXd stack(w1 + rows.rows(), w1);
  stack << shared_r_, rows;
  Eigen::HouseholderQR<Eigen::Ref<Eigen::MatrixXd>> qr(stack);
  shared_r_ = stack.topRows(w1).triangularView<Eigen::Upper>();
}

void BlockLeastSquares::EndBlock() {
  Fold();
  const int own = open_.own, rest = static_cast<int>(r_.cols()) - own;
  if (own > 0) open_.top = r_.topRows(own);
  FoldShared(r_.bottomRightCorner(rest, rest));
  columns_ += own;
  blocks_.push_back(std::move(open_));
}

// A = RᵀR and g = Rᵀ(Qᵀr), block by block.
void BlockLeastSquares::Finish() {
  const int s = shared_;
  const Eigen::MatrixXd r_ss = shared_r_.topLeftCorner(s, s);
  shared_a_ = r_ss.transpose() * r_ss;
  diagonal_.setZero(columns_);
  gradient_.setZero(columns_);
  gradient_.head(s) = r_ss.transpose() * shared_r_.col(s).head(s);
  own_a_.clear();
  cross_a_.clear();
  for (const Block& b : blocks_) {
    if (b.own == 0) {
      own_a_.emplace_back();
      cross_a_.emplace_back();
      continue;
    }
    const Eigen::MatrixXd r_tt = b.top.leftCols(b.own);
    const Eigen::MatrixXd r_ts = b.top.middleCols(b.own, s);
    const Eigen::VectorXd q_t = b.top.col(b.own + s);
    own_a_.push_back(r_tt.transpose() * r_tt);
    cross_a_.push_back(r_tt.transpose() * r_ts);
    shared_a_.noalias() += r_ts.transpose() * r_ts;
    gradient_.head(s).noalias() += r_ts.transpose() * q_t;
    gradient_.segment(b.first, b.own) = r_tt.transpose() * q_t;
    diagonal_.segment(b.first, b.own) = own_a_.back().diagonal();
  }
  diagonal_.head(s) = shared_a_.diagonal();
}

// D = diag(A)^(−1/2): (A + λ·diag A)x = b ⇔ (DAD + λI)y = Db, x = Dy. Per block t, with
// M_tt = D_tA_ttD_t + λI and M_tθ = D_tA_tθD_θ, the Schur complement
//   S = M_θθ − Σ_t M_tθᵀ M_tt⁻¹ M_tθ,   S·y_θ = D_θb_θ − Σ_t M_tθᵀ M_tt⁻¹ D_tb_t,
//   y_t = M_tt⁻¹ (D_tb_t − M_tθ y_θ).
Eigen::VectorXd BlockLeastSquares::Solve(const Eigen::VectorXd& b, double lambda) const {
  const int s = shared_;
  const Eigen::VectorXd d = diagonal_.cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
  const Eigen::VectorXd d_s = d.head(s);
  Eigen::MatrixXd schur = d_s.asDiagonal() * shared_a_ * d_s.asDiagonal();
  schur.diagonal().array() += lambda;
  Eigen::VectorXd rhs = d_s.cwiseProduct(b.head(s));
  auto own_system = [&](std::size_t t, Eigen::MatrixXd* m_ts, Eigen::VectorXd* b_t) {
    const Block& blk = blocks_[t];
    const Eigen::VectorXd d_t = d.segment(blk.first, blk.own);
    Eigen::MatrixXd m_tt = d_t.asDiagonal() * own_a_[t] * d_t.asDiagonal();
    m_tt.diagonal().array() += lambda;
    *m_ts = d_t.asDiagonal() * cross_a_[t] * d_s.asDiagonal();
    *b_t = d_t.cwiseProduct(b.segment(blk.first, blk.own));
    return Eigen::LDLT<Eigen::MatrixXd>(m_tt);
  };
  Eigen::MatrixXd m_ts;
  Eigen::VectorXd b_t;
  for (std::size_t t = 0; t < blocks_.size(); ++t) {
    if (blocks_[t].own == 0) continue;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt = own_system(t, &m_ts, &b_t);
    schur.noalias() -= m_ts.transpose() * ldlt.solve(m_ts);
    rhs.noalias() -= m_ts.transpose() * ldlt.solve(b_t);
  }
  Eigen::VectorXd x(columns_);
  const Eigen::VectorXd y_s = schur.ldlt().solve(rhs);
  x.head(s) = d_s.cwiseProduct(y_s);
  for (std::size_t t = 0; t < blocks_.size(); ++t) {
    const Block& blk = blocks_[t];
    if (blk.own == 0) continue;
    const Eigen::LDLT<Eigen::MatrixXd> ldlt = own_system(t, &m_ts, &b_t);
    x.segment(blk.first, blk.own) =
        d.segment(blk.first, blk.own).cwiseProduct(ldlt.solve(b_t - m_ts * y_s));
  }
  return x;
}

Eigen::MatrixXd BlockLeastSquares::DenseFactor() const {
  const int s = shared_;
  Eigen::MatrixXd R = Eigen::MatrixXd::Zero(columns_, columns_);
  int row = 0;
  for (const Block& b : blocks_) {
    if (b.own == 0) continue;
    R.block(row, b.first, b.own, b.own) = b.top.leftCols(b.own);
    R.block(row, 0, b.own, s) = b.top.middleCols(b.own, s);
    row += b.own;
  }
  R.block(row, 0, s, s) = shared_r_.topLeftCorner(s, s);
  return R;
}

BlockAnalysis AnalyseBlocks(const BlockLeastSquares& ls, const LeastSquaresOptions& options) {
  BlockAnalysis a;
  const Eigen::VectorXd& diag = ls.Diagonal();
  Eigen::VectorXd D(diag.size());  // column scaling 1/‖column‖, as SolveLeastSquares
  for (Eigen::Index j = 0; j < diag.size(); ++j)
    D[j] = diag[j] > 0 ? 1.0 / std::sqrt(diag[j]) : 1.0;
  a.dense = ls.columns() <= BlockAnalysis::kDenseColumns;
  const int s = a.dense ? ls.columns() : ls.shared();
  const Eigen::MatrixXd R = a.dense ? ls.DenseFactor() : ls.SharedFactor();
  const ScaledFactor f = AnalyseScaledFactor(R * D.head(s).asDiagonal(), options);
  a.condition_number = f.condition_number;
  a.not_identifiable = f.not_identifiable;
  a.unit_covariance = D.head(s).asDiagonal() * (f.pseudo_inverse * f.pseudo_inverse.transpose()) *
                      D.head(s).asDiagonal();
  if (a.dense) return a;
  for (const BlockLeastSquares::Block& b : ls.blocks()) {
    if (b.own == 0) continue;
    const Eigen::MatrixXd r_tt = b.top.leftCols(b.own) * D.segment(b.first, b.own).asDiagonal();
    const ScaledFactor ft = AnalyseScaledFactor(r_tt, options);
    a.condition_number = std::max(a.condition_number, ft.condition_number);
    if (!ft.not_identifiable.empty()) a.not_identifiable.push_back(b.first);
  }
  return a;
}

Eigen::MatrixXd SharedResponse(const BlockLeastSquares::Block& b, const Eigen::MatrixXd& c_shared,
                               int shared) {
  Eigen::MatrixXd K(shared, b.own + shared);
  if (b.own > 0) {
    const Eigen::MatrixXd x = b.top.leftCols(b.own).triangularView<Eigen::Upper>().solve(
        b.top.middleCols(b.own, shared));  // R_tt⁻¹R_tθ
    K.leftCols(b.own) = -c_shared * x.transpose();
  }
  K.rightCols(shared) = c_shared;
  return K;
}

}  // namespace uuvplan::ident
