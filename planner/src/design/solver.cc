// The solver interface's common parts (see solver.h).
#include "uuvplan/planner/design/solver.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <sstream>

#include "options_check.h"
#include "uuvplan/model/util/enum_names.h"

namespace uuvplan::planner {

constexpr model::EnumNames<Robustness, 3> kRobustnessNames{{{{Robustness::kNominal, "nominal"},
                                                             {Robustness::kMaximin, "maximin"},
                                                             {Robustness::kAverage, "average"}}}};

std::string_view RobustnessName(Robustness r) { return kRobustnessNames.Name(r); }

std::string_view SolverBackendName(SolverBackend b) {
  return b == SolverBackend::kNlopt ? "nlopt" : "ipopt";
}

constexpr model::EnumNames<SolverStatus, 4> kSolverStatusNames{
    {{{SolverStatus::kConverged, "converged"},
      {SolverStatus::kMaxEvaluations, "max_evaluations"},
      {SolverStatus::kInfeasible, "infeasible"},
      {SolverStatus::kFailed, "failed"}}}};

std::string_view SolverStatusName(SolverStatus s) { return kSolverStatusNames.Name(s); }

bool SolverOptions::IsValid(std::string* error) const {
  internal::OptionsCheck check("SolverOptions", error);
  check
      .Require(max_global_evaluations >= 0, "max_global_evaluations", max_global_evaluations,
               ">= 0")
      .Require(max_local_evaluations >= 1, "max_local_evaluations", max_local_evaluations, ">= 1")
      .Require(relative_tolerance > 0, "relative_tolerance", relative_tolerance, "> 0")
      .Require(fd_step > 0 && fd_step < 0.1, "fd_step", fd_step, "0 < fd_step < 0.1")
      .Require(penalty >= 0, "penalty", penalty, ">= 0");
  return check.ok();
}

double Aggregate(Robustness r, const std::vector<double>& phi) {
  if (phi.empty()) return -std::numeric_limits<double>::infinity();
  switch (r) {
    case Robustness::kNominal:
      return phi.front();
    case Robustness::kMaximin:
      return *std::min_element(phi.begin(), phi.end());
    case Robustness::kAverage:
      return std::accumulate(phi.begin(), phi.end(), 0.0) / static_cast<double>(phi.size());
  }
  return phi.front();
}

std::string SolverSummary::BriefReport() const {
  std::ostringstream s;
  s << backend << ": " << SolverStatusName(status) << " (" << raw_status << "), objective "
    << objective << ", " << evaluations << " evaluations";
  if (max_violation > 0) s << ", max violation " << max_violation;
  if (!message.empty()) s << "; " << message;
  return s.str();
}

SolverSummary Solve(SolverBackend backend, const DesignProblem& problem,
                    const SolverOptions& options) {
  return backend == SolverBackend::kNlopt ? SolveWithNlopt(problem, options)
                                          : SolveWithIpopt(problem, options);
}

}  // namespace uuvplan::planner
