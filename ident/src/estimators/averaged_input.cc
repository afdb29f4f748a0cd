#include "estimators/averaged_input.h"

#include <vector>

namespace uuvplan::ident::internal {

std::unique_ptr<model::Excitation> AveragedInput(const TrialData& d, double span) {
  const model::TimesView t = d.force_t.view();
  const std::vector<double>& f = d.force;
  const std::vector<int>& m = d.mapping;
  const std::size_t n = f.size();
  // A command holds from its row to the next row that changes the force or the mapping (the
  // trial's end after the last), as the zero-order hold does (model::MakeHeldExcitation).
  const auto next_change = [&](std::size_t i) {
    std::size_t k = i + 1;
    while (k < n && f[k] == f[i] && m[k] == m[i]) ++k;
    return k;
  };
  const auto time_of = [&](std::size_t k) { return k < n ? t[k] : d.duration; };
  std::vector<double> start, force;
  std::vector<int> mapping;
  bool merged = false;
  for (std::size_t i = 0; i < n;) {
    // The commands from row i on form a piece while each one's hold ends within `span` of t[i].
    std::size_t end = next_change(i);
    double impulse = f[i] * (time_of(end) - t[i]);
    int commands = 1;
    while (end < n && m[end] == m[i]) {
      const std::size_t after = next_change(end);
      if (time_of(after) > t[i] + span) break;
      impulse += f[end] * (time_of(after) - t[end]);
      end = after;
      ++commands;
    }
    const double length = time_of(end) - t[i];
    start.push_back(t[i]);
    force.push_back(commands > 1 && length > 0 ? impulse / length : f[i]);
    mapping.push_back(m[i]);
    merged = merged || commands > 1;
    i = end;
  }
  if (!merged) return nullptr;
  return model::MakeHeldExcitation(start, force, mapping, d.duration);
}

}  // namespace uuvplan::ident::internal
