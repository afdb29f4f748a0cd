#include "uuvplan/ident/prepare/shared_times.h"

#include <cmath>
#include <cstdint>
#include <cstring>

namespace uuvplan::ident {

namespace {

bool SameBits(double a, double b) {
  std::uint64_t x = 0, y = 0;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

}  // namespace

void SharedTimes::CompactUniform(double offset) {
  if (uniform() || !times_ || times_->size() < 2) return;
  const std::vector<double>& t = *times_;
  const std::size_t n = t.size();
  constexpr double kScales[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
  constexpr double kExactIntegers = 9007199254740992.0;  // 2^53
  for (const double scale : kScales) {
    model::UniformClock c;
    c.scale = scale;
    c.offset = offset;
    c.n0 = std::nearbyint((t[0] + offset) * scale);
    c.step = std::nearbyint((t[1] + offset) * scale) - c.n0;
    if (!(c.step > 0) || !(std::abs(c.n0) + c.step * static_cast<double>(n) < kExactIntegers)) {
      continue;
    }
    bool every = true;
    for (std::size_t i = 0; every && i < n; ++i) every = SameBits(c(i), t[i]);
    if (every) {
      times_.reset();
      view_ = model::TimesView(c, n);
      return;
    }
  }
}

}  // namespace uuvplan::ident
