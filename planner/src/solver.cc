// The solver interface's common parts (see solver.h).
#include "uuvplan/planner/solver.h"

#include <algorithm>
#include <limits>
#include <numeric>
#include <sstream>

namespace uuvplan::planner {

std::string_view RobustnessName(Robustness r) {
  switch (r) {
    case Robustness::kNominal:
      return "nominal";
    case Robustness::kMaximin:
      return "maximin";
    case Robustness::kAverage:
      return "average";
  }
  return "maximin";
}

std::string_view SolverBackendName(SolverBackend b) {
  return b == SolverBackend::kNlopt ? "nlopt" : "ipopt";
}

std::string_view SolverStatusName(SolverStatus s) {
  switch (s) {
    case SolverStatus::kConverged:
      return "converged";
    case SolverStatus::kMaxEvaluations:
      return "max_evaluations";
    case SolverStatus::kInfeasible:
      return "infeasible";
    case SolverStatus::kFailed:
      return "failed";
  }
  return "failed";
}

bool SolverOptions::IsValid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error) *error = m;
    return false;
  };
  if (max_global_evaluations < 0) {
    return fail("SolverOptions::max_global_evaluations = " +
                std::to_string(max_global_evaluations) + ". Violated constraint: >= 0");
  }
  if (max_local_evaluations < 1) {
    return fail("SolverOptions::max_local_evaluations = " + std::to_string(max_local_evaluations) +
                ". Violated constraint: >= 1");
  }
  if (!(relative_tolerance > 0)) {
    return fail("SolverOptions::relative_tolerance = " + std::to_string(relative_tolerance) +
                ". Violated constraint: > 0");
  }
  if (!(fd_step > 0 && fd_step < 0.1)) {
    return fail("SolverOptions::fd_step = " + std::to_string(fd_step) +
                ". Violated constraint: 0 < fd_step < 0.1");
  }
  if (!(penalty >= 0)) {
    return fail("SolverOptions::penalty = " + std::to_string(penalty) +
                ". Violated constraint: >= 0");
  }
  return true;
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
