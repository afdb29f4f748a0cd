#include "uuvplan/model/error_breakdown.h"

#include <cmath>

namespace uuvplan::model {

const ErrorGroup* Largest(const std::vector<ErrorGroup>& groups) {
  const ErrorGroup* best = nullptr;
  for (const auto& g : groups) {
    if (!best || std::abs(g.relative) > std::abs(best->relative)) best = &g;
  }
  return best;
}

const ErrorGroup* Labeled(const std::vector<ErrorGroup>& groups, const std::string& label) {
  for (const auto& g : groups) {
    if (g.label == label) return &g;
  }
  return nullptr;
}

}  // namespace uuvplan::model
