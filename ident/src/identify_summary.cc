// The summary of an identification (Ceres' Solver::Summary is the model): status, stage
// timings, one line per DOF, as a one-line Brief() and a few-line Full() text.
#include <cstdio>

#include "uuvplan/ident/identify.h"

namespace uuvplan::ident {
namespace {

std::string Seconds(double s) {
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.3f s", s);
  return buffer;
}

}  // namespace

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

double IdentifySummary::total_seconds() const {
  double total = 0.0;
  for (const StageTime& t : stages) total += t.seconds;
  return total;
}

std::string IdentifySummary::Brief() const {
  std::string out = "identify: " + std::string(IdentifyStatusName(status)) + ", " +
                    std::to_string(dofs.size()) + " DOF(s) from " + std::to_string(num_trials) +
                    " trial(s) in " + Seconds(total_seconds());
  std::string per_dof;
  for (const DofLine& d : dofs) {
    per_dof += (per_dof.empty() ? "" : ", ") + std::string(model::DofName(d.dof)) + " " +
               std::string(FinalEstimatorName(d.estimator));
  }
  return per_dof.empty() ? out : out + " (" + per_dof + ")";
}

std::string IdentifySummary::Full() const {
  std::string out = Brief() + "\n";
  out += message.empty() ? "" : "  " + message + "\n";
  out += "  stages:";
  for (const StageTime& t : stages) out += " " + t.stage + " " + Seconds(t.seconds) + ";";
  out += "\n";
  for (const DofLine& d : dofs) {
    out += "  " + std::string(model::DofName(d.dof)) + ": " +
           std::string(IdentifyStatusName(d.status)) + ", " + std::to_string(d.num_parameters) +
           " parameter(s) from " + std::to_string(d.num_fit_trials) + " fit and " +
           std::to_string(d.num_validate_trials) + " validate trial(s), " +
           std::to_string(d.num_warnings) + " warning(s); " + d.message + "\n";
  }
  return out;
}

}  // namespace uuvplan::ident
