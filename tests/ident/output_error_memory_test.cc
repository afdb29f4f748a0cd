// The output error's memory grows with the campaign's data, not with trials². The
// pieces that make it so — the block-angular factor of J (ident/src/block_least_squares.h) and
// the streaming prewhitened sandwich (covariance.h WhitenedScoreSum) — against their dense
// definitions, and the live heap of a 420-trial fit against its number of measurements.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "ident_cases.h"
#include "support/live_heap.h"
#include "uuvplan/ident/estimators/block_least_squares.h"
#include "uuvplan/ident/estimators/output_error.h"
#include "uuvplan/ident/prepare/trial_data.h"
#include "uuvplan/ident/stats/covariance.h"
#include "uuvplan/ident/stats/monte_carlo.h"

namespace uuvplan::ident {
namespace {

using RowMajor = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

// The sandwich's middle matrix by its definition: Z_j = J_j + ρ·Z_{j+1} backward within each
// group, û the innovations, batches of `block` rows from each group's start.
Eigen::MatrixXd DirectScoreSum(const Eigen::MatrixXd& J, const Eigen::VectorXd& r,
                               const Prewhitening& plan, int* batches) {
  Eigen::MatrixXd S = Eigen::MatrixXd::Zero(J.cols(), J.cols());
  *batches = 0;
  for (std::size_t g = 0; g < plan.runs.size(); ++g) {
    const auto [a, b] = plan.runs[g];
    const double rho = plan.rho[g];
    Eigen::MatrixXd Z(b - a, J.cols());
    Z.row(b - a - 1) = J.row(b - 1);
    for (int i = b - 2; i >= a; --i) Z.row(i - a) = J.row(i) + rho * Z.row(i - a + 1);
    for (int s = a; s < b; s += plan.block) {
      Eigen::VectorXd score = Eigen::VectorXd::Zero(J.cols());
      for (int i = s; i < std::min(b, s + plan.block); ++i) {
        const double u = i == a ? r[i] : r[i] - rho * r[i - 1];
        score += u * Z.row(i - a).transpose();
      }
      S += score * score.transpose();
      ++*batches;
    }
  }
  return S;
}

TEST(WhitenedScoreSumTest, StreamingEqualsTheBackwardRecursionOfItsDefinition) {
  // AR(1) residuals of ρ = 0.8 in three groups of unequal length, batches of 7 rows:
  // the forward sums are an exact rewrite, so only rounding separates them (1e-10 relative).
  std::mt19937_64 rng(15);
  std::normal_distribution<double> n01(0, 1);
  const int n = 900, p = 4;
  Eigen::MatrixXd J(n, p);
  Eigen::VectorXd r(n);
  std::vector<int> groups(n);
  double e = 0.0;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < p; ++j) J(i, j) = n01(rng) + std::sin(0.01 * i * (j + 1));
    e = 0.8 * e + n01(rng);
    r[i] = e;
    groups[i] = i < 200 ? 0 : i < 650 ? 1 : 2;
  }
  Prewhitening plan = PlanPrewhitening(r, groups);
  EXPECT_NEAR(plan.rho[1], 0.8, 0.1);  // 450 rows: σ(ρ̂) ≈ 0.03
  plan.block = 7;  // batches of several rows (AR(1) innovations are white: the plan's is 1)
  WhitenedScoreSum sum(p, plan.block);
  const RowMajor rows = J;
  for (std::size_t g = 0; g < plan.runs.size(); ++g) {
    sum.StartGroup(plan.rho[g]);
    for (int i = plan.runs[g].first; i < plan.runs[g].second; ++i)
      sum.Add(rows.row(i).data(), r[i]);
  }
  int batches = 0;
  const Eigen::MatrixXd direct = DirectScoreSum(J, r, plan, &batches);
  EXPECT_LT((sum.Sum() - direct).norm(), 1e-10 * direct.norm());
  EXPECT_EQ(sum.batches(), batches);
}

