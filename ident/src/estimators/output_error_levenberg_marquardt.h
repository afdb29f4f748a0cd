// Internal to the output error (output_error.h): its Levenberg–Marquardt iteration.
#pragma once

#include <Eigen/Dense>
#include <string>

#include "estimators/output_error_problem.h"
#include "uuvplan/ident/estimators/block_least_squares.h"
#include "uuvplan/ident/estimators/output_error.h"

namespace uuvplan::ident::internal {

struct LmOutcome {
  Eigen::VectorXd z;
  Eigen::VectorXd r;       // at z: WithResiduals (the iterations keep only the cost)
  BlockLeastSquares rows;  // J at z, as its block-angular factor
  int iterations = 0;
  bool converged = false;
  bool failed = false;
  std::string message;
};

// Levenberg–Marquardt with Marquardt's diagonal scaling (Marquardt 1963): the step solves
// (JᵀJ + λ·diag(JᵀJ))·δ = −Jᵀr; a step is accepted only if it lowers the cost ½‖r‖² and keeps
// the parameters admissible and the simulation finite, λ shrinks after an accepted step and
// grows until one is found. Converged when the Gauss–Newton step at the current point is
// statistically negligible: its length in the metric of the estimate's covariance s²·(JᵀJ)⁻¹,
//   δ_GNᵀ (JᵀJ) δ_GN / s² = gᵀ(JᵀJ)⁻¹g / s²  <  kNegligibleStep² ,   g = Jᵀr,
// i.e. under a hundredth of a standard deviation. A tiny step taken under heavy damping is
// not convergence (the classic false stop of LM far from the minimum), nor is a point where no
// step lowers the cost while the Gauss–Newton step is still long: both are reported as not
// converged and the caller falls back. JᵀJ and Jᵀr come trial by trial from the block factor
// (block_least_squares.h), and the steps from its Schur complement.
LmOutcome LevenbergMarquardt(const Problem& p, Eigen::VectorXd z, const OutputErrorOptions& o);

// The residuals at the fit's answer (one plain simulation; the iterations keep none: 16 bytes a
// measurement). False if that simulation fails, which the fit's own evaluation there did not.
bool WithResiduals(const Problem& p, LmOutcome* lm);

}  // namespace uuvplan::ident::internal
