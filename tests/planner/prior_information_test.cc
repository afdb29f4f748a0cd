// Prior information from earlier trials (PriorInformation): the inverse of the estimates'
// covariance, nothing at all before the first estimate, and mismatched sizes refused rather
// than read out of bounds. Regression: FromCovariance on an empty covariance used to crash
// (the eigen-decomposition of a 0 × 0 matrix).
#include <gtest/gtest.h>

#include <stdexcept>

#include "planner_test_util.h"
#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/schedule_planner.h"

namespace uuvplan::planner {
namespace {

// Inverting a well-conditioned 2 × 2 matrix through its eigen-decomposition: rounding only.
constexpr double kTol = 1e-12;

TEST(PriorInformation, FromCovarianceInvertsIt) {
  Eigen::Matrix2d C;
  C << 4.0, 1.0, 1.0, 2.0;
  const PriorInformation p = PriorInformation::FromCovariance({"m", "k"}, C);
  ASSERT_EQ(p.names, (std::vector<std::string>{"m", "k"}));
  // C⁻¹ = [[2, -1], [-1, 4]] / 7.
  Eigen::Matrix2d expected;
  expected << 2.0, -1.0, -1.0, 4.0;
  expected /= 7.0;
  EXPECT_LT((p.M - expected).norm(), kTol);
}

TEST(PriorInformation, SingularCovarianceGivesThePseudoInverse) {
  // C = v·vᵀ with v = (1, 1): only m + k is known, M = v·vᵀ/|v|⁴ on that direction.
  Eigen::Matrix2d C = Eigen::Matrix2d::Constant(1.0);
  const PriorInformation p = PriorInformation::FromCovariance({"m", "k"}, C);
  EXPECT_LT((p.M - Eigen::Matrix2d::Constant(0.25)).norm(), kTol);
}

TEST(PriorInformation, EmptyCovarianceIsNoInformation) {
  // No estimates yet: with or without names, nothing is known.
  for (const std::vector<std::string>& names :
       {std::vector<std::string>{}, std::vector<std::string>{"m", "k"}}) {
    const PriorInformation p = PriorInformation::FromCovariance(names, Eigen::MatrixXd(0, 0));
    EXPECT_TRUE(p.names.empty());
    EXPECT_EQ(p.M.size(), 0);
    const auto ctx = DofPlanningProblem::APriori(testing::Romeo(), testing::RomeoPool(),
                                                 model::Dof::kSurge, PlannerOptions{}, nullptr);
    const Eigen::MatrixXd M = ctx->PriorMatrix(&p);
    EXPECT_EQ(M.rows(), ctx->model().num_parameters());
    EXPECT_EQ(M.norm(), 0.0);
  }
}

TEST(PriorInformation, MismatchedSizesAreRefused) {
  EXPECT_THROW(PriorInformation::FromCovariance({"m"}, Eigen::Matrix2d::Identity()),
               std::invalid_argument);
  EXPECT_THROW(PriorInformation::FromCovariance({"m", "k"}, Eigen::MatrixXd::Identity(2, 3)),
               std::invalid_argument);
  // A hand-made prior with the wrong size: PriorMatrix and the schedule's options refuse it.
  PriorInformation bad;
  bad.names = {"m", "k"};
  bad.M = Eigen::MatrixXd::Identity(1, 1);
  const auto ctx = DofPlanningProblem::APriori(testing::Romeo(), testing::RomeoPool(),
                                               model::Dof::kSurge, PlannerOptions{}, nullptr);
  EXPECT_THROW(ctx->PriorMatrix(&bad), std::invalid_argument);
  ScheduleOptions o;
  o.dofs = {model::Dof::kSurge};
  o.prior[model::Dof::kSurge] = bad;
  std::string error;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("prior[surge]"), std::string::npos) << error;
  const ScheduleResult r = PlanSchedule(testing::Romeo(), testing::RomeoPool(), o);
  EXPECT_EQ(r.status, PlanStatus::kInfeasible);
  EXPECT_NE(r.message.find("prior[surge]"), std::string::npos) << r.message;
}

}  // namespace
}  // namespace uuvplan::planner
