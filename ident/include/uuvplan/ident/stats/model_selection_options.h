// Model selection by significance (ref 000 §IV-D), as every estimator that prunes runs it:
// while a parameter of `prunable` is insignificant (percentile error above 51.02%), the worst
// is dropped (held at 0) and the fit repeated; one correlated with another above
// `drop_correlation` is kept instead, with a note (the rule's details: model_selection.h's
// WorstInsignificant, significance.h).
#pragma once

#include <string>
#include <vector>

#include "uuvplan/ident/stats/significance.h"

namespace uuvplan::ident {

struct ModelSelectionOptions {
  bool prune_insignificant = true;
  /// An insignificant parameter correlated with another above this is kept (significance.h);
  /// kSeedDropCorrelation: ref 000's own rule, dropped whatever the correlation.
  double drop_correlation = kDropCorrelation;
  std::vector<std::string> prunable = {"k", "kq", "bias", "bias_step"};
};

}  // namespace uuvplan::ident
