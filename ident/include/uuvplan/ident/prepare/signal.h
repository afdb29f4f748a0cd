// Samples of one measured signal (a DOF's position or velocity), as identification reads them.
#pragma once

#include <cstddef>
#include <vector>

#include "uuvplan/ident/prepare/shared_times.h"

namespace uuvplan::ident {

/// Samples of one signal: times (s) and values, no NaN.
struct Signal {
  SharedTimes t;  ///< shared with the signals made from this one (a velocity estimate's)
  std::vector<double> y;
  std::size_t size() const { return t.size(); }
  bool empty() const { return t.empty(); }
};

}  // namespace uuvplan::ident
