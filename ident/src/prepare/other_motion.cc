#include "uuvplan/ident/prepare/other_motion.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace uuvplan::ident {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// max − min of the finite samples from row `first` on; NaN with fewer than two.
double Travel(const std::vector<double>& x, std::size_t first) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  int n = 0;
  for (std::size_t i = first; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) continue;
    lo = std::min(lo, x[i]);
    hi = std::max(hi, x[i]);
    ++n;
  }
  return n >= 2 ? hi - lo : kNaN;
}

// √(mean of x²) over the finite samples from row `first` on; NaN with fewer than two.
double Rms(const std::vector<double>& x, std::size_t first) {
  double sum = 0.0;
  int n = 0;
  for (std::size_t i = first; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) continue;
    sum += x[i] * x[i];
    ++n;
  }
  return n >= 2 ? std::sqrt(sum / n) : kNaN;
}

}  // namespace

std::vector<TrialNote> OtherDofMotion(const model::TrialLog& log, model::Dof dof, double from_t) {
  const std::size_t first = std::lower_bound(log.t.begin(), log.t.end(), from_t) - log.t.begin();
  const double own_travel = Travel(log.position[model::Index(dof)], first);
  const double own_rms = Rms(log.velocity[model::Index(dof)], first);
  std::vector<TrialNote> notes;
  for (const model::Dof other : model::kAllDofs) {
    if (other == dof) continue;
    const double travel = Travel(log.position[model::Index(other)], first);
    const double rms = Rms(log.velocity[model::Index(other)], first);
    if (std::isnan(travel) && std::isnan(rms)) continue;
    notes.push_back({TrialNoteKind::kOtherDofMotion,
                     {std::string(model::DofName(other)), std::string(model::DofName(dof))},
                     {travel, rms, own_travel, own_rms}});
  }
  return notes;
}

}  // namespace uuvplan::ident
