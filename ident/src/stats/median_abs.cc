// Radix selection of the median |r| (median_abs.h): non-negative floats order as their bit
// patterns do, so three counting passes over r find the median's leading 11, next 11 and last
// 10 bits (2048 counters), and r is never copied.
#include "uuvplan/ident/stats/median_abs.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace uuvplan::ident {

double MedianAbs(const Eigen::VectorXd& r) {
  if (r.size() == 0) return 0.0;
  auto bits = [&](Eigen::Index i) {
    const float a = static_cast<float>(std::abs(r[i]));
    std::uint32_t u;
    std::memcpy(&u, &a, sizeof u);
    return u;
  };
  std::size_t rank = static_cast<std::size_t>(r.size()) / 2;
  std::uint32_t prefix = 0;  // the median's leading `known` bits
  int known = 0;
  std::vector<std::uint32_t> count(std::size_t{1} << 11);
  for (const int width : {11, 11, 10}) {
    std::fill(count.begin(), count.end(), 0);
    const int shift = 32 - known - width;
    for (Eigen::Index i = 0; i < r.size(); ++i) {
      const std::uint32_t u = bits(i);
      if (known == 0 || (u >> (32 - known)) == prefix) ++count[(u >> shift) & ((1u << width) - 1)];
    }
    std::uint32_t digit = 0;
    while (rank >= count[digit]) rank -= count[digit++];
    prefix = (prefix << width) | digit;
    known += width;
  }
  float median;
  std::memcpy(&median, &prefix, sizeof median);
  return median;
}

}  // namespace uuvplan::ident
