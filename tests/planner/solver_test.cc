// The design solver interface on problems with known optima, run through both backends (the
// same DesignProblem through NLopt and Ipopt, as Drake's solvers/test examples do).
#include "uuvplan/planner/design/solver.h"

#include <gtest/gtest.h>

#include <cmath>

namespace uuvplan::planner {
namespace {

// Two box points with concave criteria -(x - 0.2)² and -(x - 0.8)²: the maximin optimum is
// x = 0.5, value -0.09 (where the two cross); the average optimum is also 0.5 but -0.09 too.
DesignProblem TwoScenarios() {
  DesignProblem p;
  p.num_variables = 1;
  p.lower = {0.0};
  p.upper = {1.0};
  p.x0 = {0.1};
  p.num_scenarios = 2;
  p.evaluate = [](const double* x, double* phi, double*) {
    phi[0] = -(x[0] - 0.2) * (x[0] - 0.2);
    phi[1] = -(x[0] - 0.8) * (x[0] - 0.8);
    return true;
  };
  return p;
}

// maximise -(x0-1)² - (x1-1)² subject to x0 + x1 <= 1: optimum (0.5, 0.5), value -0.5.
DesignProblem Constrained() {
  DesignProblem p;
  p.num_variables = 2;
  p.lower = {0.0, 0.0};
  p.upper = {2.0, 2.0};
  p.x0 = {0.0, 0.0};
  p.num_constraints = 1;
  p.evaluate = [](const double* x, double* phi, double* g) {
    phi[0] = -(x[0] - 1) * (x[0] - 1) - (x[1] - 1) * (x[1] - 1);
    g[0] = x[0] + x[1] - 1.0;
    return true;
  };
  return p;
}

// Solver tolerances: the optimisers stop at relative_tolerance 1e-6 on the objective, with
// forward-difference gradients (step 1e-5); 1e-4 in x is well inside what both reach.
constexpr double kXTol = 1e-3;
constexpr double kFTol = 1e-5;

TEST(Solver, MaximinEpigraphBothBackends) {
  for (SolverBackend b : {SolverBackend::kNlopt, SolverBackend::kIpopt}) {
    SolverOptions o;
    o.robustness = Robustness::kMaximin;
    const SolverSummary s = Solve(b, TwoScenarios(), o);
    ASSERT_TRUE(s.is_success()) << s.BriefReport();
    EXPECT_NEAR(s.x[0], 0.5, kXTol) << s.BriefReport();
    EXPECT_NEAR(s.objective, -0.09, kFTol) << s.BriefReport();
  }
}

TEST(Solver, ConstrainedOptimumBothBackends) {
  for (SolverBackend b : {SolverBackend::kNlopt, SolverBackend::kIpopt}) {
    SolverOptions o;
    o.robustness = Robustness::kAverage;
    const SolverSummary s = Solve(b, Constrained(), o);
    ASSERT_TRUE(s.is_success()) << s.BriefReport();
    EXPECT_NEAR(s.x[0], 0.5, kXTol) << s.BriefReport();
    EXPECT_NEAR(s.x[1], 0.5, kXTol) << s.BriefReport();
    EXPECT_NEAR(s.objective, -0.5, kFTol) << s.BriefReport();
    EXPECT_LE(s.max_violation, 1e-7);
  }
}

TEST(Solver, GlobalSearchFindsTheHigherOfTwoPeaks) {
  // φ(x) = exp(-50(x - 0.15)²) + 1.5·exp(-50(x - 0.8)²): a local method from x0 = 0.1 climbs the
  // lower peak; DIRECT-L and MLSL must find the one at 0.8 (value 1.5 up to the other's tail).
  DesignProblem p;
  p.num_variables = 1;
  p.lower = {0.0};
  p.upper = {1.0};
  p.x0 = {0.1};
  p.evaluate = [](const double* x, double* phi, double*) {
    phi[0] = std::exp(-50 * (x[0] - 0.15) * (x[0] - 0.15)) +
             1.5 * std::exp(-50 * (x[0] - 0.8) * (x[0] - 0.8));
    return true;
  };
  SolverOptions o;
  o.robustness = Robustness::kNominal;
  const SolverSummary global = SolveWithNlopt(p, o);
  EXPECT_NEAR(global.x[0], 0.8, 0.01) << global.BriefReport();
  o.global = GlobalMethod::kMlsl;
  const SolverSummary mlsl = SolveWithNlopt(p, o);
  EXPECT_NEAR(mlsl.x[0], 0.8, 0.01) << mlsl.BriefReport();
}

TEST(Solver, InfeasibleProblemIsReportedAsSuch) {
  DesignProblem p = Constrained();
  p.evaluate = [](const double* x, double* phi, double* g) {
    phi[0] = -x[0];
    g[0] = 5.0 - x[0] - x[1];  // needs x0 + x1 >= 5, impossible in [0, 2]²
    return true;
  };
  for (SolverBackend b : {SolverBackend::kNlopt, SolverBackend::kIpopt}) {
    SolverOptions o;
    o.robustness = Robustness::kNominal;
    const SolverSummary s = Solve(b, p, o);
    EXPECT_EQ(s.status, SolverStatus::kInfeasible) << s.BriefReport();
    EXPECT_FALSE(s.is_success());
    EXPECT_NEAR(s.max_violation, 1.0, 1e-3);  // the closest point, (2, 2), misses by 1
  }
}

TEST(Solver, OptionsAreValidated) {
  SolverOptions o;
  o.fd_step = -1;
  std::string error;
  EXPECT_FALSE(o.IsValid(&error));
  EXPECT_NE(error.find("fd_step"), std::string::npos) << error;
  const SolverSummary s = SolveWithNlopt(TwoScenarios(), o);
  EXPECT_EQ(s.status, SolverStatus::kFailed);
  EXPECT_NE(s.message.find("fd_step"), std::string::npos);
}

}  // namespace
}  // namespace uuvplan::planner
