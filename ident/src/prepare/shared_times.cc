#include "uuvplan/ident/prepare/shared_times.h"

#include <cmath>
#include <cstdint>
#include <cstring>
#include <optional>

namespace uuvplan::ident {

namespace {

bool SameBits(double a, double b) {
  std::uint64_t x = 0, y = 0;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return x == y;
}

// The uniform decimal clock that gives at(i) bit for bit for i < n (SharedTimes::CompactUniform).
std::optional<model::UniformClock> UniformClockOf(std::size_t n,
                                                  const std::function<double(std::size_t)>& at,
                                                  double offset) {
  if (n < 2) return std::nullopt;
  constexpr double kScales[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8, 1e9};
  constexpr double kExactIntegers = 9007199254740992.0;  // 2^53
  for (const double scale : kScales) {
    model::UniformClock c;
    c.scale = scale;
    c.offset = offset;
    c.n0 = std::nearbyint((at(0) + offset) * scale);
    c.step = std::nearbyint((at(1) + offset) * scale) - c.n0;
    if (!(c.step > 0) || !(std::abs(c.n0) + c.step * static_cast<double>(n) < kExactIntegers)) {
      continue;
    }
    bool every = true;
    for (std::size_t i = 0; every && i < n; ++i) every = SameBits(c(i), at(i));
    if (every) return c;
  }
  return std::nullopt;
}

}  // namespace

SharedTimes SharedTimes::Of(std::size_t n, const std::function<double(std::size_t)>& at,
                            double offset) {
  SharedTimes s;
  if (const std::optional<model::UniformClock> c = UniformClockOf(n, at, offset)) {
    s.view_ = model::TimesView(*c, n);
    return s;
  }
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = at(i);
  s = std::move(t);
  return s;
}

void SharedTimes::CompactUniform(double offset) {
  if (uniform() || !times_ || times_->size() < 2) return;
  const std::vector<double>& t = *times_;
  if (const auto c = UniformClockOf(
          t.size(), [&t](std::size_t i) { return t[i]; }, offset)) {
    view_ = model::TimesView(*c, t.size());
    times_.reset();
  }
}

}  // namespace uuvplan::ident
