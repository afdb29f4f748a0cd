// Medians of records: the whole, or a long record's from evenly spread values. At most ~20,000
// of them give a sampling interval's median well within 1% (the factor-2 and factor-4 tests
// that use it), in 160 KB instead of 8 bytes a sample (a million-row log).
#pragma once

#include <algorithm>
#include <cstddef>
#include <limits>
#include <vector>

namespace uuvplan::model {

/// The median (the upper middle of an even count) of `v`; NaN when `v` is empty.
inline double Median(std::vector<double> v) {
  if (v.empty()) return std::numeric_limits<double>::quiet_NaN();
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

/// Every how many of `count` values a spread sample of at most ~20,000 keeps one.
inline std::size_t SpreadStride(std::size_t count) {
  constexpr std::size_t kSpreadSample = 20000;
  return std::max<std::size_t>(1, count / kSpreadSample);
}

}  // namespace uuvplan::model
