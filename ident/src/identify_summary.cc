// The summary of an identification (Ceres' Solver::Summary is the model): status, stage
// timings, one line per DOF, in the pipelines' shared shape (summary.h).
#include "uuvplan/ident/identify.h"

namespace uuvplan::ident {

IdentifySummary IdentifyResult::Summary() const {
  IdentifySummary s;
  s.status = status;
  s.message = message;
  s.num_trials = static_cast<int>(trials.size());
  for (const char* stage : {"prepare", "estimate", "refine", "validate"}) {
    s.stages.push_back({stage, 0.0});
  }
  for (const DofIdentification& d : dofs) {
    for (const StageTime& t : d.timing) {
      for (StageTime& total : s.stages) {
        if (total.stage == t.stage) total.seconds += t.seconds;
      }
    }
    s.dofs.push_back({d.dof, d.status, d.estimator, static_cast<int>(d.parameter_names.size()),
                      static_cast<int>(d.fit_trials.size()),
                      static_cast<int>(d.validate_trials.size()),
                      static_cast<int>(d.warnings.size()), d.message});
  }
  return s;
}

PipelineSummary IdentifySummary::Shape() const {
  PipelineSummary s{
      "identify", std::string(IdentifyStatusName(status)), message, num_trials, stages, {}};
  for (const DofLine& d : dofs) {
    s.dofs.push_back({d.dof, std::string(FinalEstimatorName(d.estimator)),
                      std::string(IdentifyStatusName(d.status)) + ", " +
                          std::to_string(d.num_parameters) + " parameter(s) from " +
                          std::to_string(d.num_fit_trials) + " fit and " +
                          std::to_string(d.num_validate_trials) + " validate trial(s), " +
                          std::to_string(d.num_warnings) + " warning(s); " + d.message});
  }
  return s;
}

}  // namespace uuvplan::ident
