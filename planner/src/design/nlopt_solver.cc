// NLopt backend of the design solver (see solver.h): a global phase on the penalised robust
// aggregate (DIRECT-L, or MLSL with BOBYQA as its local method), then a local phase on the
// epigraph form of maximin (COBYLA derivative-free; SLSQP when the problem gives gradients).
#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <nlopt.hpp>

#include "design/design_evaluator.h"
#include "uuvplan/model/util/enum_names.h"
#include "uuvplan/planner/design/solver.h"

namespace uuvplan::planner {
namespace {

using internal::DesignEvaluator;

// What NLopt hands each objective and constraint callback through its void* data.
struct ObjectiveData {
  DesignEvaluator* ev;
  const SolverOptions* opt;
  const DesignProblem* p;
};

// Global phase objective: R(φ(x)) - ρ·Σ max(0, g_c)², a very poor value where the model fails.
double PenalisedObjective(unsigned n, const double* x, double* grad, void* data) {
  (void)n;
  (void)grad;  // derivative-free global methods only
  auto* c = static_cast<ObjectiveData*>(data);
  const double *phi, *g;
  if (!c->ev->Values(x, &phi, &g)) return -1e10;
  std::vector<double> v(phi, phi + c->ev->J());
  double f = Aggregate(c->opt->robustness, v);
  for (int k = 0; k < c->ev->C(); ++k) {
    const double e = std::max(0.0, g[k]);
    f -= c->opt->penalty * e * e;
  }
  return std::isfinite(f) ? f : -1e10;
}

// Local phase, epigraph variables z = (x, t) for maximin; z = x otherwise.
struct LocalObjectiveData {
  ObjectiveData base;
  bool epigraph;
};

double LocalObjective(unsigned n, const double* z, double* grad, void* data) {
  auto* c = static_cast<LocalObjectiveData*>(data);
  const int nx = c->base.ev->n();
  if (c->epigraph) {
    if (grad) {
      std::fill(grad, grad + n, 0.0);
      grad[nx] = 1.0;
    }
    return z[nx];
  }
  const double *phi, *g;
  if (!c->base.ev->Values(z, &phi, &g)) return -1e10;
  std::vector<double> v(phi, phi + c->base.ev->J());
  const double f = Aggregate(c->base.opt->robustness, v);
  if (grad) {
    const double *Jp, *Jg;
    std::fill(grad, grad + n, 0.0);
    if (c->base.ev->Gradients(z, &Jp, &Jg)) {
      const int J = c->base.ev->J();
      for (int i = 0; i < nx; ++i) {
        if (c->base.opt->robustness == Robustness::kAverage) {
          for (int j = 0; j < J; ++j) grad[i] += Jp[j * nx + i] / J;
        } else {
          grad[i] = Jp[i];  // nominal: the first scenario
        }
      }
    }
  }
  return f;
}

// Vector constraint: [t - φ_j(x) for j (epigraph only), g_c(x)] <= 0.
void LocalConstraints(unsigned m, double* result, unsigned n, const double* z, double* grad,
                      void* data) {
  auto* c = static_cast<LocalObjectiveData*>(data);
  const int nx = c->base.ev->n(), J = c->base.ev->J(), C = c->base.ev->C();
  const double *phi, *g;
  if (!c->base.ev->Values(z, &phi, &g)) {
    std::fill(result, result + m, 1e10);
    if (grad) std::fill(grad, grad + m * n, 0.0);
    return;
  }
  int r = 0;
  if (c->epigraph) {
    for (int j = 0; j < J; ++j) result[r++] = z[nx] - phi[j];
  }
  for (int k = 0; k < C; ++k) result[r++] = g[k];
  if (!grad) return;
  std::fill(grad, grad + m * n, 0.0);
  const double *Jp, *Jg;
  if (!c->base.ev->Gradients(z, &Jp, &Jg)) return;
  r = 0;
  if (c->epigraph) {
    for (int j = 0; j < J; ++j, ++r) {
      for (int i = 0; i < nx; ++i) grad[r * n + i] = -Jp[j * nx + i];
      grad[r * n + nx] = 1.0;
    }
  }
  for (int k = 0; k < C; ++k, ++r) {
    for (int i = 0; i < nx; ++i) grad[r * n + i] = Jg[k * nx + i];
  }
}

// NLopt's names of its results; the failures by number (FAILURE(n)).
constexpr model::EnumNames<nlopt::result, 6> kResultNames{
    {{{nlopt::SUCCESS, "SUCCESS"},
      {nlopt::STOPVAL_REACHED, "STOPVAL_REACHED"},
      {nlopt::FTOL_REACHED, "FTOL_REACHED"},
      {nlopt::XTOL_REACHED, "XTOL_REACHED"},
      {nlopt::MAXEVAL_REACHED, "MAXEVAL_REACHED"},
      {nlopt::MAXTIME_REACHED, "MAXTIME_REACHED"}}}};

// One local run from x_start; returns the backend's result name.
std::string RunLocal(const DesignProblem& p, const SolverOptions& o, DesignEvaluator* ev,
                     const std::vector<double>& x_start) {
  const int nx = p.num_variables;
  const bool epigraph = o.robustness == Robustness::kMaximin;
  const bool gradients = static_cast<bool>(p.evaluate_with_gradient);
  const int nz = nx + (epigraph ? 1 : 0);
  const int m = (epigraph ? p.num_scenarios : 0) + p.num_constraints;
  nlopt::opt local(gradients ? nlopt::LD_SLSQP : nlopt::LN_COBYLA, nz);
  std::vector<double> lb(p.lower), ub(p.upper), z(x_start);
  LocalObjectiveData lc{{ev, &o, &p}, epigraph};
  if (epigraph) {
    const double *phi, *g;
    double t0 = -1e10;
    if (ev->Values(x_start.data(), &phi, &g)) {
      t0 = *std::min_element(phi, phi + p.num_scenarios);
    }
    if (!std::isfinite(t0) || t0 < -1e9) return "START_NOT_EVALUABLE";
    const double span = 100.0 * (1.0 + std::abs(t0));
    lb.push_back(t0 - span);
    ub.push_back(t0 + span);
    z.push_back(t0);
  }
  local.set_lower_bounds(lb);
  local.set_upper_bounds(ub);
  local.set_max_objective(LocalObjective, &lc);
  if (m > 0) {
    local.add_inequality_mconstraint(LocalConstraints, &lc, std::vector<double>(m, 1e-8));
  }
  local.set_ftol_rel(o.relative_tolerance);
  local.set_xtol_rel(1e-6);
  local.set_maxeval(o.max_local_evaluations);
  if (!gradients) {
    std::vector<double> step(nz);
    for (int i = 0; i < nx; ++i) step[i] = 0.05 * (p.upper[i] - p.lower[i]);
    if (epigraph) step[nx] = 0.01 * (1.0 + std::abs(z[nx]));
    local.set_initial_step(step);
  }
  double f = 0.0;
  try {
    return kResultNames.NameOrNumber(local.optimize(z, f), "FAILURE");
  } catch (const std::exception& e) {
    return std::string("EXCEPTION: ") + e.what();  // the best point is kept by the evaluator
  }
}

}  // namespace

SolverSummary SolveWithNlopt(const DesignProblem& p, const SolverOptions& o) {
  SolverSummary s;
  if (!internal::StartSummary("nlopt", o, &s)) return s;
  DesignEvaluator ev(p, o);
  ObjectiveData ctx{&ev, &o, &p};
  std::vector<double> start = p.x0;
  std::string raw;
  if (o.global != GlobalMethod::kNone && o.max_global_evaluations > 0) {
    const bool mlsl = o.global == GlobalMethod::kMlsl;
    nlopt::opt global(mlsl ? nlopt::G_MLSL_LDS : nlopt::GN_DIRECT_L, p.num_variables);
    nlopt::opt inner(nlopt::LN_BOBYQA, p.num_variables);
    if (mlsl) {
      inner.set_ftol_rel(1e-4);
      inner.set_maxeval(std::max(10, o.max_global_evaluations / 10));
      global.set_local_optimizer(inner);
    }
    global.set_lower_bounds(p.lower);
    global.set_upper_bounds(p.upper);
    global.set_max_objective(PenalisedObjective, &ctx);
    global.set_maxeval(o.max_global_evaluations);
    std::vector<double> x = p.x0;
    double f = 0.0;
    try {
      raw = (mlsl ? "MLSL:" : "DIRECT-L:") +
            kResultNames.NameOrNumber(global.optimize(x, f), "FAILURE");
    } catch (const std::exception& e) {
      raw = std::string("global EXCEPTION: ") + e.what();
    }
    if (ev.has_best()) start = ev.best_x();
  }
  std::vector<std::vector<double>> starts = {start};
  for (const auto& x : o.extra_starts) {
    if (static_cast<int>(x.size()) == p.num_variables) starts.push_back(x);
  }
  for (const auto& x : starts) {
    const std::string r = RunLocal(p, o, &ev, x);
    raw += (raw.empty() ? "" : "; ") +
           std::string(p.evaluate_with_gradient ? "SLSQP:" : "COBYLA:") + r;
  }
  s.raw_status = raw;
  s.status =
      raw.find("MAXEVAL") != std::string::npos && raw.find("COBYLA:MAXEVAL") != std::string::npos
          ? SolverStatus::kMaxEvaluations
          : SolverStatus::kConverged;
  internal::FillFromBest(ev, &s);
  return s;
}

}  // namespace uuvplan::planner
