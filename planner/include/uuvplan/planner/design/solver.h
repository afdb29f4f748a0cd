// One small interface for the robust design problems and two backends behind it:
//
//   maximise   R(φ_1(x), ..., φ_J(x))     x in [lower, upper]  (design variables scaled to O(1))
//   subject to g_c(x) <= 0,  c = 1..C
//
// φ_j is the design criterion at the j-th point of the a priori box, R the robust aggregate:
// the worst case (maximin) min_j φ_j, the average (1/J)·Σ_j φ_j, or the nominal φ_1.
//
//   NLopt: a global search for multimodal, non-smooth criteria (DIRECT-L or MLSL on the
//          penalised aggregate: R(φ) - ρ·Σ_c max(0, g_c)²), then a local refinement (COBYLA,
//          derivative-free; SLSQP when gradients are given) on the epigraph form below.
//   Ipopt: the smooth constrained formulation. Maximin in epigraph form:
//          maximise t subject to φ_j(x) >= t for every box point j and g(x) <= 0;
//          average and nominal directly. Gradients are the problem's own or forward
//          differences; the Hessian is approximated by limited-memory BFGS.
//
// Both backends take the same DesignProblem, so tests run the same problems through both.
#pragma once

#include <functional>
#include <string>
#include <string_view>
#include <vector>

namespace uuvplan::planner {

enum class Robustness { kNominal, kMaximin, kAverage };
enum class SolverBackend { kNlopt, kIpopt };
enum class GlobalMethod { kNone, kDirectL, kMlsl };

std::string_view RobustnessName(Robustness r);
std::string_view SolverBackendName(SolverBackend b);

struct DesignProblem {
  int num_variables = 0;
  std::vector<double> lower, upper;  ///< bounds, O(1) scale
  std::vector<double> x0;            ///< starting point (local methods and Ipopt)
  int num_scenarios = 1;             ///< J: points of the box (criterion values per x)
  int num_constraints = 0;           ///< C: g_c(x) <= 0, scaled to O(1)
  /// Fills phi[J] and g[C] at x; returns false where the model cannot be evaluated.
  std::function<bool(const double* x, double* phi, double* g)> evaluate;
  /// Optional analytic gradients, row-major: J_phi[j·n + i] = ∂φ_j/∂x_i, J_g[c·n + i].
  std::function<bool(const double* x, double* phi, double* g, double* J_phi, double* J_g)>
      evaluate_with_gradient;
};

struct SolverOptions {
  Robustness robustness = Robustness::kMaximin;
  GlobalMethod global = GlobalMethod::kDirectL;  ///< NLopt only; kNone: local from x0
  int max_global_evaluations = 150;
  int max_local_evaluations = 200;
  int max_iterations = 200;          ///< Ipopt iterations
  double relative_tolerance = 1e-6;  ///< on the objective (NLopt) / Ipopt's tol
  double penalty = 1e3;              ///< ρ of the global phase's constraint penalty
  double fd_step = 1e-5;             ///< forward-difference step in x (O(1) variables)
  /// A local phase started from each of these points too (NLopt) after the global one.
  std::vector<std::vector<double>> extra_starts;

  bool IsValid(std::string* error) const;
};

enum class SolverStatus { kConverged, kMaxEvaluations, kInfeasible, kFailed };
std::string_view SolverStatusName(SolverStatus s);

struct [[nodiscard]] SolverSummary {
  SolverStatus status = SolverStatus::kFailed;
  std::string backend;
  std::string raw_status;  ///< the backend's own return code, as text
  std::string message;
  std::vector<double> x;
  double objective = 0.0;   ///< R(φ(x))
  std::vector<double> phi;  ///< φ_j(x)
  std::vector<double> g;    ///< g_c(x)
  double max_violation = 0.0;
  int evaluations = 0;

  bool is_success() const {
    return status == SolverStatus::kConverged || status == SolverStatus::kMaxEvaluations;
  }
  std::string BriefReport() const;
};

/// The robust aggregate R of `phi` (see above).
double Aggregate(Robustness r, const std::vector<double>& phi);

SolverSummary Solve(SolverBackend backend, const DesignProblem& problem,
                    const SolverOptions& options);
SolverSummary SolveWithNlopt(const DesignProblem& problem, const SolverOptions& options);
SolverSummary SolveWithIpopt(const DesignProblem& problem, const SolverOptions& options);

}  // namespace uuvplan::planner
