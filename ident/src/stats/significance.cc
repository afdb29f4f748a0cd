#include "uuvplan/ident/stats/significance.h"

#include <cmath>
#include <limits>

namespace uuvplan::ident {

double PercentileError(double value, double sigma) {
  if (value == 0.0) return std::numeric_limits<double>::infinity();
  return 100.0 * sigma / std::abs(value);
}

bool IsSignificant(double value, double sigma) {
  return PercentileError(value, sigma) <= kInsignificantPercentileError;
}

}  // namespace uuvplan::ident
