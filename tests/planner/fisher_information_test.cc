// Fisher information of a trial: against the closed form of a linear first-order step response,
// its convergence with the RK4 step, its continuity in the duration, the Goodwin & Payne
// D-optimal frequency (seed 000 eq. 14) as an oracle, and the predicted σ against the spread
// of output-error estimates on simulated noisy trials (Monte Carlo).
//
// Monte Carlo size: UUVPLAN_PLANNER_MC_RUNS (default 200; the full-size check is 2000, see
// docs/planning.md).
#include "uuvplan/planner/fisher_information.h"

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
#include "uuvplan/planner/criteria.h"
#include "uuvplan/planner/dof_context.h"
#include "uuvplan/planner/seed_rules.h"
#include "uuvplan/planner/solver.h"

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
  // m·dξ/dt = -k·ξ + F from rest: ξ(t) = (F/k)(1 - e^{-kt/m}),
  //   ∂ξ/∂m = -(F·t/m²)·e^{-kt/m},  ∂ξ/∂k = -(F/k²)(1 - e^{-kt/m}) + (F·t/(k·m))·e^{-kt/m}.
  // Velocity sampled at 10 Hz with σ = 0.01 over 20 s: M = Σ s·sᵀ/σ².
  const double m = 100.0, k = 20.0, F = 10.0, T = 20.0, sigma = 0.01;
  const model::Vehicle v = SimpleVehicle(m, k, 0.0, true, false);
  const model::DofModel dm(v, LinearStructure());
  ASSERT_EQ(dm.num_parameters(), 2);
  const Eigen::Vector2d theta(m, k);
  const auto input = model::MakeSteadyExcitation(F, 0, T);
  const TrialResponse r =
      SimulateTrial(dm, theta, *input, v.sensors.at(model::Dof::kSurge), T, 0.01, true);
  Eigen::Matrix2d M = Eigen::Matrix2d::Zero();
  for (int i = 0; i <= 200; ++i) {
    const double t = 0.1 * i, e = std::exp(-k * t / m);
    const Eigen::Vector2d s(-(F * t / (m * m)) * e, -(F / (k * k)) * (1 - e) + F * t / (k * m) * e);
    M += s * s.transpose() / (sigma * sigma);
  }
  // RK4 at 0.01 s on a 5 s time constant: relative error far below 1e-8.
  EXPECT_LT((r.M - M).norm() / M.norm(), 1e-8);
  EXPECT_NEAR(r.velocity_max, (F / k) * (1 - std::exp(-k * T / m)), 1e-9);
}

TEST(FisherInformation, ConvergesWithTheChosenStep) {
  // ROMEO surge, the seed's sine design, box centre: σ from ChooseStep's step (half the shortest
  // time constant) against a 0.01 s step. RK4's error at h/t_c ≈ 0.5 is ~1e-6 relative
  // (measured); 1e-4 leaves room and still catches a wrong step rule (h = t_c gives ~1e-3).
  const model::Vehicle v = testing::Romeo();
  std::vector<std::string> notes;
  const auto ctx = DofContext::APriori(v, testing::RomeoPool(), model::Dof::kSurge, {}, &notes);
  const model::TrialDesign d = testing::PaperSurgeSine();  // seed 000 §IV-D
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
  // M(10.05 s) = M(10 s) + 0.5·s(10.1)s(10.1)ᵀ/σ² at 10 Hz, and M is continuous at 10 s.
  const model::Vehicle v = SimpleVehicle(100.0, 20.0, 0.0, true, false);
  const model::DofModel dm(v, LinearStructure());
  const Eigen::Vector2d theta(100.0, 20.0);
  const auto input = model::MakeSteadyExcitation(10.0, 0, 100.0);
  const auto& sensors = v.sensors.at(model::Dof::kSurge);
  auto M = [&](double T) { return SimulateTrial(dm, theta, *input, sensors, T, 0.01, true).M; };
  const Eigen::MatrixXd M10 = M(10.0), M10p = M(10.0 + 1e-9), M1005 = M(10.05), M101 = M(10.1);
  EXPECT_LT((M10p - M10).norm() / M10.norm(), 1e-7);
  // Half of the 10.1 s sample's term: M(10.1) - M(10) is that whole term.
  EXPECT_LT((M1005 - (M10 + 0.5 * (M101 - M10))).norm() / M10.norm(), 1e-9);
}

TEST(FisherInformation, GoodwinPayneOptimalFrequencyIsAOverRoot3) {
  // Seed 000 eq. 14 (Goodwin & Payne): for dξ/dt = -a·ξ + b·u, ξ measured with white noise,
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
  // Each replicate adds seeded Gaussian noise and fits θ = [m, k, kq, bias] by Gauss-Newton
  // output error from the truth (the maximum-likelihood estimate for this noise). Its spread
  // must match the Cramér-Rao σ = sqrt((M⁻¹)_ii) the planner predicts: with n replicates the
  // sample σ has a relative standard error 1/sqrt(2(n-1)); the tolerance is 4 of those.
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
  Eigen::MatrixXd est(n, 4);
  for (int r = 0; r < n; ++r) {
    Eigen::VectorXd y = clean;
    for (int i = 0; i < y.size(); ++i) y[i] += noise(rng);
    Eigen::VectorXd th = truth;
    for (int it = 0; it < 6; ++it) {
      const model::Trajectory tr = model::SimulateMeasured(dm, th, c, times, so);
      const Eigen::MatrixXd& S = tr.S[0];
      th += (S.transpose() * S).ldlt().solve(S.transpose() * (y - tr.x.col(0)));
    }
    est.row(r) = th.transpose();
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
