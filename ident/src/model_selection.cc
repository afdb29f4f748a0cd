#include "model_selection.h"

#include <algorithm>

#include "drag_parameter.h"
#include "uuvplan/ident/significance.h"

namespace uuvplan::ident {

int WorstInsignificant(const std::vector<PruneCandidate>& candidates,
                       const std::vector<std::string>& prunable, double* worst_pe) {
  const auto drag_terms = std::count_if(candidates.begin(), candidates.end(),
                                        [](const PruneCandidate& c) { return IsDragParameter(c.name); });
  int worst = -1;
  *worst_pe = kInsignificantPercentileError;
  for (std::size_t c = 0; c < candidates.size(); ++c) {
    const PruneCandidate& p = candidates[c];
    if (std::find(prunable.begin(), prunable.end(), p.name) == prunable.end()) continue;
    if (IsDragParameter(p.name) && drag_terms <= 1) continue;
    const double pe = PercentileError(p.value, p.sigma);
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
