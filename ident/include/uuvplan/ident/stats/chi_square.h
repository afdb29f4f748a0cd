// Tail probabilities of the χ² distribution, for likelihood-ratio tests.
#pragma once

namespace uuvplan::ident {

/// P(X > x) for X ~ χ²(dof): the regularized upper incomplete gamma Q(dof/2, x/2)
/// (series for x < a + 1, continued fraction otherwise; Numerical Recipes §6.2).
double ChiSquareSurvival(double x, int dof);

}  // namespace uuvplan::ident
