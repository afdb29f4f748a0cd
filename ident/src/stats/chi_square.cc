#include "uuvplan/ident/stats/chi_square.h"

#include <cmath>

namespace uuvplan::ident {
namespace {

constexpr int kMaxIterations = 500;
constexpr double kEpsilon = 1e-15;

// P(a, x) by its series, valid for x < a + 1.
double LowerSeries(double a, double x) {
  double sum = 1.0 / a, term = sum;
  for (int n = 1; n < kMaxIterations; ++n) {
    term *= x / (a + n);
    sum += term;
    if (std::abs(term) < std::abs(sum) * kEpsilon) break;
  }
  return sum * std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x) by Lentz's continued fraction, valid for x >= a + 1.
double UpperFraction(double a, double x) {
  constexpr double kTiny = 1e-300;
  double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, h = d;
  for (int i = 1; i < kMaxIterations; ++i) {
    const double an = -i * (i - a);
    b += 2.0;
    d = an * d + b;
    if (std::abs(d) < kTiny) d = kTiny;
    c = b + an / c;
    if (std::abs(c) < kTiny) c = kTiny;
    d = 1.0 / d;
    const double delta = d * c;
    h *= delta;
    if (std::abs(delta - 1.0) < kEpsilon) break;
  }
  return std::exp(-x + a * std::log(x) - std::lgamma(a)) * h;
}

}  // namespace

double ChiSquareSurvival(double x, int dof) {
  if (dof <= 0) return 1.0;
  if (!(x > 0)) return 1.0;
  const double a = 0.5 * dof, xx = 0.5 * x;
  return xx < a + 1.0 ? 1.0 - LowerSeries(a, xx) : UpperFraction(a, xx);
}

}  // namespace uuvplan::ident