// A block-angular J: `shared` columns for every row, `own` of each block's own.
struct Arrow {
  Eigen::MatrixXd J;  // dense, unknowns' order: θ, then each block's own columns
  Eigen::VectorXd r;
  BlockLeastSquares ls;
};
Arrow MakeArrow(int shared, int blocks, int own, int rows_per_block, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01(0, 1);
  const int P = shared + blocks * own, n = blocks * rows_per_block;
  Arrow a{Eigen::MatrixXd::Zero(n, P), Eigen::VectorXd(n), BlockLeastSquares(shared)};
  for (int t = 0; t < blocks; ++t) {
    const int first = shared + t * own;
    a.ls.StartBlock(first, own);
    for (int k = 0; k < rows_per_block; ++k) {
      const int i = t * rows_per_block + k;
      double* row = a.ls.Row();
      for (int c = 0; c < own; ++c) row[c] = a.J(i, first + c) = n01(rng) + (c == 0 ? 2.0 : 0.0);
      for (int c = 0; c < shared; ++c) row[own + c] = a.J(i, c) = n01(rng) + 0.1 * c;
      row[own + shared] = a.r[i] = n01(rng);
      a.ls.Commit();
    }
    a.ls.EndBlock();
  }
  a.ls.Finish();
  return a;
}

TEST(BlockLeastSquaresTest, StepsAndCovarianceEqualTheDenseNormalEquations) {
  // 30 blocks of 700 rows (more than one 512-row chunk each), 3 shared and 2 own columns:
  // the Levenberg–Marquardt step, the gradient and (JᵀJ)⁻¹ of the dense J to rounding (1e-9
  // relative: the condition number of JᵀJ here is ~10², so rounding stays below 1e-12).
  const Arrow a = MakeArrow(3, 30, 2, 700, 16);
  const Eigen::MatrixXd A = a.J.transpose() * a.J;
  const Eigen::VectorXd g = a.J.transpose() * a.r;
  EXPECT_LT((a.ls.Gradient() - g).norm(), 1e-9 * g.norm());
  for (double lambda : {0.0, 1e-3, 10.0}) {
    Eigen::MatrixXd M = A;
    M.diagonal() += lambda * A.diagonal();
    const Eigen::VectorXd dense = M.ldlt().solve(g);
    EXPECT_LT((a.ls.Solve(g, lambda) - dense).norm(), 1e-9 * dense.norm()) << "λ = " << lambda;
  }
  const Eigen::MatrixXd inverse = A.inverse();
  LeastSquaresOptions o;
  const BlockAnalysis dense = AnalyseBlocks(a.ls, o);
  ASSERT_TRUE(dense.dense);
  EXPECT_LT((dense.unit_covariance - inverse).norm(), 1e-9 * inverse.norm());
  EXPECT_TRUE(dense.not_identifiable.empty());
  // Many blocks (beyond kDenseColumns unknowns): θ's block of the same inverse, and each
  // block's response K_t maps its columns to θ's rows of (JᵀJ)⁻¹.
  const Arrow big = MakeArrow(3, 250, 2, 20, 17);
  const BlockAnalysis reduced = AnalyseBlocks(big.ls, o);
  ASSERT_FALSE(reduced.dense);
  const Eigen::MatrixXd big_inverse = (big.J.transpose() * big.J).inverse();
  EXPECT_LT((reduced.unit_covariance - big_inverse.topLeftCorner(3, 3)).norm(),
            1e-9 * big_inverse.topLeftCorner(3, 3).norm());
  const Eigen::MatrixXd K = SharedResponse(big.ls.blocks()[7], reduced.unit_covariance, 3);
  Eigen::MatrixXd expected(3, 5);
  expected << big_inverse.block(0, 3 + 7 * 2, 3, 2), big_inverse.topLeftCorner(3, 3);
  EXPECT_LT((K - expected).norm(), 1e-9 * expected.norm());
}

// The output error of the campaign's standard surge model started 5% off the truth, model
// selection off, and its peak live heap.
std::pair<OutputErrorResult, long long> SurgeFitCountingHeap(
    const model::Campaign& c, const model::Truth& truth,
    const std::vector<const TrialData*>& trials) {
  const model::DofModel m(
      c.vehicle, model::ModelStructure::Standard(c.vehicle, model::Dof::kSurge, {}, false));
  Eigen::VectorXd theta(m.num_parameters());
  for (int j = 0; j < m.num_parameters(); ++j) {
    theta[j] = 1.05 * TrueParameter(truth, model::Dof::kSurge, m.parameter_names()[j]);
  }
  const std::vector<ParameterState> state(m.num_parameters(), ParameterState::kEstimated);
  OutputErrorOptions o;
  o.selection.prune_insignificant = false;
  uuvplan::testing::StartCountingHeap();
  OutputErrorResult r = OutputErrorFit(m, trials, theta, state, o);
  return {std::move(r), uuvplan::testing::StopCountingHeap()};
}

