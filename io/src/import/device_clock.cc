#include "import/device_clock.h"

#include <algorithm>
#include <cmath>

#include "uuvplan/model/input_error.h"

namespace uuvplan::io::import {

std::vector<double> OnRecorderClock(const std::vector<double>& device_s,
                                    const std::vector<double>& arrival_s,
                                    const std::string& where) {
  const std::size_t n = device_s.size();
  for (std::size_t i = 0; i < n; ++i) {
    if (!std::isfinite(device_s[i]) || (i > 0 && device_s[i] < device_s[i - 1])) {
      throw model::InputError(where, "expected a device clock that runs forward, got " +
                                         std::to_string(device_s[i]) + " s at message " +
                                         std::to_string(i + 1) + " after " +
                                         std::to_string(i > 0 ? device_s[i - 1] : NAN) + " s");
    }
  }
  if (n < 2 || device_s.back() == device_s.front()) {
    throw model::InputError(where,
                            "expected a device clock with at least two distinct times, "
                            "got " +
                                std::to_string(n) + " samples at one time");
  }
  // Least squares about the means (the recorder's epoch times would cancel digits).
  double d_mean = 0, a_mean = 0;
  for (std::size_t i = 0; i < n; ++i) d_mean += device_s[i] / n, a_mean += arrival_s[i] / n;
  double sdd = 0, sda = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sdd += (device_s[i] - d_mean) * (device_s[i] - d_mean);
    sda += (device_s[i] - d_mean) * (arrival_s[i] - a_mean);
  }
  const double rate = sda / sdd;
  if (!(std::abs(rate - 1.0) <= 0.01)) {  // crystals differ by 1e-4, not 1e-2
    throw model::InputError(where,
                            "expected a device clock in s (after the map's scale) running "
                            "within 1% of the recorder's, got " +
                                std::to_string(rate) + " recorder s per device s");
  }
  double least_delay = INFINITY;
  for (std::size_t i = 0; i < n; ++i) {
    least_delay = std::min(least_delay, (arrival_s[i] - a_mean) - rate * (device_s[i] - d_mean));
  }
  std::vector<double> t(n);
  for (std::size_t i = 0; i < n; ++i) t[i] = a_mean + least_delay + rate * (device_s[i] - d_mean);
  return t;
}

}  // namespace uuvplan::io::import
