// Internal to the solver backends: evaluates a DesignProblem with a one-point cache (backends
// ask for f, g and their gradients at the same x in separate calls), forward-difference
// gradients when the problem has none, and the best feasible point seen so far (a backend that
// stops early, or throws, still returns the best design it evaluated).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "uuvplan/planner/design/solver.h"

namespace uuvplan::planner::internal {

class DesignEvaluator {
 public:
  DesignEvaluator(const DesignProblem& p, const SolverOptions& o) : p_(p), o_(o) {
    n_ = p.num_variables;
    J_ = p.num_scenarios;
    C_ = p.num_constraints;
  }
  int n() const { return n_; }
  int J() const { return J_; }
  int C() const { return C_; }
  int evaluations() const { return evaluations_; }

  /// φ and g at x (cached). Returns false if the model could not be evaluated.
  bool Values(const double* x, const double** phi, const double** g) {
    if (!(has_values_ && Same(x))) {
      x_.assign(x, x + n_);
      phi_.assign(J_, 0.0);
      g_.assign(C_, 0.0);
      has_grad_ = false;
      ok_ = p_.evaluate(x, phi_.data(), g_.data());
      ++evaluations_;
      has_values_ = true;
      if (ok_) Track(x_, phi_, g_);
    }
    *phi = phi_.data();
    *g = g_.data();
    return ok_;
  }

  /// Gradients (row-major J_phi[j·n + i], J_g[c·n + i]) at x (cached).
  bool Gradients(const double* x, const double** J_phi, const double** J_g) {
    const double *phi, *g;
    if (!Values(x, &phi, &g)) return false;
    if (!has_grad_) {
      Jphi_.assign(J_ * n_, 0.0);
      Jg_.assign(C_ * n_, 0.0);
      if (p_.evaluate_with_gradient) {
        std::vector<double> phi2(J_), g2(C_);
        ok_ = p_.evaluate_with_gradient(x, phi2.data(), g2.data(), Jphi_.data(), Jg_.data());
        ++evaluations_;
      } else {
        std::vector<double> xp(x_), phi2(J_), g2(C_);
        for (int i = 0; i < n_; ++i) {
          double h = o_.fd_step * std::max(1.0, std::abs(x_[i]));
          if (x_[i] + h > p_.upper[i]) h = -h;  // stay inside the bounds
          xp[i] = x_[i] + h;
          const bool ok = p_.evaluate(xp.data(), phi2.data(), g2.data());
          ++evaluations_;
          xp[i] = x_[i];
          if (!ok) return false;
          Track(std::vector<double>(xp.begin(), xp.end()), phi2, g2);
          for (int j = 0; j < J_; ++j) Jphi_[j * n_ + i] = (phi2[j] - phi_[j]) / h;
          for (int c = 0; c < C_; ++c) Jg_[c * n_ + i] = (g2[c] - g_[c]) / h;
        }
      }
      has_grad_ = true;
    }
    *J_phi = Jphi_.data();
    *J_g = Jg_.data();
    return ok_;
  }

  double Violation(const std::vector<double>& g) const {
    double v = 0.0;
    for (double gc : g) v = std::max(v, gc);
    return v;
  }

  bool has_best() const { return !best_x_.empty(); }
  const std::vector<double>& best_x() const { return best_x_; }
  const std::vector<double>& best_phi() const { return best_phi_; }
  const std::vector<double>& best_g() const { return best_g_; }
  double best_objective() const { return best_obj_; }
  double best_violation() const { return best_violation_; }

 private:
  bool Same(const double* x) const {
    for (int i = 0; i < n_; ++i) {
      if (x[i] != x_[i]) return false;
    }
    return true;
  }
  // Best point: feasible beats infeasible; among feasible the larger aggregate; among
  // infeasible the smaller violation.
  void Track(const std::vector<double>& x, const std::vector<double>& phi,
             const std::vector<double>& g) {
    for (double v : phi) {
      if (!std::isfinite(v)) return;
    }
    const double viol = Violation(g);
    const double obj = Aggregate(o_.robustness, phi);
    constexpr double kFeasible = 1e-7;
    const bool feasible = viol <= kFeasible;
    const bool best_feasible = best_violation_ <= kFeasible;
    bool better;
    if (best_x_.empty()) {
      better = true;
    } else if (feasible != best_feasible) {
      better = feasible;
    } else if (feasible) {
      better = obj > best_obj_;
    } else {
      better = viol < best_violation_;
    }
    if (better) {
      best_x_ = x;
      best_phi_ = phi;
      best_g_ = g;
      best_obj_ = obj;
      best_violation_ = viol;
    }
  }

  const DesignProblem& p_;
  const SolverOptions& o_;
  int n_ = 0, J_ = 0, C_ = 0;
  int evaluations_ = 0;
  bool has_values_ = false, has_grad_ = false, ok_ = false;
  std::vector<double> x_, phi_, g_, Jphi_, Jg_;
  std::vector<double> best_x_, best_phi_, best_g_;
  double best_obj_ = -std::numeric_limits<double>::infinity();
  double best_violation_ = std::numeric_limits<double>::infinity();
};

/// A backend's summary before solving: its name, and the options' error if they are invalid
/// (then false: the backend returns the summary as it is).
inline bool StartSummary(const char* backend, const SolverOptions& o, SolverSummary* s) {
  s->backend = backend;
  std::string error;
  if (o.IsValid(&error)) return true;
  s->message = error;
  return false;
}

/// Fills a summary from the evaluator's best point.
inline void FillFromBest(const DesignEvaluator& ev, SolverSummary* s) {
  s->evaluations = ev.evaluations();
  if (!ev.has_best()) {
    s->status = SolverStatus::kFailed;
    if (s->message.empty()) s->message = "no point of the design space could be evaluated";
    return;
  }
  s->x = ev.best_x();
  s->phi = ev.best_phi();
  s->g = ev.best_g();
  s->objective = ev.best_objective();
  s->max_violation = std::max(0.0, ev.best_violation());
  if (s->max_violation > 1e-7) {
    s->status = SolverStatus::kInfeasible;
    s->message = "no feasible design found (smallest constraint violation " +
                 std::to_string(s->max_violation) + ")";
  }
}

}  // namespace uuvplan::planner::internal
