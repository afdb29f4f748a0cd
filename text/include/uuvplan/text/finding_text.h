// What a diagnosis finding means, in words: one sentence per effect of the effect table
// (model/effects.h), keyed by the effect's name, quoting the finding's estimates and where the
// standard model's free-run simulation goes wrong (its error breakdown). An effect registered
// from outside the library gives its sentence through ScopedFindingSentence; one without a
// sentence reads as its table entry's physics.
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "uuvplan/ident/diagnosis/diagnosis.h"

namespace uuvplan::text {

/// What a finding's sentence may quote: the extension's parameters (final estimates, σ 0 for
/// one held at its admissible bound), the breakdown of the finding's DOF and the proposal's
/// detail (the coupling's velocity letters).
struct FindingQuotes {
  const std::vector<ident::ParameterEstimate>& params;
  const model::ErrorBreakdown& breakdown;
  const std::string& detail;
};

using FindingSentenceRule = std::function<std::string(const FindingQuotes&)>;

/// Gives effect `effect` the sentence `rule` for the lifetime of the object (an effect
/// registered through model::ScopedEffect).
class ScopedFindingSentence {
 public:
  ScopedFindingSentence(std::string effect, FindingSentenceRule rule);
  ~ScopedFindingSentence();
  ScopedFindingSentence(const ScopedFindingSentence&) = delete;
  ScopedFindingSentence& operator=(const ScopedFindingSentence&) = delete;

 private:
  std::string effect_;
};

/// The breakdown's time shift in one convention for every lag and delay printed: positive means
/// the measurement comes later; the words say which way ("measured velocity lags the standard
/// model's simulation by 0.082 ± 0.0031 s", "… leads … by …"), the number is its size.
std::string MeasuredShiftText(const model::ErrorBreakdown& breakdown);

/// What the standard simulation gets wrong that `finding` explains, from `breakdown` (its
/// DOF's); a thrust_map finding adds each mapping's delivered thrust against the command.
std::string FindingSentence(const ident::Finding& finding, const model::ErrorBreakdown& breakdown);

/// The same, with the breakdown of the finding's DOF in `result`.
std::string FindingSentence(const ident::DiagnosisResult& result, const ident::Finding& finding);

}  // namespace uuvplan::text
