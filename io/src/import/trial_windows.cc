#include "import/trial_windows.h"

#include <cmath>

namespace uuvplan::io::import {
namespace {

bool Active(const std::vector<std::vector<double>>& commands, std::size_t i) {
  for (const std::vector<double>& thruster : commands) {
    if (std::isfinite(thruster[i]) && thruster[i] != 0.0) return true;
  }
  return false;
}

}  // namespace

std::vector<std::array<double, 2>> WholeWindow(const std::vector<double>& command_times) {
  if (command_times.empty()) return {};
  return {{command_times.front(), command_times.back()}};
}

std::vector<std::array<double, 2>> ActivityWindows(const std::vector<double>& command_times,
                                                   const std::vector<std::vector<double>>& commands,
                                                   double quiet_s) {
  std::vector<std::array<double, 2>> windows;
  const std::size_t n = command_times.size();
  for (std::size_t i = 0; i < n;) {
    if (!Active(commands, i)) {
      ++i;
      continue;
    }
    std::size_t end = i;
    while (end < n && Active(commands, end)) ++end;
    const double stop = command_times[std::min(end, n - 1)];
    if (!windows.empty() && command_times[i] - windows.back()[1] < quiet_s) {
      windows.back()[1] = stop;
    } else {
      windows.push_back({command_times[i], stop});
    }
    i = end;
  }
  return windows;
}

}  // namespace uuvplan::io::import
