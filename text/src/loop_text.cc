// The loop's progress for people (loop_text.h).
#include "uuvplan/text/loop_text.h"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string_view>

#include "uuvplan/ident/stats/monte_carlo.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"
#include "uuvplan/text/quantity_text.h"
#include "uuvplan/text/text_table.h"

namespace uuvplan::text {
namespace {

// "5.00%", "12.3%", "—" when not finite: 2 decimals below 10%, 1 above.
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

std::string EffectEnteredText(model::Dof dof, const planner::EffectEntered& e) {
  std::ostringstream s;
  s << e.effect << (e.detail.empty() ? "" : " (" + e.detail + ")") << " added to the "
    << model::DofName(dof) << " model:";
  const char* sep = " ";
  for (const auto& p : e.params) {
    s << sep << p.name << " " << ValueSigma(p.value, p.sigma, model::Unit(p.name, dof));
    sep = ", ";
  }
  if (e.gain.scored) {
    s << "; velocity MAE " << model::Significant(100.0 * e.gain.relative, 2) << "% lower on "
      << e.gain.on;
  }
  return s.str();
}

std::string_view DiagnosedModelAssumption() {
  return "each DOF's model is the one the diagnosis of its trials found; a thruster lag and a "
         "sensor delay (or other look-alike effects) can be taken for each other on responses "
         "slower than them, and the estimates are then those of the wrong model "
         "(docs/validation.md, \"The loop finds hidden effects\")";
}

std::string EffectLeftText(model::Dof dof, const std::string& effect) {
  return effect + " removed from the " + std::string(model::DofName(dof)) +
         " model: the diagnosis of every trial so far no longer finds it";
}

std::string InterestText(model::Dof dof, const planner::InterestParameter& q, double target) {
  std::ostringstream s;
  s << q.name << " ";
  if (!std::isfinite(q.value)) return s.str() + "—";
  s << model::Significant(q.value, 4) << UnitSuffix(model::Unit(q.name, dof));
  if (std::isfinite(q.sigma))
    s << " ± " << model::Significant(q.sigma, 3);
  else
    s << " (no σ: not estimated)";
  if (q.estimated) s << " (" << PercentAgainst(q.percent, target) << ")";
  if (q.held) s << " [HELD: no information]";
  if (!q.physical) s << " [NON-PHYSICAL]";
  return s.str();
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
                           !q.estimated          ? "held"
                           : q.percent <= target ? "ok"
                                                 : "above target"});
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

}  // namespace uuvplan::text
