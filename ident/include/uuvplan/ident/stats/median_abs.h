// The median of |r| without a copy of r (the output error's gross-error limit on a
// million residuals held a 4 MB sorted copy).
#pragma once

#include <Eigen/Core>

namespace uuvplan::ident {

/// The median |r_i|, taken as the (n/2)-th smallest from 0 (the upper median when n is even),
/// in single precision: its relative rounding, 6e-8, is nothing on a robust σ. 0 when r is
/// empty. Exactly what std::nth_element would pick from a float copy of |r|.
double MedianAbs(const Eigen::VectorXd& r);

}  // namespace uuvplan::ident
