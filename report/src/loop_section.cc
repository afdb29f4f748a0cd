// The loop's history: its trials and the estimates after the last one.
#include <cmath>
#include <string>
#include <vector>

#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/report/sections.h"

namespace uuvplan::report {

namespace {

// "+ thrust_map, + thruster_lag, − sensor_delay": effects `loop --diagnose` added and removed.
std::string ModelChangeCell(const io::LoopTrialRow& r) {
  std::vector<std::string> items;
  for (const auto& e : r.effects_entered) items.push_back("+ " + e);
  for (const auto& e : r.effects_left) items.push_back("− " + e);
  return model::Join(items, ", ");
}

}  // namespace

Section LoopSection(const io::LoopHistory& h) {
  Section s{"loop", "Loop history", {}, {}, {}};
  s.paragraphs.push_back("Loop (" + h.path + "): " + h.status + ", " +
                         std::to_string(h.trials.size()) + " trials, pool time " +
                         Number(h.pool_time) + " s (" + Number(h.pool_time / 60) +
                         " min), target " + Number(h.target_percent) + " %." +
                         (h.message.empty() ? "" : " " + h.message));
  Table trials{"Trials in the order run",
               {"#", "trial", "DOF", "kind", "mapping", "duration (s)", "pool time after (s)",
                "model change after it"},
               {}};
  for (const io::LoopTrialRow& r : h.trials) {
    trials.rows.push_back({std::to_string(r.iteration), r.id, std::string(model::DofName(r.dof)),
                           r.kind, r.mapping, Number(r.duration), Number(r.pool_time),
                           ModelChangeCell(r)});
  }
  s.tables.push_back(std::move(trials));
  Table last{"Estimates after the last trial (" +
                 (h.predicted_assumption.empty() ? std::string("no σ was predicted")
                                                 : h.predicted_assumption) +
                 ")",
             {"DOF", "parameter", "value", "σ", "unit", "percentile error (%)", "predicted σ"},
             {}};
  for (const auto& [dof, params] : h.series) {
    for (const auto& [name, points] : params) {
      const io::LoopPoint& q = points.back();
      last.rows.push_back({std::string(model::DofName(dof)), name, Number(q.value), Number(q.sigma),
                           model::Unit(name, dof),
                           Number(q.value != 0 ? 100 * q.sigma / std::abs(q.value) : NAN),
                           Number(q.predicted)});
    }
  }
  s.tables.push_back(std::move(last));
  return s;
}

}  // namespace uuvplan::report
