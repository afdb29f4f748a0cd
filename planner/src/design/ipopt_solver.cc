// Ipopt backend of the design solver (see solver.h): the smooth constrained formulation.
// Maximin in epigraph form, variables z = (x, t):
//   minimise -t   subject to  φ_j(x) - t >= 0 (j = 1..J),  g_c(x) <= 0,  lower <= x <= upper.
// Average / nominal: minimise -R(φ(x)) subject to g(x) <= 0. Limited-memory BFGS Hessian;
// gradients from the problem or forward differences (design_evaluator.h). Debian's Ipopt 3.11
// has MUMPS only; the design variables are already O(1) (notes/toolchain.md).
#include <IpIpoptApplication.hpp>
#include <IpTNLP.hpp>
#include <algorithm>
#include <cmath>
#include <string>

#include "design/design_evaluator.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/planner/design/solver.h"

namespace uuvplan::planner {
namespace {

using internal::DesignEvaluator;
using Ipopt::Index;
using Ipopt::Number;

class DesignNlp final : public Ipopt::TNLP {
 public:
  DesignNlp(const DesignProblem& p, const SolverOptions& o, DesignEvaluator* ev)
      : p_(p), o_(o), ev_(ev), epigraph_(o.robustness == Robustness::kMaximin) {}

  bool get_nlp_info(Index& n, Index& m, Index& nnz_jac_g, Index& nnz_h_lag,
                    IndexStyleEnum& index_style) override {
    n = nz();
    m = ncons();
    nnz_jac_g = n * m;
    nnz_h_lag = 0;
    index_style = C_STYLE;
    return true;
  }

  bool get_bounds_info(Index n, Number* x_l, Number* x_u, Index m, Number* g_l,
                       Number* g_u) override {
    for (int i = 0; i < p_.num_variables; ++i) {
      x_l[i] = p_.lower[i];
      x_u[i] = p_.upper[i];
    }
    if (epigraph_) {
      x_l[n - 1] = -2e19;
      x_u[n - 1] = 2e19;
    }
    int r = 0;
    if (epigraph_) {
      for (int j = 0; j < p_.num_scenarios; ++j, ++r) {
        g_l[r] = 0.0;
        g_u[r] = 2e19;
      }
    }
    for (int c = 0; c < p_.num_constraints; ++c, ++r) {
      g_l[r] = -2e19;
      g_u[r] = 0.0;
    }
    (void)m;
    return true;
  }

  bool get_starting_point(Index n, bool init_x, Number* x, bool, Number*, Number*, Index, bool,
                          Number*) override {
    if (!init_x) return true;
    for (int i = 0; i < p_.num_variables; ++i) {
      x[i] = std::min(p_.upper[i], std::max(p_.lower[i], p_.x0[i]));
    }
    if (epigraph_) {
      const double *phi, *g;
      if (!ev_->Values(x, &phi, &g)) return false;
      x[n - 1] = *std::min_element(phi, phi + p_.num_scenarios) - 1e-3;
    }
    return true;
  }

  bool eval_f(Index n, const Number* x, bool, Number& obj) override {
    if (epigraph_) {
      obj = -x[n - 1];
      return true;
    }
    const double *phi, *g;
    if (!ev_->Values(x, &phi, &g)) return false;
    obj = -Aggregate(o_.robustness, std::vector<double>(phi, phi + p_.num_scenarios));
    return std::isfinite(obj);
  }

  bool eval_grad_f(Index n, const Number* x, bool, Number* grad) override {
    std::fill(grad, grad + n, 0.0);
    if (epigraph_) {
      grad[n - 1] = -1.0;
      return true;
    }
    const double *Jp, *Jg;
    if (!ev_->Gradients(x, &Jp, &Jg)) return false;
    const int nx = p_.num_variables, J = p_.num_scenarios;
    for (int i = 0; i < nx; ++i) {
      if (o_.robustness == Robustness::kAverage) {
        for (int j = 0; j < J; ++j) grad[i] -= Jp[j * nx + i] / J;
      } else {
        grad[i] = -Jp[i];
      }
    }
    return true;
  }

  bool eval_g(Index n, const Number* x, bool, Index m, Number* out) override {
    const double *phi, *g;
    if (!ev_->Values(x, &phi, &g)) return false;
    int r = 0;
    if (epigraph_) {
      for (int j = 0; j < p_.num_scenarios; ++j) out[r++] = phi[j] - x[n - 1];
    }
    for (int c = 0; c < p_.num_constraints; ++c) out[r++] = g[c];
    (void)m;
    return true;
  }

