// A parameter subset's part of a matrix in the parameters' layout, in the order given: the
// block of an information or covariance matrix (a sub-information matrix, a sub-covariance),
// the columns of a regressor matrix.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace uuvplan::ident {

/// out(a, b) = M(rows[a], cols[b]): rows.size() × cols.size(), indices in M's layout.
inline Eigen::MatrixXd SubMatrix(const Eigen::MatrixXd& M, const std::vector<int>& rows,
                                 const std::vector<int>& cols) {
  return M(rows, cols);
}

/// The principal block out(a, b) = M(indices[a], indices[b]) of the parameters `indices`.
inline Eigen::MatrixXd SubMatrix(const Eigen::MatrixXd& M, const std::vector<int>& indices) {
  return SubMatrix(M, indices, indices);
}

/// The columns out.col(c) = M.col(cols[c]) of the parameters `cols` (a regressor's rows kept).
inline Eigen::MatrixXd SelectedColumns(const Eigen::MatrixXd& M, const std::vector<int>& cols) {
  return M(Eigen::all, cols);
}

}  // namespace uuvplan::ident
