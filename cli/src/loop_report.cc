// Printing and JSON shared by `next` and `loop` (loop_report.h).
#include "uuvplan/cli/loop_report.h"

#include <cmath>
#include <iomanip>
#include <sstream>

#include "uuvplan/cli/command.h"
#include "uuvplan/cli/text_table.h"
#include "uuvplan/cli/trial_text.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/ident/stats/monte_carlo.h"
#include "uuvplan/io/io.h"
#include "uuvplan/io/schedule_json.h"

namespace uuvplan::cli {
namespace {

using nlohmann::json;


std::string Percent(double p) {
  if (!std::isfinite(p)) return "—";
  std::ostringstream s;
  s << std::fixed << std::setprecision(p < 10 ? 2 : 1) << p << "%";
  return s.str();
}

// "5.00%" at or below the target, "12.3%*" above it; a value above it that rounds to it gets
// six significant digits that show it ("5.0012%*", not "5.00%*").
std::string PercentAgainst(double p, double target) {
  if (p <= target) return Percent(p);
  std::string text = Percent(p);
  if (text == Percent(target)) {
    std::ostringstream s;
    s << std::setprecision(6) << p << "%";
    text = s.str();
  }
  return text + "*";
}

}  // namespace

std::string TrialLine(const model::TrialDesign& d) {
  std::ostringstream s;
  s << std::left << std::setw(9) << model::TrialKindName(d.kind) << std::setw(22) << d.mapping
    << std::right << std::setw(9) << model::DurationText(d.duration) << "  "
    << ForceText(d, kLoopForceStyle);
  if (d.ballast_steps != 0) s << ", ballast " << d.ballast_steps;
  return s.str();
}

int ExitStatus(planner::LoopStatus s) {
  switch (s) {
    case planner::LoopStatus::kConverged: return kExitOk;
    case planner::LoopStatus::kInfeasible: return kExitActionNeeded;
    case planner::LoopStatus::kBudgetSpent: return kExitBudgetSpent;
    case planner::LoopStatus::kStuck: return kExitStuck;
    case planner::LoopStatus::kRefused: return kExitRefused;
  }
  return kExitActionNeeded;
}

int ExitStatus(planner::NextStatus s) {
  switch (s) {
    case planner::NextStatus::kTrial:
    case planner::NextStatus::kConverged: return kExitOk;
    case planner::NextStatus::kInfeasible: return kExitActionNeeded;
    case planner::NextStatus::kStuck: return kExitStuck;
    case planner::NextStatus::kRefused: return kExitRefused;
  }
  return kExitActionNeeded;
}

std::string InterestText(model::Dof dof, const planner::InterestParameter& q, double target) {
  const std::string unit = model::Unit(q.name, dof);
  const std::string u = unit == "1" ? "" : " " + unit;
  std::ostringstream s;
  s << q.name << " ";
  if (!std::isfinite(q.value)) return s.str() + "—";
  s << model::Significant(q.value, 4) << u;
  if (std::isfinite(q.sigma)) s << " ± " << model::Significant(q.sigma, 3);
  else s << " (no σ: not estimated)";
  if (q.estimated) s << " (" << PercentAgainst(q.percent, target) << ")";
  if (q.held) s << " [HELD: no information]";
  if (!q.physical) s << " [NON-PHYSICAL]";
  return s.str();
}

json CandidatesJson(const std::vector<planner::CandidateGain>& candidates) {
  json j = json::array();
  for (const auto& c : candidates) {
    j.push_back({{"dof", std::string(model::DofName(c.dof))},
                 {"trial", c.trial},
                 {"parameter", c.parameter},
                 {"sigma_now", io::JsonNumber(c.sigma_now)},
                 {"sigma_after", io::JsonNumber(c.sigma_after)},
                 {"gain", io::JsonNumber(c.gain)},
                 {"trials_to_target", io::JsonNumber(c.trials_to_target)},
                 {"first_estimate", c.first_estimate},
                 {"negligible", c.negligible}});
  }
  return j;
}

namespace {

std::string DofHeadline(const planner::DofProgress& p, double target) {
  if (p.converged) return "converged: every parameter of interest below " + Percent(target);
  if (p.precise) {
    return "every parameter of interest below " + Percent(target) + " but NOT trusted";
  }
  if (!std::isfinite(p.worst_percent)) {
    return "worst " + p.worst + ": not estimated yet (target " + Percent(target) + ")";
  }
  return "worst " + p.worst + " at " + Percent(p.worst_percent) + " (target " + Percent(target) +
         ")";
}

// One row of a DOF's interest table: parameter, value, σ, percentile error, state; with a
// truth also the true value and the estimate's error against it (in % and in σ).
std::vector<std::string> InterestRow(model::Dof dof, const planner::InterestParameter& q,
                                     double target, const model::Truth* truth) {
  const std::string unit = model::Unit(q.name, dof);
  std::vector<std::string> row{std::string(model::DofName(dof)), q.name};
  if (std::isfinite(q.value)) {
    row.insert(row.end(), {Quantity(q.value, unit, 4), Quantity(q.sigma, unit, 3),
                           q.estimated ? model::Significant(q.percent, 3) : "-",
                           !q.estimated ? "held" : q.percent <= target ? "ok" : "above target"});
  } else {
    row.insert(row.end(), {"-", "-", "-", "not estimated yet"});
  }
  if (truth != nullptr) {
    const double v = ident::TrueParameter(*truth, dof, q.name);
    const bool compared = std::isfinite(q.value) && v != 0;
    row.insert(row.end(),
               {Quantity(v, unit, 4),
                compared ? model::Significant(100.0 * (q.value - v) / std::abs(v), 3) : "-",
                compared ? model::Significant((q.value - v) / q.sigma, 2) : "-"});
  }
  return row;
}

}  // namespace

void PrintProgress(const std::vector<planner::DofProgress>& progress, double target,
                   std::ostream& out, const model::Truth* truth) {
  for (const auto& p : progress) {
    out << "  " << model::DofName(p.dof) << " (" << p.trials << " trial"
        << (p.trials == 1 ? "" : "s") << "): " << DofHeadline(p, target) << "\n";
    std::vector<std::string> titles{"DOF", "parameter", "value", "σ", "error (%)", "state"};
    if (truth != nullptr) titles.insert(titles.end(), {"true", "off truth (%)", "off truth (σ)"});
    TextTable table(titles);
    for (const auto& q : p.interest) table.AddRow(InterestRow(p.dof, q, target, truth));
    table.Print(out, "    ");
    for (const auto& q : p.interest) {
      if (!q.flag.empty()) out << "      ! " << q.name << ": " << q.flag << "\n";
    }
    if (p.consistency.tested) out << "    consistency: " << p.consistency.text << "\n";
    if (!p.converged) {
      for (const auto& d : p.doubts) {
        if (d != p.consistency.text) out << "    not trusted: " << d << "\n";
      }
    }
  }
}

json ProgressJson(const std::vector<planner::DofProgress>& progress) {
  json j = json::object();
  for (const auto& p : progress) {
    json interest = json::object();
    for (const auto& q : p.interest) {
      interest[q.name] = std::isfinite(q.value) ? json{{"value", io::JsonNumber(q.value)},
                                                        {"sigma", io::JsonNumber(q.sigma)},
                                                        {"percent", io::JsonNumber(q.percent)},
                                                        {"unit", model::Unit(q.name, p.dof)},
                                                        {"held", q.held},
                                                        {"physical", q.physical},
                                                        {"flag", q.flag}}
                                                  : json(nullptr);
    }
    json consistency = nullptr;
    if (p.consistency.tested) {
      consistency = {{"chi2", io::JsonNumber(p.consistency.chi2)},
                     {"dof", p.consistency.dof},
                     {"p_value", io::JsonNumber(p.consistency.p_value)},
                     {"level", p.consistency.level},
                     {"consistent", p.consistency.consistent},
                     {"worst", p.consistency.worst},
                     {"worst_sigmas", io::JsonNumber(p.consistency.worst_sigmas)}};
    }
    j[std::string(model::DofName(p.dof))] = {
        {"converged", p.converged}, {"worst", p.worst},   {"worst_percent", io::JsonNumber(p.worst_percent)},
        {"trials", p.trials},       {"usable", p.usable}, {"status", p.status},
        {"precise", p.precise},     {"trusted", p.trusted}, {"doubts", p.doubts},
        {"refusal", p.refusal},     {"consistency", consistency}, {"interest", interest}};
  }
  return j;
}

json PredictedJson(model::Dof dof, const planner::PredictedPrecision& p) {
  return {{std::string(model::DofName(dof)), io::PredictedToJson(p)}};
}

}  // namespace uuvplan::cli
