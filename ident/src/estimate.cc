#include "uuvplan/ident/estimate.h"

#include <cmath>

#include "uuvplan/ident/stats/significance.h"
#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::ident {

std::string_view ParameterStateName(ParameterState s) {
  static constexpr model::EnumNames<ParameterState, 3> kNames{{{
      {ParameterState::kEstimated, "estimated"},
      {ParameterState::kDropped, "dropped"},
      {ParameterState::kFixed, "fixed"},
  }}};
  return kNames.Name(s);
}

double ParameterEstimate::percentile_error() const {
  if (state == ParameterState::kDropped)
    return PercentileError(value_before_drop, sigma_before_drop);
  return PercentileError(value, sigma);
}

std::vector<ParameterEstimate> MakeEstimates(const std::vector<std::string>& names,
                                             const Eigen::VectorXd& theta,
                                             const Eigen::MatrixXd& cov,
                                             const std::vector<ParameterState>& state) {
  std::vector<ParameterEstimate> out(names.size());
  for (std::size_t i = 0; i < names.size(); ++i) {
    ParameterEstimate& e = out[i];
    e.name = names[i];
    e.value = theta[i];
    e.state = i < state.size() ? state[i] : ParameterState::kEstimated;
    e.sigma = e.state == ParameterState::kEstimated ? std::sqrt(std::max(0.0, cov(i, i)))
                                                    : std::numeric_limits<double>::quiet_NaN();
    e.significant = e.state == ParameterState::kEstimated && IsSignificant(e.value, e.sigma);
  }
  return out;
}

int FindEstimate(const std::vector<ParameterEstimate>& estimates, const std::string& name) {
  for (std::size_t i = 0; i < estimates.size(); ++i) {
    if (estimates[i].name == name) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace uuvplan::ident
