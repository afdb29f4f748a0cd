// A diagnosis as a readable report (docs/cli.md): the standard model's errors, the findings
// with their extension and gain, and the candidate effects tested.
#include "uuvplan/text/diagnosis_report.h"

#include <cmath>
#include <iomanip>

#include "uuvplan/model/util/text.h"
#include "uuvplan/text/diagnosis_notes_text.h"
#include "uuvplan/text/finding_text.h"
#include "uuvplan/text/identify_table.h"
#include "uuvplan/text/quantity_text.h"
#include "uuvplan/text/text_table.h"

namespace uuvplan::text {
namespace {

// Where the standard model's free-run simulation goes wrong on one DOF.
void PrintBreakdown(const ident::ErrorBreakdown& b, std::ostream& out) {
  const std::string unit(model::VelocityUnit(b.dof));
  out << "\nWhere the standard model's free-run simulation goes wrong (" << model::DofName(b.dof)
      << ", velocity MAE " << std::setprecision(4) << b.velocity_mae << " " << unit << "):\n";
  auto print = [&](const std::vector<ident::ErrorGroup>& groups) {
    for (const auto& g : groups) {
      out << "  " << std::left << std::setw(48) << g.label << std::right
          << SignedPercent(g.relative) << " speed  (MAE " << std::setprecision(4) << g.mae << " "
          << unit << ", " << g.samples << " samples)\n";
    }
  };
  print(b.by_thrust);
  print(b.by_motion);
  print(b.by_speed);
  print(b.by_command);
  out << "  " << MeasuredShiftText(b)
      << (std::isfinite(b.lag_sigma_s) || !(std::abs(b.lag_s) > 0) ? ""
                                                                   : " (σ needs 2 trials or more)")
      << "; ";
  if (std::isfinite(b.drift_per_hour)) {
    out << "speed error drifts "
        << ValueSigma(100.0 * b.drift_per_hour, 100.0 * b.drift_sigma_per_hour, "% per hour")
        << " of campaign" << (std::isfinite(b.drift_sigma_per_hour) ? "" : " (σ needs 3 trials)")
        << "\n";
  } else {
    out << "drift over the campaign not assessed (no `start` times: campaign clock unknown)\n";
  }
}

// The static maps compared in place of the power law (diagnosis.md §5), and the one chosen.
void PrintStaticMaps(const ident::Finding& f, std::ostream& out) {
  if (f.static_maps.empty()) return;
  out << "     static maps in place of the power law (linear unless another predicts the validate "
         "trials better by > 2σ, then by AIC on the fit trials): chosen "
      << (f.chosen_map.empty() ? "none (no physical fit)" : f.chosen_map) << "\n";
  for (const auto& c : f.static_maps) {
    if (!c.physical) {  // not an alternative: said why, its values stay in the JSON
      out << "       " << std::setw(11) << c.shape
          << "  rejected: " << (c.why.empty() ? "no usable fit" : c.why) << "\n";
      continue;
    }
    out << "       " << std::setw(11) << c.shape << "  AIC " << model::Significant(c.aic, 6);
    for (const auto& p : c.params) {
      const bool held = p.state == ident::ParameterState::kFixed;
      out << ", " << p.name << " = " << Cell(p.value) << (held ? "" : " ± " + Cell(p.sigma))
          << UnitSuffix(model::Unit(p.name, f.dof)) << (held ? " (held at its bound)" : "");
    }
    if (c.scored) {
      out << "; validate MAE " << model::Significant(c.validate_mae, 4)
          << UnitSuffix(std::string(model::VelocityUnit(f.dof))) << ", vs the power law "
          << (c.vs_power_law >= 0 ? "+" : "")
          << ValueSigma(c.vs_power_law, c.vs_power_law_sigma,
                        std::string(model::VelocityUnit(f.dof)))
          << (std::isfinite(c.vs_power_law_sigma) ? "" : " (its σ cannot be computed)");
    } else {
      out << "; not scored on held-out data" << (c.why.empty() ? "" : ": " + c.why);
    }
    out << "\n";
  }
}

// command, nominal, power law, chosen map: the corrected thrust map's fixed columns.
const std::vector<FixedColumn> kThrustMapColumns{{10, true}, {16, true}, {24, true}, {16, true}};

// The corrected static thrust map of a thrust_map finding, per thruster command.
void PrintThrustMap(const ident::CorrectedThrustMap& m, std::ostream& out) {
  out << "     corrected thrust map of " << m.mapping << " (thruster " << m.thruster
      << "; commands of the data " << model::Significant(m.smallest_command, 3) << " to "
      << model::Significant(m.largest_command, 3)
      << " in the vehicle file's command unit): " << m.shape
      << "\n       for the vehicle file: thrust: {model: poly2, a: "
      << model::Significant(m.poly2_a, 4) << ", b: " << model::Significant(m.poly2_b, 4) << "}\n"
      << "       "
      << FixedRow(kThrustMapColumns, {"command", "nominal (N)", "power law (N)", "chosen map (N)"})
      << "\n";
  for (std::size_t i = 0; i < m.rows.size(); ++i) {
    const auto& r = m.rows[i];
    const double chosen = i < m.chosen_force.size() ? m.chosen_force[i] : std::nan("");
    out << "       "
        << FixedRow(kThrustMapColumns,
                    {model::Significant(r.command, 3), model::Significant(r.nominal, 4),
                     model::Significant(r.delivered, 4) + " ± " + model::Significant(r.sigma, 2),
                     Cell(chosen)})
        << "\n";
  }
}

// Each finding with its extension, evidence and gain.
void PrintFindings(const ident::DiagnosisResult& r, std::ostream& out) {
  int i = 0;
  for (const auto& f : r.findings) {
    out << "  " << ++i << ". " << f.effect << " (" << model::DofName(f.dof)
        << "): " << FindingSentence(r, f) << "\n     extension:";
    for (const auto& p : f.params) {
      const bool held = p.state == ident::ParameterState::kFixed;
      out << " " << p.name << " = " << Cell(p.value) << (held ? "" : " ± " + Cell(p.sigma))
          << UnitSuffix(model::Unit(p.name, f.dof))
          << (held ? " (held at its admissible bound)" : "");
    }
    out << "\n     evidence: likelihood ratio D = " << std::setprecision(1) << f.statistic << " on "
        << f.added_parameters << " parameter(s), p = " << std::scientific << std::setprecision(1)
        << f.p_value << std::fixed << "\n     gain: velocity MAE " << std::setprecision(4)
        << f.gain.before << " -> " << f.gain.after << " " << model::VelocityUnit(f.dof) << " ("
        << std::setprecision(0) << 100.0 * f.gain.relative << "% better) on " << f.gain.on << "\n";
    for (const auto& m : f.thrust_maps) PrintThrustMap(m, out);
    PrintStaticMaps(f, out);
  }
}

// Per DOF: the baseline every candidate is compared with — the standard model refitted by
// output error with every parameter free, within the admissible ranges (ident/diagnosis.cc,
// DiagnoseDof) — which `--max-effects 0 --write-vehicle` writes and `score` scores. It differs
// from the table above where model selection dropped a parameter there.
void PrintBaseline(const ident::DiagnosisResult& r, std::ostream& out) {
  if (r.standard.empty()) return;
  out << "\nBaseline of the comparisons: the standard model refitted by output error with every "
         "parameter free (no model selection), within the admissible ranges:\n";
  for (const ident::DofIdentification& d : r.standard) {
    out << "  " << model::DofName(d.dof) << ":";
    for (const ident::ParameterEstimate& p : d.params) {
      const bool held = p.state == ident::ParameterState::kFixed;
      out << " " << p.name << " = " << Cell(p.value) << (held ? "" : " ± " + Cell(p.sigma))
          << UnitSuffix(model::Unit(p.name, d.dof)) << (held ? " (held at its bound)" : "") << ";";
    }
    out << " velocity MAE fit " << model::Significant(d.fit.velocity_mae_fit, 4);
    if (std::isfinite(d.fit.velocity_mae_validate)) {
      out << ", validate " << model::Significant(d.fit.velocity_mae_validate, 4);
    }
    out << " " << model::VelocityUnit(d.dof) << "\n";
  }
}

// Per DOF: the standard and the extended model's free-run velocity MAE (what `uuvplan score`
// gives for the file `--write-vehicle` writes).
void PrintModels(const ident::DiagnosisResult& r, std::ostream& out) {
  for (std::size_t i = 0; i < r.extended.size() && i < r.standard.size(); ++i) {
    const ident::FitSummary &a = r.standard[i].fit, &b = r.extended[i].fit;
    const std::string unit(model::VelocityUnit(r.extended[i].dof));
    auto pair = [&](double x, double y) {
      return model::Significant(x, 4) + " -> " + model::Significant(y, 4) + " " + unit +
             (x > 0 && std::isfinite(y)
                  ? " (" + model::Significant(100 * (x - y) / x, 3) + "% better)"
                  : "");
    };
    out << "  " << model::DofName(r.extended[i].dof)
        << ": velocity MAE, standard (the baseline) -> extended: fit "
        << pair(a.velocity_mae_fit, b.velocity_mae_fit);
    if (std::isfinite(a.velocity_mae_validate)) {
      out << ", validate " << pair(a.velocity_mae_validate, b.velocity_mae_validate);
    }
    out << "\n";
  }
}

// The candidates tested, one row each: DOF, round, effect, likelihood ratio D, largest z, the
// held-out gain and the verdict.
void PrintCandidateTests(const ident::DiagnosisResult& r, std::ostream& out) {
  TextTable table(
      {"DOF", "round", "effect", "detail", "D (no unit)", "z (σ)", "gain (%)", "verdict"});
  for (const auto& t : r.tests) {
    std::string verdict = t.significant ? "significant" : "not significant";
    if (std::isfinite(t.gain)) {
      verdict += t.accepted      ? ", ACCEPTED"
                 : t.removed     ? ", accepted, then removed: " + RemovedText(t)
                 : !t.not_chosen ? ", not enough gain"
                                 : ", not chosen: " + NotChosenText(t);
    }
    if (!std::isfinite(t.gain) && !t.unscored.empty()) {
      verdict += ", held-out gain cannot be scored: " + t.unscored;
    }
    if (!t.non_physical.empty()) verdict += ", non-physical: " + t.non_physical;
    table.AddRow({std::string(model::DofName(t.dof)), std::to_string(t.round), t.effect,
                  t.detail.empty() ? "-" : t.detail, model::Significant(t.statistic, 3),
                  std::isfinite(t.max_z) ? model::Significant(t.max_z, 3) : "-",
                  std::isfinite(t.gain) ? model::Significant(100.0 * t.gain, 3) : "-", verdict});
  }
  table.Print(out);
}

}  // namespace

void PrintDiagnosis(const ident::DiagnosisResult& r, std::ostream& out) {
  out << "Standard model (contract: all eta = 1, symmetric drag, no extra terms), identified by "
         "identify's chain with every eta held at 1 (model selection by the 51.02% rule):\n";
  PrintIdentifyTable(r.nominal, out);
  PrintBaseline(r, out);
  out << std::fixed;
  for (const auto& b : r.breakdowns) PrintBreakdown(b, out);
  out << "\nFindings (ordered by gain):\n";
  for (const auto& [dof, why] : r.not_diagnosed) {
    out << "  FAILED: " << model::DofName(dof) << " not diagnosed: " << why << "\n";
  }
  for (const auto& w : r.warnings) out << "  WARNING: " << NoteText(w) << "\n";
  if (r.findings.empty()) {
    // breakdowns: one per DOF whose standard model could be fitted and diagnosed.
    if (r.breakdowns.empty()) {
      out << "  none: no DOF could be diagnosed\n";
    } else {
      out << "  none: the standard model explains the data of";
      for (const auto& b : r.breakdowns) out << " " << model::DofName(b.dof);
      out << "\n";
    }
  }
  PrintFindings(r, out);
  if (!r.extended.empty()) {
    out << "\nThe extended model (all its findings; `--write-vehicle` writes it, `uuvplan score` "
           "scores it):\n";
    PrintModels(r, out);
  }
  out << "\nCandidate effects tested (significant: p < 1e-3 and a new parameter >= 3 sigma from "
         "'no effect'; accepted: also >= 0.5% better on held-out data):\n";
  PrintCandidateTests(r, out);
  for (const auto& n : r.notes) out << "note: " << NoteText(n) << "\n";
}

}  // namespace uuvplan::text
