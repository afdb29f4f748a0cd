// Model selection by significance (ref 000 §IV-D), shared by the steady-state and the
// output-error fits: drop the prunable parameter with the largest percentile error above
// 51.02% and refit, until every prunable parameter is significant.
#pragma once

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "uuvplan/ident/estimate.h"
#include "uuvplan/ident/stats/model_selection_options.h"

namespace uuvplan::ident {

/// A parameter that model selection may drop: its name, estimate and σ in the current fit,
/// and its largest |correlation| with another parameter of that fit (LargestCorrelations).
struct PruneCandidate {
  const std::string& name;
  double value, sigma;
  double correlation = 0.0;
};

/// For each parameter of a covariance (any order), the largest |correlation| with another.
std::vector<double> LargestCorrelations(const Eigen::MatrixXd& covariance);

/// The candidates of a fit in the model's layout: the parameters `free` (indices into `names`,
/// `theta` and `covariance`), each with its σ and its largest |correlation| among them.
std::vector<PruneCandidate> CandidatesOf(const std::vector<std::string>& names,
                                         const Eigen::VectorXd& theta,
                                         const Eigen::MatrixXd& covariance,
                                         const std::vector<int>& free);

/// The index in `candidates` of the parameter to drop, or -1: the one named in `prunable`
/// with the largest percentile error above 51.02% (first of equals), never the last drag term
/// among the candidates (a model without drag has no steady state), nor one correlated with
/// another above `max_correlation` (kDropCorrelation; 1: ref 000's rule, any) unless it is a
/// negative drag term (non-physical: fixed at its bound 0). *worst_pe is set to its
/// percentile error. `kept`, when given, gets a note for every insignificant parameter kept
/// for its correlation.
int WorstInsignificant(const std::vector<PruneCandidate>& candidates,
                       const std::vector<std::string>& prunable, double max_correlation,
                       double* worst_pe, std::vector<std::string>* kept = nullptr);
/// As above, among `selection`'s prunable parameters at its drop correlation.
inline int WorstInsignificant(const std::vector<PruneCandidate>& candidates,
                              const ModelSelectionOptions& selection, double* worst_pe,
                              std::vector<std::string>* kept = nullptr) {
  return WorstInsignificant(candidates, selection.prunable, selection.drop_correlation, worst_pe,
                            kept);
}

/// The estimated and dropped parameters (fixed ones left out) of a fit, dropped ones with the
/// value and σ they had in the last fit that still had them.
std::vector<ParameterEstimate> EstimatedAndDropped(const std::vector<std::string>& names,
                                                   const Eigen::VectorXd& theta,
                                                   const Eigen::MatrixXd& covariance,
                                                   const std::vector<ParameterState>& state,
                                                   const std::vector<double>& value_before_drop,
                                                   const std::vector<double>& sigma_before_drop);

}  // namespace uuvplan::ident
