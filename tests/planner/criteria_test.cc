// Design criteria against hand computations on small information matrices.
#include "uuvplan/planner/design/criteria.h"

#include <gtest/gtest.h>

#include <cmath>

namespace uuvplan::planner {
namespace {

constexpr double kRoundingTol = 1e-12;  // closed forms on 2×2 / 3×3 matrices: rounding only

TEST(Criteria, DOnADiagonalMatrixIsTheSumOfLogs) {
  Eigen::MatrixXd M = Eigen::Vector3d(4.0, 9.0, 25.0).asDiagonal();
  EXPECT_NEAR(EvaluateCriterion(M, Criterion::kD, {}).value, std::log(4.0 * 9.0 * 25.0),
              kRoundingTol);
  // A: -log(1/4 + 1/9 + 1/25); E: log 4.
  EXPECT_NEAR(EvaluateCriterion(M, Criterion::kA, {}).value,
              -std::log(1 / 4.0 + 1 / 9.0 + 1 / 25.0), kRoundingTol);
  EXPECT_NEAR(EvaluateCriterion(M, Criterion::kE, {}).value, std::log(4.0), kRoundingTol);
}

TEST(Criteria, DsMarginalisesTheNuisance) {
  // M = [[a, b], [b, c]]: information on θ_0 with θ_1 unknown is a - b²/c (Schur complement),
  // i.e. 1/(M⁻¹)_00. Here 4 - 1·1/2 = 3.5.
  Eigen::Matrix2d M;
  M << 4.0, 1.0, 1.0, 2.0;
  const CriterionValue v = EvaluateCriterion(M, Criterion::kDs, {0});
  EXPECT_NEAR(v.value, std::log(3.5), kRoundingTol);
  EXPECT_FALSE(v.singular);
  EXPECT_NEAR(std::exp(v.value), 1.0 / M.inverse()(0, 0), kRoundingTol);
}

TEST(Criteria, UninformedParametersAreDroppedAndFlagged) {
  // θ_2 has no information (a direction the trial never uses): D is that of the 2×2 block.
  Eigen::Matrix3d M = Eigen::Matrix3d::Zero();
  M.topLeftCorner<2, 2>() << 4.0, 1.0, 1.0, 2.0;
  EXPECT_NEAR(EvaluateCriterion(M, Criterion::kD, {}).value, std::log(7.0), kRoundingTol);
  EXPECT_EQ(InformedParameters(M), (std::vector<int>{0, 1}));
  // Asking for θ_2 as interest floors the value and says so.
  const CriterionValue v = EvaluateCriterion(M, Criterion::kDs, {2});
  EXPECT_TRUE(v.singular);
  EXPECT_EQ(v.uninformed_interest, std::vector<int>{2});
  EXPECT_NEAR(v.value, std::log(kSingularFloor), 1e-9);
}

TEST(Criteria, ConfoundedParametersAreSingular) {
  // Two parameters with proportional sensitivities (m and eta scaled together): rank 1.
  Eigen::Vector2d s(1.0, -2.0);
  const Eigen::Matrix2d M = 100.0 * s * s.transpose();
  EXPECT_TRUE(EvaluateCriterion(M, Criterion::kD, {}).singular);
  const Eigen::VectorXd sigma = PredictedSigma(M, Eigen::Vector2d(1.0, 1.0));
  EXPECT_TRUE(std::isinf(sigma[0]));
  EXPECT_TRUE(std::isinf(sigma[1]));
}

TEST(Criteria, RelativeInformationGivesPercentileErrors) {
  // σ_m = 5 kg on m = 500 kg is 1%: M_rel(0,0) = 1/0.01² = 1e4. A zero parameter keeps its
  // absolute scale.
  Eigen::Matrix2d M = Eigen::Vector2d(1.0 / 25.0, 4.0).asDiagonal();
  const Eigen::Vector2d theta(500.0, 0.0);
  const Eigen::MatrixXd R = RelativeInformation(M, theta);
  EXPECT_NEAR(R(0, 0), 1e4, 1e-8);
  EXPECT_NEAR(R(1, 1), 4.0, kRoundingTol);
  const Eigen::VectorXd sigma = PredictedSigma(M, theta);
  EXPECT_NEAR(sigma[0], 5.0, 1e-12);
  EXPECT_NEAR(sigma[1], 0.5, 1e-12);
}

}  // namespace
}  // namespace uuvplan::planner
