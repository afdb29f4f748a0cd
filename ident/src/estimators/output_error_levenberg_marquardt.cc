// The output error's Levenberg–Marquardt iteration (output_error_levenberg_marquardt.h).
#include "estimators/output_error_levenberg_marquardt.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "uuvplan/model/util/text.h"

namespace uuvplan::ident::internal {
namespace {

// The length of a negligible Gauss–Newton step, in standard deviations of the estimate.
constexpr double kNegligibleStep = 0.1;
// Within this many standard deviations of the minimum the undamped Gauss–Newton step is tried
// first: there the quadratic model is good, while Marquardt's damping shortens the step along a
// weakly determined direction by 1/(1 + λ·diag A/eigenvalue) — a half at λ = 1e-4 and a
// condition number of 10⁴ (a 10⁶-sample surge trial) — and convergence becomes linear.
constexpr double kUndampedWithin = 10.0;

// The Gauss–Newton decrement gᵀ(JᵀJ)⁻¹g / s² of factor `a` at cost ½‖r‖² = `cost`, s² from
// `dof` degrees of freedom: the step's squared length in the estimate's standard deviations.
double Decrement(const BlockLeastSquares& a, double cost, int dof) {
  const double s2 = std::max(2.0 * cost / dof, 1e-300);
  const double dec = a.Gradient().dot(a.Solve(a.Gradient(), 0.0)) / s2;
  return std::isfinite(dec) ? std::abs(dec) : std::numeric_limits<double>::infinity();
}

enum class Attempt { kLower, kHigher, kFailed };

// The step of damping λ from *z: kLower when it lowers the cost (z, cost and J then move to it
// and the relative decrease is in *rel_decrease), kHigher when it does not, kFailed when the
// solve or the simulation fails.
Attempt TryStep(const Problem& p, double lambda, Eigen::VectorXd* z, double* cost,
                BlockLeastSquares* J, double* rel_decrease) {
  const Eigen::VectorXd step = -J->Solve(J->Gradient(), lambda);
  if (!step.allFinite()) return Attempt::kFailed;
  const Eigen::VectorXd z_new = *z + step;
  // The trial point is simulated with its sensitivities: most steps are accepted, and an
  // accepted step then needs no second simulation for its Jacobian.
  BlockLeastSquares J_trial(p.num_free());
  double cost_new = 0.0;
  if (!p.Evaluate(z_new, nullptr, &J_trial, &cost_new)) return Attempt::kFailed;
  if (cost_new > *cost) return Attempt::kHigher;
  *rel_decrease = (*cost - cost_new) / std::max(*cost, 1e-300);
  *z = z_new;
  *cost = cost_new;
  std::swap(*J, J_trial);
  return Attempt::kLower;
}

// Damped steps from *z, λ growing (×10 past a failed solve or simulation, ×4 past a higher
// cost), until one lowers the cost, at most 30: then z, cost and J move to it, λ shrinks, the
// relative decrease is in *rel_decrease and the answer is true; false when none did. Within
// kUndampedWithin σ of the minimum (`decrement`) the Gauss–Newton step is tried first.
bool DampedStep(const Problem& p, double decrement, Eigen::VectorXd* z, double* cost,
                BlockLeastSquares* J, double* lambda, double* rel_decrease) {
  if (decrement < kUndampedWithin * kUndampedWithin &&
      TryStep(p, 0.0, z, cost, J, rel_decrease) == Attempt::kLower) {
    return true;
  }
  for (int tries = 0; tries < 30; ++tries) {
    const Attempt a = TryStep(p, *lambda, z, cost, J, rel_decrease);
    if (a == Attempt::kLower) {
      *lambda = std::max(1e-12, *lambda / 3);
      return true;
    }
    *lambda *= a == Attempt::kFailed ? 10 : 4;
  }
  return false;
}

}  // namespace

LmOutcome LevenbergMarquardt(const Problem& p, Eigen::VectorXd z, const OutputErrorOptions& o) {
  LmOutcome out;
  BlockLeastSquares J(p.num_free());
  double cost = 0.0;
  if (!p.Evaluate(z, nullptr, &J, &cost)) {
    out.failed = true;
    out.message = "the simulation fails at the starting parameters";
    out.z = z;
    return out;
  }
  double lambda = 1e-3;
  const int dof = std::max(1, p.num_r() - p.num_excluded() - p.num_z());
  for (int it = 0; it < o.max_iterations; ++it) {
    const double decrement = Decrement(J, cost, dof);
    if (decrement < kNegligibleStep * kNegligibleStep) {
      out.converged = true;
      break;
    }
    out.iterations = it + 1;
    double rel_decrease = 0.0;
    if (!DampedStep(p, decrement, &z, &cost, &J, &lambda, &rel_decrease)) {
      // No step lowers the cost. At the minimum to rounding when the Gauss–Newton step is
      // tiny in σ units (checked by the caller's final test below); otherwise stalled. (The
      // decrement of the point the last iteration started from: J is unchanged.)
      const double dec = Decrement(J, cost, dof);
      out.converged = dec < 1.0;
      if (!out.converged) {
        out.message =
            "Levenberg–Marquardt stalled (no step lowers the cost, the Gauss–Newton "
            "step is still " +
            model::Significant(std::sqrt(dec), 3) + " σ long)";
      }
      break;
    }
    // The cost no longer changes at all (to the tolerance) with an undamped step: done.
    if (rel_decrease < o.tolerance && lambda < 1e-2 && Decrement(J, cost, dof) < 1.0) {
      out.converged = true;
      break;
    }
  }
  if (!out.converged && !out.failed && out.message.empty()) {
    out.message = "Levenberg–Marquardt did not converge in " + std::to_string(o.max_iterations) +
                  " iterations";
  }
  out.z = z;
  out.rows = std::move(J);
  return out;
}

bool WithResiduals(const Problem& p, LmOutcome* lm) { return p.Evaluate(lm->z, &lm->r, nullptr); }

}  // namespace uuvplan::ident::internal
