// SubMatrix and SelectedColumns (ident/stats/sub_matrix.h): a parameter subset's part of a
// matrix, element for element in the order the indices are given.
#include "uuvplan/ident/stats/sub_matrix.h"

#include <gtest/gtest.h>

namespace uuvplan::ident {
namespace {

Eigen::MatrixXd Numbered(int rows, int cols) {
  Eigen::MatrixXd M(rows, cols);
  for (int i = 0; i < rows; ++i) {
    for (int j = 0; j < cols; ++j) M(i, j) = 10.0 * i + j;
  }
  return M;
}

TEST(SubMatrixTest, PicksTheRowsAndColumnsInTheOrderGiven) {
  const Eigen::MatrixXd M = Numbered(4, 4);
  const std::vector<int> rows = {3, 1}, cols = {0, 2, 1};
  const Eigen::MatrixXd S = SubMatrix(M, rows, cols);
  ASSERT_EQ(S.rows(), 2);
  ASSERT_EQ(S.cols(), 3);
  for (int a = 0; a < 2; ++a) {
    for (int b = 0; b < 3; ++b) EXPECT_EQ(S(a, b), M(rows[a], cols[b]));
  }
}

TEST(SubMatrixTest, PrincipalBlockAndEmptySubset) {
  const Eigen::MatrixXd M = Numbered(3, 3);
  const Eigen::MatrixXd S = SubMatrix(M, {2, 0});
  EXPECT_EQ(S, (Eigen::MatrixXd(2, 2) << 22, 20, 2, 0).finished());
  EXPECT_EQ(SubMatrix(M, {}).size(), 0);
}

TEST(SubMatrixTest, SelectedColumnsKeepEveryRow) {
  const Eigen::MatrixXd H = Numbered(5, 3);
  const Eigen::MatrixXd S = SelectedColumns(H, {2, 0});
  ASSERT_EQ(S.rows(), 5);
  ASSERT_EQ(S.cols(), 2);
  EXPECT_EQ(S.col(0), H.col(2));
  EXPECT_EQ(S.col(1), H.col(0));
}

}  // namespace
}  // namespace uuvplan::ident
