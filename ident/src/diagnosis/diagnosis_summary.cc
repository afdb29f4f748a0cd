// The summary of a diagnosis in the pipelines' shared shape (summary.h): status, the stage
// timings of the driver, per DOF the effects found with their held-out gain.
#include <algorithm>

#include "uuvplan/ident/diagnosis/diagnosis.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {
namespace {

bool Diagnosed(const DiagnosisResult& r, model::Dof dof) {
  return std::any_of(r.extended.begin(), r.extended.end(),
                     [&](const DofIdentification& e) { return e.dof == dof; });
}

// "thrust_asymmetry (held-out gain 3.12% on validate)".
std::string FindingText(const Finding& f) {
  return f.effect + " (held-out gain " + model::Significant(100.0 * f.gain.relative, 3) + "% on " +
         f.gain.on + ")";
}

PipelineSummary::DofLine DofLineOf(const DiagnosisResult& r, model::Dof dof) {
  if (!Diagnosed(r, dof)) {
    const auto why = r.not_diagnosed.find(dof);
    return {dof, "not diagnosed",
            "not diagnosed: " +
                (why != r.not_diagnosed.end() ? why->second : std::string("no breakdown"))};
  }
  std::string effects, details;
  int n = 0;
  for (const Finding& f : r.findings) {
    if (f.dof != dof) continue;
    effects += (effects.empty() ? "" : "+") + f.effect;
    details += (details.empty() ? "" : ", ") + FindingText(f);
    ++n;
  }
  if (n == 0) return {dof, "none", "no effect found"};
  return {dof, effects, std::to_string(n) + " effect(s): " + details};
}

}  // namespace

PipelineSummary DiagnosisResult::Summary() const {
  PipelineSummary s{"diagnose", "", "", static_cast<int>(nominal.trials.size()), timing, {}};
  bool any_diagnosed = false;
  for (model::Dof dof : dofs) {
    any_diagnosed = any_diagnosed || Diagnosed(*this, dof);
    s.dofs.push_back(DofLineOf(*this, dof));
  }
  s.status = !not_diagnosed.empty() ? "failed" : findings.empty() ? "none" : "findings";
  if (!any_diagnosed) {
    s.message = "no DOF could be diagnosed";
  } else if (!not_diagnosed.empty()) {
    s.message = std::to_string(not_diagnosed.size()) + " DOF(s) not diagnosed";
  } else if (!warnings.empty()) {
    s.message = std::to_string(warnings.size()) + " warning(s) beside the findings";
  }
  return s;
}

}  // namespace uuvplan::ident
