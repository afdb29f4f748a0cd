// A least-squares problem whose unknowns are shared columns θ and, per block of rows, a few
// columns of the block's own (the output error: each trial's initial position and velocity).
// Its Jacobian is block-angular,
//
//       [ J_1  0   …  J_1θ ]            block t's rows touch only its own columns s_t and θ,
//   J = [ 0    J_2 …  J_2θ ],           so JᵀJ is a block arrow: A_tt = J_tᵀJ_t,
//       [ …            …   ]            A_tθ = J_tᵀJ_tθ, A_θθ = Σ_t J_tθᵀJ_tθ,
//
// and is never stored (memory grows with the trials, not trials × rows). Each block's
// rows [J_t, J_tθ, r_t] are folded into a triangular factor by Householder QR in chunks of
// kChunkRows rows; when the block ends, its first rows (its own columns: R_tt, R_tθ, q_t) are
// kept and the rest is folded into the shared factor R_θθ (Golub & Van Loan §6.3, block-angular
// least squares). So R is the factor Householder QR of the whole J would give (to rounding):
//
//   R = [ R_tt  R_tθ ]   per block, and R_θθ,   JᵀJ = RᵀR,   Jᵀr = Rᵀ(Qᵀr).
//
// Levenberg–Marquardt solves (A + λ·diag A)·δ = −g on the arrow by eliminating each block's own
// columns (Schur complement, docs/identification.md "Output error: the normal equations").
#pragma once

#include <Eigen/Dense>
#include <vector>

#include "uuvplan/ident/estimators/least_squares.h"

namespace uuvplan::ident {

/// Receives a block-angular problem's rows, block by block in order; each row is laid out as
/// [own columns, shared columns, residual].
class BlockRowSink {
 public:
  virtual ~BlockRowSink() = default;
  /// A block whose own columns are [first_own, first_own + own) of the unknowns.
  virtual void StartBlock(int first_own, int own) = 0;
  /// The buffer for the next row (own + shared + 1 numbers), taken by Commit().
  virtual double* Row() = 0;
  virtual void Commit() = 0;
  virtual void EndBlock() = 0;
  /// After the last block.
  virtual void Finish() {}
};

class BlockLeastSquares : public BlockRowSink {
 public:
  static constexpr int kChunkRows = 512;
  /// Unknowns: `shared` columns θ first (indices 0..shared−1), then the blocks' own.
  explicit BlockLeastSquares(int shared = 0);

  void StartBlock(int first_own, int own) override;
  double* Row() override { return chunk_.row(filled_).data(); }
  void Commit() override;
  void EndBlock() override;
  /// Builds the normal-equation blocks (below) from the factor.
  void Finish() override;

  struct Block {
    int first = 0, own = 0;
    Eigen::MatrixXd top;  ///< own × (own + shared + 1): [R_tt (upper), R_tθ, q_t]
  };
  int shared() const { return shared_; }
  int columns() const { return columns_; }
  const std::vector<Block>& blocks() const { return blocks_; }
  /// R_θθ (shared × shared, upper) after every block's own columns are eliminated.
  Eigen::MatrixXd SharedFactor() const { return shared_r_.topLeftCorner(shared_, shared_); }

  /// ‖column‖² of J (the diagonal of JᵀJ), and g = Jᵀr.
  const Eigen::VectorXd& Diagonal() const { return diagonal_; }
  const Eigen::VectorXd& Gradient() const { return gradient_; }
  /// x = (A + λ·diag A)⁻¹·b, A = JᵀJ, solved on the unit-diagonal scaling of A by eliminating
  /// each block's own columns; non-finite when a block or the Schur complement is singular.
  Eigen::VectorXd Solve(const Eigen::VectorXd& b, double lambda) const;
  /// The factor as a dense matrix (columns() rows and columns, unknowns' order): for analysis
  /// of small problems only.
  Eigen::MatrixXd DenseFactor() const;

 private:
  void Fold();
  void FoldShared(const Eigen::MatrixXd& rows);
  int shared_ = 0, columns_ = 0;
  Block open_;
  int filled_ = 0;
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> chunk_;
  Eigen::MatrixXd r_;         // the open block's factor
  Eigen::MatrixXd shared_r_;  // (shared + 1)², the last column Qᵀr
  std::vector<Block> blocks_;
  // Normal-equation blocks, built by Finish: A_tt and A_tθ per block, A_θθ.
  std::vector<Eigen::MatrixXd> own_a_, cross_a_;
  Eigen::MatrixXd shared_a_;
  Eigen::VectorXd diagonal_, gradient_;
};

/// What the factor says about the unknowns (least_squares.h's analysis of the column-scaled
/// factor): with at most kDenseColumns unknowns, of the whole R as one dense matrix (as a dense
/// QR of J would); beyond, of R_θθ after the blocks' own columns are eliminated, and of each
/// block's R_tt (a block's own columns that are not identifiable are reported by its first own
/// column), so no columns × columns matrix is formed (64: the dense SVD with U and V costs
/// ~c³, 17 ms at 204 unknowns, docs/identification.md).
struct BlockAnalysis {
  static constexpr int kDenseColumns = 64;
  bool dense = true;
  double condition_number = 0.0;
  std::vector<int> not_identifiable;  ///< unknowns' indices
  /// (JᵀJ)⁺ on the column scaling: all unknowns (dense), else the shared θ block only.
  Eigen::MatrixXd unit_covariance;
};
BlockAnalysis AnalyseBlocks(const BlockLeastSquares& ls, const LeastSquaresOptions& options);

/// The map from a block's local columns [own, θ] to the θ part of (JᵀJ)⁻¹·g for a g that lives
/// in those columns: K_t = C_θθ·[−R_tθᵀR_tt⁻ᵀ, I] (C_θθ the θ block of (JᵀJ)⁻¹).
Eigen::MatrixXd SharedResponse(const BlockLeastSquares::Block& b, const Eigen::MatrixXd& c_shared,
                               int shared);

}  // namespace uuvplan::ident
