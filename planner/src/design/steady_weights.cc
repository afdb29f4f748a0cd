// Steps 2 and 3 of the steady design (steady_design.h): the approximate design's problem over
// the candidates' weights, and its rounding to N legs.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <numeric>

#include "design/steady_legs.h"
#include "uuvplan/ident/stats/sub_matrix.h"
#include "uuvplan/planner/design/criteria.h"
#include "uuvplan/planner/design/steady_design.h"

namespace uuvplan::planner {
namespace {

using ident::SubMatrix;

// Relative scaling of the DOF parameters at a design point.
Eigen::VectorXd Scale(const Eigen::VectorXd& theta) {
  Eigen::VectorXd d(theta.size());
  for (int i = 0; i < theta.size(); ++i) d[i] = theta[i] != 0.0 ? std::abs(theta[i]) : 1.0;
  return d;
}

// The candidates' and the prior's information relative to each design point (D·M·D,
// D = diag|θ_j|), on the parameters P that some candidate or the prior reaches; m (index 0) is
// the nuisance.
struct WeightsData {
  std::vector<int> P, nuisance;                  // nuisance: indices into P
  std::vector<std::vector<Eigen::MatrixXd>> Mc;  // [j][c] relative, on P
  std::vector<Eigen::MatrixXd> M0;               // [j] relative prior on P
  int N;
  Criterion criterion;
  int num_candidates() const { return static_cast<int>(Mc.front().size()); }
};

std::shared_ptr<const WeightsData> MakeWeightsData(
    const DofPlanningProblem& ctx, const std::vector<std::vector<Eigen::MatrixXd>>& M, int N,
    const std::vector<Eigen::MatrixXd>& prior, Criterion criterion) {
  const int C = static_cast<int>(M.size());
  const int J = static_cast<int>(ctx.design_thetas().size());
  const int np = ctx.model().num_parameters();
  auto data = std::make_shared<WeightsData>();
  data->N = N;
  data->criterion = criterion;
  Eigen::MatrixXd total = Eigen::MatrixXd::Zero(np, np);
  for (const auto& mc : M) total += RelativeInformation(mc[0], ctx.design_thetas()[0]);
  if (!prior.empty()) total += RelativeInformation(prior[0], ctx.design_thetas()[0]);
  data->P = InformedParameters(total);
  for (std::size_t a = 0; a < data->P.size(); ++a) {
    if (data->P[a] == 0) data->nuisance.push_back(static_cast<int>(a));
  }
  data->Mc.resize(J);
  data->M0.resize(J);
  for (int j = 0; j < J; ++j) {
    const Eigen::VectorXd d = Scale(ctx.design_thetas()[j]);
    for (int c = 0; c < C; ++c) {
      data->Mc[j].push_back(SubMatrix(d.asDiagonal() * M[c][j] * d.asDiagonal(), data->P));
    }
    data->M0[j] = j < static_cast<int>(prior.size()) && prior[j].size() > 0
                      ? SubMatrix(d.asDiagonal() * prior[j] * d.asDiagonal(), data->P)
                      : Eigen::MatrixXd::Zero(data->P.size(), data->P.size());
  }
  return data;
}

// M_j(w) = M_prior,j + N·Σ_c w_c·M_cj, with a ridge at the criteria's floor: finite values
// where some direction has weight 0.
Eigen::MatrixXd WeightedInformation(const WeightsData& data, int j, const double* w) {
  const int p = static_cast<int>(data.P.size());
  Eigen::MatrixXd Mw = data.M0[j] + kSingularFloor * Eigen::MatrixXd::Identity(p, p);
  for (int c = 0; c < data.num_candidates(); ++c) Mw += data.N * w[c] * data.Mc[j][c];
  return Mw;
}

// Every reached parameter but the nuisance m: the interest of the A and E criteria.
std::vector<int> InterestOf(const WeightsData& data) {
  std::vector<int> interest;
  for (int a = 0; a < static_cast<int>(data.P.size()); ++a) {
    if (std::find(data.nuisance.begin(), data.nuisance.end(), a) == data.nuisance.end()) {
      interest.push_back(a);
    }
  }
  return interest;
}

// log det M_j (D) or log det M_j − log det of its nuisance block (Ds), and, when J_phi_j is
// given, its gradient ∂/∂w_c = N·(tr(M⁻¹ M_c) − tr(M_nn⁻¹ M_c,nn)).
double LogDetCriterion(const WeightsData& data, int j, const Eigen::MatrixXd& Mw, double* J_phi_j) {
  const int p = static_cast<int>(data.P.size());
  const bool nuis = data.criterion == Criterion::kDs && !data.nuisance.empty();
  Eigen::LDLT<Eigen::MatrixXd> full(Mw);
  double v = full.vectorD().array().log().sum();
  Eigen::MatrixXd Mn;
  Eigen::LDLT<Eigen::MatrixXd> nn;
  if (nuis) {
    Mn = SubMatrix(Mw, data.nuisance);
    nn.compute(Mn);
    v -= nn.vectorD().array().log().sum();
  }
  if (J_phi_j) {
    const Eigen::MatrixXd Minv = full.solve(Eigen::MatrixXd::Identity(p, p));
    Eigen::MatrixXd Nninv;
    if (nuis) Nninv = nn.solve(Eigen::MatrixXd::Identity(Mn.rows(), Mn.cols()));
    for (int c = 0; c < data.num_candidates(); ++c) {
      double d = (Minv.cwiseProduct(data.Mc[j][c])).sum();
      if (nuis) d -= (Nninv.cwiseProduct(SubMatrix(data.Mc[j][c], data.nuisance))).sum();
      J_phi_j[c] = data.N * d;
    }
  }
  return v;
}

// The criterion at every design point (φ_j) and the constraint Σ w_c − 1 (g), with their
// gradients (row-major J_phi[j·C + c]; J_g) when asked.
bool EvaluateWeights(const WeightsData& data, const double* w, double* phi, double* g,
                     double* J_phi, double* J_g) {
  const int C = data.num_candidates();
  double sw = 0.0;
  for (int c = 0; c < C; ++c) sw += w[c];
  g[0] = sw - 1.0;
  if (J_g) std::fill(J_g, J_g + C, 1.0);
  for (int j = 0; j < static_cast<int>(data.Mc.size()); ++j) {
    const Eigen::MatrixXd Mw = WeightedInformation(data, j, w);
    if (data.criterion == Criterion::kA || data.criterion == Criterion::kE) {
      phi[j] = EvaluateCriterion(Mw, data.criterion, InterestOf(data)).value;
      continue;
    }
    phi[j] = LogDetCriterion(data, j, Mw, J_phi ? J_phi + j * C : nullptr);
  }
  return true;
}

}  // namespace

DesignProblem SteadyWeightsProblem(const DofPlanningProblem& ctx,
                                   const std::vector<std::vector<Eigen::MatrixXd>>& M, int N,
                                   const std::vector<Eigen::MatrixXd>& prior, Criterion criterion) {
  const int C = static_cast<int>(M.size());
  const std::shared_ptr<const WeightsData> data = MakeWeightsData(ctx, M, N, prior, criterion);
  DesignProblem p;
  p.num_variables = C;
  p.lower.assign(C, 0.0);
  p.upper.assign(C, 1.0);
  p.x0.assign(C, 1.0 / std::max(1, C));
  p.num_scenarios = static_cast<int>(ctx.design_thetas().size());
  p.num_constraints = 1;
  p.evaluate = [data](const double* w, double* phi, double* g) {
    return EvaluateWeights(*data, w, phi, g, nullptr, nullptr);
  };
  if (criterion == Criterion::kD || criterion == Criterion::kDs) {
    p.evaluate_with_gradient = [data](const double* w, double* phi, double* g, double* J_phi,
                                      double* J_g) {
      return EvaluateWeights(*data, w, phi, g, J_phi, J_g);
    };
  }
  return p;
}

std::vector<int> EfficientRounding(const std::vector<double>& w, int N) {
  const int C = static_cast<int>(w.size());
  std::vector<int> n(C, 0);
  if (N <= 0 || C == 0) return n;
  const double top = *std::max_element(w.begin(), w.end());
  if (!(top > 0)) return n;  // no support: nothing to apportion (all-zero or NaN weights)
  int p = 0;
  for (double x : w) p += x > 1e-3 * top ? 1 : 0;
  // n_c = ceil((N - p/2)·w_c) on the support, then the apportionment adjustments.
  const double sum = std::accumulate(w.begin(), w.end(), 0.0);
  for (int c = 0; c < C; ++c) {
    if (w[c] > 1e-3 * top) n[c] = static_cast<int>(std::ceil((N - 0.5 * p) * w[c] / sum));
  }
  int total = std::accumulate(n.begin(), n.end(), 0);
  while (total > N) {
    int best = -1;
    double best_r = -1.0;
    for (int c = 0; c < C; ++c) {
      if (n[c] == 0) continue;
      const double r = (n[c] - 1) / (w[c] / sum);
      if (r > best_r) {
        best_r = r;
        best = c;
      }
    }
    --n[best];
    --total;
  }
  while (total < N) {
    int best = -1;
    double best_r = std::numeric_limits<double>::infinity();
    for (int c = 0; c < C; ++c) {
      if (!(w[c] > 1e-3 * top)) continue;
      const double r = n[c] / (w[c] / sum);
      if (r < best_r) {
        best_r = r;
        best = c;
      }
    }
    ++n[best];
    ++total;
  }
  return n;
}

namespace internal {

// Step 3: efficient rounding of N·w; every direction with weight keeps a leg.
std::vector<SteadyLeg> ExactDesign(const std::vector<SteadyLeg>& candidates,
                                   const std::vector<double>& weights, int N) {
  std::vector<int> n = EfficientRounding(weights, N);
  const double wmax = *std::max_element(weights.begin(), weights.end());
  std::map<std::string, int> best_in_dir;  // direction -> candidate with the largest weight
  std::map<std::string, int> legs_in_dir;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const std::string key = DirName(candidates[c].mapping, candidates[c].force > 0 ? 1 : -1);
    if (weights[c] > 1e-3 * wmax &&
        (!best_in_dir.count(key) || weights[c] > weights[best_in_dir[key]])) {
      best_in_dir[key] = static_cast<int>(c);
    }
    legs_in_dir[key] += n[c];
  }
  for (const auto& [key, c] : best_in_dir) {
    if (legs_in_dir[key] == 0) ++n[c];
  }
  std::vector<SteadyLeg> legs;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    for (int k = 0; k < n[c]; ++k) legs.push_back(candidates[c]);
  }
  return legs;
}

}  // namespace internal

}  // namespace uuvplan::planner
