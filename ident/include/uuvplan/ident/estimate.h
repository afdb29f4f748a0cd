// A parameter estimate as every estimator reports it: value, 1σ, percentile error and
// significance (ref 000 §III-A, §IV-D), and whether it was dropped by model selection.
#pragma once

#include <Eigen/Dense>
#include <limits>
#include <string>
#include <vector>

namespace uuvplan::ident {

enum class ParameterState {
  kEstimated,  ///< estimated by this estimator
  kDropped,    ///< insignificant (percentile error > 51.02%), fixed to 0 and the rest refitted
  kFixed,      ///< held at a given value (known from an earlier stage, or not excited)
};
std::string_view ParameterStateName(ParameterState s);

struct ParameterEstimate {
  std::string name;
  double value = 0.0;  ///< value used by the model (0 when dropped)
  double sigma = std::numeric_limits<double>::quiet_NaN();
  ParameterState state = ParameterState::kEstimated;
  bool significant = true;
  /// For dropped parameters: the estimate and σ of the last fit that still had them.
  double value_before_drop = 0.0;
  double sigma_before_drop = std::numeric_limits<double>::quiet_NaN();

  /// 100·σ/|θ| (of the fit that had the parameter).
  double percentile_error() const;
};

/// Estimates for `names` from theta and its covariance (σ = √diag); `state` per parameter.
std::vector<ParameterEstimate> MakeEstimates(const std::vector<std::string>& names,
                                             const Eigen::VectorXd& theta,
                                             const Eigen::MatrixXd& covariance,
                                             const std::vector<ParameterState>& state);

/// Index of `name` in `estimates`, or -1.
int FindEstimate(const std::vector<ParameterEstimate>& estimates, const std::string& name);

}  // namespace uuvplan::ident
