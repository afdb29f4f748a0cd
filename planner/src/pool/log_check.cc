// Is a logged trial the planned one (log_check.h)?
#include "uuvplan/planner/pool/log_check.h"

#include <algorithm>
#include <cmath>

#include "uuvplan/model/util/median.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::planner {
namespace {

using model::Significant;

// Median |F_log − φ_n| over the log's rows with a force, t from the log's first row.
double MedianForceDeviation(const model::TrialDesign& design, const std::vector<double>& t,
                            const std::vector<double>& force) {
  std::vector<double> deviation;
  for (std::size_t i = 0; i < t.size(); ++i) {
    if (std::isnan(force[i]) || t[i] - t.front() > design.duration) continue;
    deviation.push_back(std::abs(force[i] - design.NominalForce(t[i] - t.front())));
  }
  return deviation.empty() ? INFINITY : model::Median(std::move(deviation));
}

}  // namespace

std::vector<std::string> CompareLogWithDesign(const model::TrialDesign& design, model::Dof dof,
                                              const std::string& mapping,
                                              const model::TrialLog& log,
                                              const LogCheckOptions& o) {
  std::vector<std::string> problems;
  const std::string planned = "the planned trial " + design.id;
  if (dof != design.dof) {
    problems.push_back("DOF " + std::string(model::DofName(dof)) + ", " + planned + " is on " +
                       std::string(model::DofName(design.dof)));
    return problems;
  }
  if (!mapping.empty() && mapping != design.mapping) {
    problems.push_back("mapping " + mapping + ", " + planned + " starts in " + design.mapping);
  }
  const double span = log.t.empty() ? 0.0 : log.t.back() - log.t.front();
  const auto as_planned = [&](double s) {
    return s >= o.min_duration_fraction * design.duration &&
           s <= o.max_duration_fraction * design.duration;
  };
  if (!as_planned(span) && as_planned(span / 1000)) {  // the force check would read ms as s too
    problems.push_back("the log's t spans " + model::DurationText(span) + ", 1000 times " +
                       planned + "'s " + model::DurationText(design.duration) +
                       ": is its time in ms? t / 1000 spans " + model::DurationText(span / 1000) +
                       ", as planned; write t in s");
    return problems;
  }
  if (!as_planned(span)) {
    problems.push_back("the log spans " + model::DurationText(span) + ", " + planned + " lasts " +
                       model::DurationText(design.duration) + " (expected " +
                       Significant(o.min_duration_fraction * 100, 3) + "-" +
                       Significant(o.max_duration_fraction * 100, 3) + "% of it)");
  }
  if (!log.HasForce(dof)) return problems;
  double largest = 0.0;
  for (const model::ForceDemand& d : design.Demands()) {
    largest = std::max({largest, std::abs(d.min), std::abs(d.max)});
  }
  const double deviation = MedianForceDeviation(design, log.t, log.force[model::Index(dof)]);
  if (!(deviation <= o.max_force_deviation * largest)) {
    const std::string unit = model::IsRotational(dof) ? " N·m" : " N";
    problems.push_back("force_" + std::string(model::DofName(dof)) + " departs from " + planned +
                       "'s force by " + Significant(deviation, 3) + unit + " (median), more than " +
                       Significant(o.max_force_deviation * 100, 3) + "% of its largest force " +
                       Significant(largest, 3) + unit);
  }
  return problems;
}

}  // namespace uuvplan::planner
