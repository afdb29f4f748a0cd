// The shared result shape of the staged pipelines (summary.h).
#include "uuvplan/ident/summary.h"

#include "uuvplan/model/util/text.h"

namespace uuvplan::ident {
namespace {

std::string Seconds(double s) { return model::Decimals(s, 3) + " s"; }

}  // namespace

StageClock::StageClock(const std::vector<std::string>& stages) {
  for (const std::string& s : stages) times_.push_back({s, 0.0});
}

void StageClock::Lap(const std::string& stage) {
  const double s = watch_.Lap();
  for (StageTime& t : times_) {
    if (t.stage == stage) {
      t.seconds += s;
      return;
    }
  }
  times_.push_back({stage, s});
}

double PipelineSummary::total_seconds() const {
  double total = 0.0;
  for (const StageTime& t : stages) total += t.seconds;
  return total;
}

std::string PipelineSummary::Brief() const {
  std::string out = pipeline + ": " + status + ", " + std::to_string(dofs.size()) +
                    " DOF(s) from " + std::to_string(num_trials) + " trial(s) in " +
                    Seconds(total_seconds());
  std::string per_dof;
  for (const DofLine& d : dofs) {
    per_dof += (per_dof.empty() ? "" : ", ") + std::string(model::DofName(d.dof)) + " " + d.brief;
  }
  return per_dof.empty() ? out : out + " (" + per_dof + ")";
}

std::string PipelineSummary::Full() const {
  std::string out = Brief() + "\n";
  out += message.empty() ? "" : "  " + message + "\n";
  out += "  stages:";
  for (const StageTime& t : stages) out += " " + t.stage + " " + Seconds(t.seconds) + ";";
  out += "\n";
  for (const DofLine& d : dofs) {
    out += "  " + std::string(model::DofName(d.dof)) + ": " + d.detail + "\n";
  }
  return out;
}

}  // namespace uuvplan::ident