  bool eval_jac_g(Index n, const Number* x, bool, Index m, Index, Index* iRow, Index* jCol,
                  Number* values) override {
    if (!values) {
      int k = 0;
      for (int r = 0; r < m; ++r) {
        for (int i = 0; i < n; ++i, ++k) {
          iRow[k] = r;
          jCol[k] = i;
        }
      }
      return true;
    }
    const double *Jp, *Jg;
    if (!ev_->Gradients(x, &Jp, &Jg)) return false;
    const int nx = p_.num_variables;
    std::fill(values, values + n * m, 0.0);
    int r = 0;
    if (epigraph_) {
      for (int j = 0; j < p_.num_scenarios; ++j, ++r) {
        for (int i = 0; i < nx; ++i) values[r * n + i] = Jp[j * nx + i];
        values[r * n + n - 1] = -1.0;
      }
    }
    for (int c = 0; c < p_.num_constraints; ++c, ++r) {
      for (int i = 0; i < nx; ++i) values[r * n + i] = Jg[c * nx + i];
    }
    return true;
  }

  void finalize_solution(Ipopt::SolverReturn status, Index, const Number*, const Number*,
                         const Number*, Index, const Number*, const Number*, Number,
                         const Ipopt::IpoptData*, Ipopt::IpoptCalculatedQuantities*) override {
    status_ = status;
  }

  Ipopt::SolverReturn status() const { return status_; }

 private:
  int nz() const { return p_.num_variables + (epigraph_ ? 1 : 0); }
  int ncons() const { return (epigraph_ ? p_.num_scenarios : 0) + p_.num_constraints; }

  const DesignProblem& p_;
  const SolverOptions& o_;
  DesignEvaluator* ev_;
  bool epigraph_;
  Ipopt::SolverReturn status_ = Ipopt::UNASSIGNED;
};

// Ipopt's names of its solver returns; the others by number (RETURN(n)).
constexpr model::EnumNames<Ipopt::SolverReturn, 8> kReturnNames{
    {{{Ipopt::SUCCESS, "SUCCESS"},
      {Ipopt::MAXITER_EXCEEDED, "MAXITER_EXCEEDED"},
      {Ipopt::STOP_AT_TINY_STEP, "STOP_AT_TINY_STEP"},
      {Ipopt::STOP_AT_ACCEPTABLE_POINT, "STOP_AT_ACCEPTABLE_POINT"},
      {Ipopt::LOCAL_INFEASIBILITY, "LOCAL_INFEASIBILITY"},
      {Ipopt::RESTORATION_FAILURE, "RESTORATION_FAILURE"},
      {Ipopt::ERROR_IN_STEP_COMPUTATION, "ERROR_IN_STEP_COMPUTATION"},
      {Ipopt::INVALID_NUMBER_DETECTED, "INVALID_NUMBER_DETECTED"}}}};

}  // namespace

SolverSummary SolveWithIpopt(const DesignProblem& p, const SolverOptions& o) {
  SolverSummary s;
  if (!internal::StartSummary("ipopt", o, &s)) return s;
  DesignEvaluator ev(p, o);
  Ipopt::SmartPtr<DesignNlp> nlp = new DesignNlp(p, o, &ev);
  Ipopt::SmartPtr<Ipopt::IpoptApplication> app = IpoptApplicationFactory();
  app->Options()->SetStringValue("sb", "yes");
  app->Options()->SetIntegerValue("print_level", 0);
  app->Options()->SetStringValue("hessian_approximation", "limited-memory");
  app->Options()->SetStringValue("mu_strategy", "adaptive");
  app->Options()->SetNumericValue("tol", o.relative_tolerance);
  app->Options()->SetNumericValue("acceptable_tol", 1e3 * o.relative_tolerance);
  app->Options()->SetIntegerValue("max_iter", o.max_iterations);
  if (app->Initialize() != Ipopt::Solve_Succeeded) {
    s.message = "Ipopt failed to initialise";
    return s;
  }
  const Ipopt::ApplicationReturnStatus rs = app->OptimizeTNLP(Ipopt::SmartPtr<Ipopt::TNLP>(nlp));
  s.raw_status = kReturnNames.NameOrNumber(nlp->status(), "RETURN") + " (application status " +
                 std::to_string(static_cast<int>(rs)) + ")";
  switch (nlp->status()) {
    case Ipopt::SUCCESS:
    case Ipopt::STOP_AT_ACCEPTABLE_POINT:
    case Ipopt::STOP_AT_TINY_STEP:
      s.status = SolverStatus::kConverged;
      break;
    case Ipopt::MAXITER_EXCEEDED:
      s.status = SolverStatus::kMaxEvaluations;
      break;
    case Ipopt::LOCAL_INFEASIBILITY:
      s.status = SolverStatus::kInfeasible;
      break;
    default:
      s.status = SolverStatus::kFailed;
      break;
  }
  internal::FillFromBest(ev, &s);
  if (s.status == SolverStatus::kFailed && ev.has_best() && s.max_violation <= 1e-7) {
    // Ipopt stopped on a numerical difficulty; the best feasible design it evaluated stands.
    s.status = SolverStatus::kConverged;
    s.message = "Ipopt stopped with " + s.raw_status + "; best feasible evaluated design kept";
  }
  return s;
}

}  // namespace uuvplan::planner
