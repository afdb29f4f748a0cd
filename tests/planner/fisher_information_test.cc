// Fisher information of a trial: against the closed form of a linear first-order step response,
// its convergence with the RK4 step, its continuity in the duration, the Goodwin & Payne
// D-optimal frequency (ref 000 eq. 14) as an oracle, and the predicted σ against the spread
// of output-error estimates on simulated noisy trials (Monte Carlo).
//
// Monte Carlo size: UUVPLAN_PLANNER_MC_RUNS (default 200; the full-size check is 2000, see
// docs/planning.md).
#include "uuvplan/planner/design/fisher_information.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>

#include "planner_test_util.h"
#include "uuvplan/model/dof_model.h"
#include "uuvplan/model/excitation.h"
#include "uuvplan/model/model_structure.h"
#include "uuvplan/model/simulator.h"
#include "uuvplan/planner/design/criteria.h"
#include "uuvplan/planner/design/dof_planning_problem.h"
#include "uuvplan/planner/design/seed_rules.h"
#include "uuvplan/planner/design/solver.h"

namespace uuvplan::planner {
namespace {

using testing::SimpleVehicle;

model::ModelStructure LinearStructure() {
  model::ModelStructure s;
  s.dof = model::Dof::kSurge;
  s.Remove("kq");
  s.Remove("bias");
  return s;
}

TEST(FisherInformation, MatchesTheClosedFormOfALinearStepResponse) {
  // m·dξ/dt = -k·ξ + F from ξ0 = 0: ξ(t) = (F/k)(1 - e^{-kt/m}),
  //   ∂ξ/∂m = -(F·t/m²)·e^{-kt/m},  ∂ξ/∂k = -(F/k²)(1 - e^{-kt/m}) + (F·t/(k·m))·e^{-kt/m},
  //   ∂ξ/∂ξ0 = e^{-kt/m} (the initial velocity the output error fits with θ).
  // Velocity sampled at 10 Hz with σ = 0.01 over 20 s: the information of (m, k, ξ0) is
  // J = Σ s·sᵀ/σ², and M on (m, k) is its Schur complement with ξ0 profiled out.
  const double m = 100.0, k = 20.0, F = 10.0, T = 20.0, sigma = 0.01;
  const model::Vehicle v = SimpleVehicle(m, k, 0.0, true, false);
  const model::DofModel dm(v, LinearStructure());
  ASSERT_EQ(dm.num_parameters(), 2);
  const Eigen::Vector2d theta(m, k);
  const auto input = model::MakeSteadyExcitation(F, 0, T);
  const TrialResponse r =
      SimulateTrial(dm, theta, *input, v.sensors.at(model::Dof::kSurge), T, 0.01, true);
  Eigen::Matrix3d J = Eigen::Matrix3d::Zero();
  for (int i = 0; i <= 200; ++i) {
    const double t = 0.1 * i, e = std::exp(-k * t / m);
    const Eigen::Vector3d s(-(F * t / (m * m)) * e, -(F / (k * k)) * (1 - e) + F * t / (k * m) * e,
                            e);
    J += s * s.transpose() / (sigma * sigma);
  }
  const Eigen::Matrix2d M =
      J.topLeftCorner<2, 2>() - J.topRightCorner<2, 1>() * J.bottomLeftCorner<1, 2>() / J(2, 2);
  // RK4 at 0.01 s on a 5 s time constant: relative error far below 1e-8; ∂ξ/∂ξ0 by a forward
  // difference, exact for a linear model up to rounding (~1e-10).
  ASSERT_EQ(r.M_joint.rows(), 3);
  EXPECT_LT((r.M_joint - J).norm() / J.norm(), 1e-8);
  EXPECT_LT((r.M - M).norm() / M.norm(), 1e-8);
  // start_known gives θ's block of the joint information (the same sums: to rounding), and
  // profiling ξ0 out costs information: that block minus M is positive semidefinite and not 0.
  const TrialResponse known = SimulateTrial(dm, theta, *input, v.sensors.at(model::Dof::kSurge), T,
                                            0.01, true, /*start_known=*/true);
  EXPECT_EQ(known.M_joint.size(), 0);
  EXPECT_LT((known.M - r.M_joint.topLeftCorner<2, 2>()).norm() / known.M.norm(), 1e-12);
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> lost(known.M - r.M);
  EXPECT_GE(lost.eigenvalues().minCoeff(), -1e-9 * known.M.norm());
  EXPECT_GT(lost.eigenvalues().maxCoeff(), 1e-3 * r.M.norm());
  EXPECT_NEAR(r.velocity_max, (F / k) * (1 - std::exp(-k * T / m)), 1e-9);
}

TEST(FisherInformation, ConvergesWithTheChosenStep) {
  // ROMEO surge, the seed's sine design, box centre: σ from ChooseStep's step (half the shortest
  // time constant) against a 0.01 s step. RK4's error at h/t_c ≈ 0.5 is ~1e-6 relative
  // (measured); 1e-4 leaves room and still catches a wrong step rule (h = t_c gives ~1e-3).
  const model::Vehicle v = testing::Romeo();
  std::vector<std::string> notes;
  const auto ctx =
      DofPlanningProblem::APriori(v, testing::RomeoPool(), model::Dof::kSurge, {}, &notes);
  const model::TrialDesign d = testing::PaperSurgeSine();  // ref 000 §IV-D
  const auto& tm = ctx->ModelFor(d);
  const auto input = model::MakeExcitation(v, d);
  for (const auto& theta : tm.design_thetas) {
    const Eigen::MatrixXd M1 =
        SimulateTrial(*tm.model, theta, *input, ctx->sensors(), d.duration, ctx->step_s(), true).M;
    const Eigen::MatrixXd M2 =
        SimulateTrial(*tm.model, theta, *input, ctx->sensors(), d.duration, 0.01, true).M;
    const Eigen::VectorXd s1 = PredictedSigma(M1, theta), s2 = PredictedSigma(M2, theta);
    for (int i = 0; i < s1.size(); ++i) EXPECT_NEAR(s1[i] / s2[i], 1.0, 1e-4) << i;
  }
  EXPECT_GT(ctx->step_s(), 0.1);  // the point of choosing: not the 0.01 s reference
}

TEST(FisherInformation, IsContinuousInTheDuration) {
  // The sample after the last whole one counts with the fraction of its interval covered:
  // J(10.05 s) = J(10 s) + 0.5·s(10.1)s(10.1)ᵀ/σ² at 10 Hz for the information J of (θ, ξ0),
  // and M (ξ0 profiled out) is continuous at 10 s.
  const model::Vehicle v = SimpleVehicle(100.0, 20.0, 0.0, true, false);
  const model::DofModel dm(v, LinearStructure());
  const Eigen::Vector2d theta(100.0, 20.0);
  const auto input = model::MakeSteadyExcitation(10.0, 0, 100.0);
  const auto& sensors = v.sensors.at(model::Dof::kSurge);
  // The half-sample identity holds for the information of (θ, ξ0), linear in the weights
  // (M_joint); M, its Schur complement with ξ0 profiled out, is only continuous.
  auto R = [&](double T) { return SimulateTrial(dm, theta, *input, sensors, T, 0.01, true); };
  const TrialResponse R10 = R(10.0), R10p = R(10.0 + 1e-9), R1005 = R(10.05), R101 = R(10.1);
  EXPECT_LT((R10p.M - R10.M).norm() / R10.M.norm(), 1e-7);
  EXPECT_LT((R10p.M_joint - R10.M_joint).norm() / R10.M_joint.norm(), 1e-7);
  // Half of the 10.1 s sample's term: M_joint(10.1) - M_joint(10) is that whole term. (The
  // forward-difference step of ∂y/∂ξ0 scales with the trial's speed range, which grows with the
  // duration: exact for this linear model up to rounding.)
  const Eigen::MatrixXd &J10 = R10.M_joint, &J1005 = R1005.M_joint, &J101 = R101.M_joint;
  EXPECT_LT((J1005 - (J10 + 0.5 * (J101 - J10))).norm() / J10.norm(), 1e-9);
  // M between its neighbours: one half-sample adds information, the other half more.
  const double m10 = R10.M(0, 0), m1005 = R1005.M(0, 0), m101 = R101.M(0, 0);
  EXPECT_GT(m1005, m10);
  EXPECT_LT(m1005, m101);
}

TEST(FisherInformation, GoodwinPayneOptimalFrequencyIsAOverRoot3) {
  // Ref 000 eq. 14 (Goodwin & Payne): for dξ/dt = -a·ξ + b·u, ξ measured with white noise,
  // a single sine of fixed amplitude, det M ∝ ω²/(a² + ω²)⁴ per unit time, maximal at
  // ω = a/√3. Here a = k/m = 0.2 s⁻¹ and θ = (m, k) (a fixed reparametrisation of (a, b)
  // changes det M by a constant factor only). 100 whole periods per trial make the start from
  // rest negligible; the D criterion of M/T is maximised over ω by the NLopt backend.
  // Tolerance 1% (the requirement).
  const double m = 100.0, k = 20.0, a = k / m;
  model::Vehicle v = SimpleVehicle(m, k, 0.0, true, false);
  v.sensors[model::Dof::kSurge].velocity->rate_hz = 2.0;  // 27 samples per period at a/√3
  const model::DofModel dm(v, LinearStructure());
  const Eigen::Vector2d theta(m, k);
  const auto& sensors = v.sensors.at(model::Dof::kSurge);
  auto omega_of = [a](double x) { return a * std::pow(10.0, 2.0 * x - 1.0); };  // 0.1a..10a
  DesignProblem p;
  p.num_variables = 1;
  p.lower = {0.0};
  p.upper = {1.0};
  p.x0 = {0.5};
  p.evaluate = [&](const double* x, double* phi, double*) {
    const double w = omega_of(x[0]);
    const double T = 100.0 * 2 * M_PI / w;
    const auto input = model::MakeSineExcitation(0.0, 5.0, w, 0, T);
    const Eigen::MatrixXd M = SimulateTrial(dm, theta, *input, sensors, T, 0.5, true).M / T;
    phi[0] = EvaluateCriterion(RelativeInformation(M, theta), Criterion::kD, {}).value;
    return true;
  };
  SolverOptions o;
  o.max_global_evaluations = 40;
  o.max_local_evaluations = 40;
  o.relative_tolerance = 1e-10;
  const SolverSummary s = SolveWithNlopt(p, o);
  ASSERT_TRUE(s.is_success()) << s.BriefReport();
  const double w_opt = DOptimalSineFrequency(TimeConstant(m, k));
  EXPECT_NEAR(w_opt, a / std::sqrt(3.0), 1e-15);
  std::cout << "[ goodwin-payne ] optimum ω/(a/√3) = " << omega_of(s.x[0]) / w_opt << "\n";
  EXPECT_NEAR(omega_of(s.x[0]) / w_opt, 1.0, 0.01) << s.BriefReport();
}

TEST(FisherInformation, PredictedSigmaMatchesMonteCarloOutputError) {
  // ROMEO surge truth (cases/romeo/truth.yaml: m 890, k 46.9, kq 306.2, bias 0) run through the
  // seed's sine (35 ± 25 N, 26 s period, 52 s) in surge-front, sonar at 3.33 Hz with σ = 0.03 m.
  // Each replicate adds seeded Gaussian noise and fits θ = [m, k, kq, bias] with the trial's
  // initial position χ0 and velocity ξ0 by Gauss-Newton output error from the truth (the
  // maximum-likelihood estimate for this noise, with the initial state unknown as in
  // ident/src/estimators/output_error.cc). Its spread must match the Cramér-Rao σ = sqrt((M⁻¹)_ii)
  // the planner predicts (χ0 and ξ0 profiled out): with n replicates the sample σ has a relative
  // standard error 1/sqrt(2(n-1)); the tolerance is 4 of those.
  const model::Vehicle v = testing::Romeo();
  model::ModelStructure s = model::ModelStructure::Standard(v, model::Dof::kSurge, {}, false);
  const model::DofModel dm(v, s);
  ASSERT_EQ(dm.num_parameters(), 4);
  const Eigen::Vector4d truth(890.0, 46.9, 306.2, 0.0);
  const auto input =
      model::MakeSineExcitation(35.0, 25.0, 2 * M_PI / 26.0, v.MappingIndex("surge-front"), 52.0);
  const auto& sensors = v.sensors.at(model::Dof::kSurge);
  const double sigma = sensors.position->sigma;
  const Eigen::MatrixXd M = SimulateTrial(dm, truth, *input, sensors, 52.0, 0.05, true).M;
  const Eigen::VectorXd predicted = PredictedSigma(M, truth);

  std::vector<double> times;
  for (int i = 0; i / sensors.position->rate_hz <= 52.0; ++i) {
    times.push_back(i / sensors.position->rate_hz);
  }
  model::TrialConditions c;
  c.input = input.get();
  model::SimulationOptions so;
  so.step_s = 0.05;
  so.sensitivities = true;
  const Eigen::VectorXd clean = model::SimulateMeasured(dm, truth, c, times, so).x.col(0);
  const char* env = std::getenv("UUVPLAN_PLANNER_MC_RUNS");
  const int n = env ? std::max(10, std::atoi(env)) : 200;
  std::mt19937_64 rng(20240601);
  std::normal_distribution<double> noise(0.0, sigma);
  model::SimulationOptions plain = so;
  plain.sensitivities = false;
  Eigen::MatrixXd est(n, 4);
  for (int r = 0; r < n; ++r) {
    Eigen::VectorXd y = clean;
    for (int i = 0; i < y.size(); ++i) y[i] += noise(rng);
    Eigen::VectorXd z = Eigen::VectorXd::Zero(6);  // θ, χ0, ξ0
    z.head(4) = truth;
    for (int it = 0; it < 6; ++it) {
      Eigen::VectorXd x0 = Eigen::VectorXd::Zero(dm.num_states());
      x0[0] = z[4];
      x0[1] = z[5];
      const model::Trajectory tr = model::SimulateMeasured(dm, z.head(4), c, times, so, &x0);
      const double h = 1e-6;  // m/s: ∂y/∂ξ0 by a forward difference
      Eigen::VectorXd x1 = x0;
      x1[1] += h;
      const Eigen::VectorXd y1 =
          model::SimulateMeasured(dm, z.head(4), c, times, plain, &x1).x.col(0);
      Eigen::MatrixXd S(times.size(), 6);
      S.leftCols(4) = tr.S[0];
      S.col(4).setOnes();
      S.col(5) = (y1 - tr.x.col(0)) / h;
      z += (S.transpose() * S).ldlt().solve(S.transpose() * (y - tr.x.col(0)));
    }
    est.row(r) = z.head(4).transpose();
  }
  const Eigen::RowVectorXd mean = est.colwise().mean();
  const double tol = 4.0 / std::sqrt(2.0 * (n - 1));
  for (int i = 0; i < 4; ++i) {
    const double sd = std::sqrt((est.col(i).array() - mean[i]).square().sum() / (n - 1));
    std::cout << "[ monte carlo ] " << dm.parameter_names()[i]
              << ": sample σ / predicted σ = " << sd / predicted[i] << " (n = " << n << ")\n";
    EXPECT_NEAR(sd / predicted[i], 1.0, tol)
        << dm.parameter_names()[i] << " sample σ " << sd << " predicted " << predicted[i];
  }
}

}  // namespace
}  // namespace uuvplan::planner