TEST(OutputErrorMemoryTest, LiveHeapOfAManyTrialFitGrowsWithItsMeasurementsNotTrialsSquared) {
  if (!uuvplan::testing::HeapCountingAvailable())
    GTEST_SKIP() << "a sanitizer build counts no heap";
  // 420 ROMEO surge trials of 24 s (position at 3.33 Hz, ~80 measurements each; each trial's
  // initial position is an unknown of its own: 423 unknowns). A dense Jacobian would be
  // measurements × unknowns × 8 B = 34,000 × 423 × 8 = 115 MB; the fit's peak live heap must
  // stay under 400 B per measurement (13.6 MB): the trials' prepared signals and
  // simulations, a few residual vectors, O(trials) blocks — what is proportional to the data.
  const model::Truth truth = testing::CaseTruth("romeo");
  std::vector<model::TrialDesign> designs;
  for (int i = 0; i < 420; ++i) {
    designs.push_back(testing::Segments("t" + std::to_string(i), model::Dof::kSurge, "surge-front",
                                        {{20.0 + i % 7, 12}, {-25.0, 12}}));
  }
  const model::Campaign c = VirtualCampaign(truth, designs, 15, {}, 5.0);
  std::vector<TrialData> data;
  for (std::size_t i = 0; i < c.trials.size(); ++i) {
    data.push_back(PrepareTrial(c.trials[i], static_cast<int>(i), c.vehicle, TrialDataOptions{}));
  }
  std::vector<const TrialData*> trials;
  for (const TrialData& d : data) trials.push_back(&d);
  const auto [r, peak] = SurgeFitCountingHeap(c, truth, trials);
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_GT(static_cast<int>(r.initial.size() + r.names.size()), BlockAnalysis::kDenseColumns);
  EXPECT_LT(peak, 400LL * r.num_residuals)
      << r.num_residuals << " measurements, peak live heap " << peak << " B";
  std::cout << r.num_residuals << " measurements, peak live heap " << peak / 1e6 << " MB\n";
}

TEST(OutputErrorMemoryTest,
     ALongPositionTrialIsFittedWithoutStoringItsSimulationOrItsSamplesAgain) {
  if (!uuvplan::testing::HeapCountingAvailable())
    GTEST_SKIP() << "a sanitizer build counts no heap";
  // The long-log benchmark case in small (bench/cases/position_surge_truth.yaml: position alone at
  // 100 Hz, σ 1 cm), 300 s of force legs: 30,001 measurements on the output error's 0.05 s grid
  // (6,001 points). The fit makes the trial's rows while the simulation runs and reads the
  // samples in place. What it holds per measurement at its peak: the residuals at the answer
  // (8 B), the grid (1.6 B) and O(1) more: 10.8 B measured (the gross-error median selects in
  // place, MedianAbs). Under 13 B: the single-precision copy of the residuals' absolute values
  // that median once took adds 4 B, the simulation stored on the grid instead (its
  // sensitivities, Hermite slopes and times) 28 B, a copy of the samples and their times 16 B,
  // a second residual vector 8 B.
  const model::Truth truth =
      io::ReadTruth(std::string(UUVPLAN_SOURCE_DIR) + "/bench/cases/position_surge_truth.yaml");
  const model::Campaign c = VirtualCampaign(
      truth,
      {testing::Segments(
          "legs", model::Dof::kSurge, "surge-front",
          {{50, 40}, {-25, 30}, {75, 40}, {-50, 40}, {25, 50}, {-75, 40}, {50, 60}})},
      16);
  const TrialData d = PrepareTrial(c.trials[0], 0, c.vehicle, TrialDataOptions{});
  ASSERT_FALSE(d.has_velocity());
  const auto [r, peak] = SurgeFitCountingHeap(c, truth, {&d});
  ASSERT_TRUE(r.ok()) << r.message;
  ASSERT_EQ(r.num_residuals, static_cast<int>(d.position.size()));
  EXPECT_LT(peak, 13LL * r.num_residuals)
      << r.num_residuals << " measurements, peak live heap " << peak << " B";
  std::cout << r.num_residuals << " measurements, peak live heap " << peak << " B ("
            << double(peak) / r.num_residuals << " B a measurement)\n";
  // The fit is a fit: m within 3σ of the truth (1.5 times a 95% interval's half-width).
  const int im = static_cast<int>(std::find(r.names.begin(), r.names.end(), "m") - r.names.begin());
  ASSERT_LT(im, static_cast<int>(r.names.size()));
  EXPECT_LT(std::abs(r.theta[im] - 900.0), 3.0 * std::sqrt(r.covariance(im, im)));
}

}  // namespace
}  // namespace uuvplan::ident
