#include "stats/model_selection.h"

#include <algorithm>
#include <cmath>

#include "drag_parameter.h"
#include "uuvplan/ident/stats/significance.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {

std::vector<double> LargestCorrelations(const Eigen::MatrixXd& covariance) {
  const Eigen::Index n = covariance.rows();
  std::vector<double> out(n, 0.0);
  for (Eigen::Index i = 0; i < n; ++i) {
    for (Eigen::Index k = 0; k < n; ++k) {
      const double scale = std::sqrt(covariance(i, i) * covariance(k, k));
      if (k == i || !(scale > 0)) continue;
      out[i] = std::max(out[i], std::abs(covariance(i, k)) / scale);
    }
  }
  return out;
}

std::vector<PruneCandidate> CandidatesOf(const std::vector<std::string>& names,
                                         const Eigen::VectorXd& theta,
                                         const Eigen::MatrixXd& covariance,
                                         const std::vector<int>& free) {
  const std::vector<double> correlation = LargestCorrelations(covariance(free, free));
  std::vector<PruneCandidate> out;
  for (std::size_t i = 0; i < free.size(); ++i) {
    const int j = free[i];
    out.push_back({names[j], theta[j], std::sqrt(covariance(j, j)), correlation[i]});
  }
  return out;
}

int WorstInsignificant(const std::vector<PruneCandidate>& candidates,
                       const std::vector<std::string>& prunable, double max_correlation,
                       double* worst_pe, std::vector<std::string>* kept) {
  const auto drag_terms =
      std::count_if(candidates.begin(), candidates.end(),
                    [](const PruneCandidate& c) { return IsDragParameter(c.name); });
  int worst = -1;
  *worst_pe = kInsignificantPercentileError;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const PruneCandidate& p = candidates[c];
    if (std::find(prunable.begin(), prunable.end(), p.name) == prunable.end()) continue;
    if (IsDragParameter(p.name) && drag_terms <= 1) continue;
    const double pe = PercentileError(p.value, p.sigma);
    if (!(pe > kInsignificantPercentileError)) continue;
    const bool non_physical = IsDragParameter(p.name) && p.value < 0;
    if (p.correlation > max_correlation && !non_physical) {
      if (kept) {
        kept->push_back(p.name + " = " + model::Significant(p.value, 4) + " ± " +
                        model::Significant(p.sigma, 4) +
                        " is insignificant but kept: correlated at " +
                        model::Decimals(p.correlation, 2) +
                        " with another parameter, so dropping it would report that one's σ as if " +
                        p.name + " were exactly 0 (model selection, docs/identification.md)");
      }
      continue;
    }
    if (pe > *worst_pe) {
      *worst_pe = pe;
      worst = static_cast<int>(c);
    }
  }
  return worst;
}

std::vector<ParameterEstimate> EstimatedAndDropped(const std::vector<std::string>& names,
                                                   const Eigen::VectorXd& theta,
                                                   const Eigen::MatrixXd& covariance,
                                                   const std::vector<ParameterState>& state,
                                                   const std::vector<double>& value_before_drop,
                                                   const std::vector<double>& sigma_before_drop) {
  std::vector<ParameterEstimate> all = MakeEstimates(names, theta, covariance, state);
  std::vector<ParameterEstimate> out;
  for (std::size_t j = 0; j < all.size(); ++j) {
    if (state[j] == ParameterState::kFixed) continue;
    if (state[j] == ParameterState::kDropped) {
      all[j].value_before_drop = value_before_drop[j];
      all[j].sigma_before_drop = sigma_before_drop[j];
      all[j].significant = false;
    }
    out.push_back(all[j]);
  }
  return out;
}

}  // namespace uuvplan::ident
