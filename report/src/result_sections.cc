// The estimates, their validation and the diagnosis.
#include <cmath>

#include "figure_parts.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/report/sections.h"
#include "uuvplan/text/diagnosis_notes_text.h"
#include "uuvplan/text/finding_text.h"

namespace uuvplan::report {

namespace {

std::string StateText(const ident::ParameterEstimate& e) {
  switch (e.state) {
    case ident::ParameterState::kEstimated:
      return e.significant ? "estimated" : "not significant";
    case ident::ParameterState::kDropped:
      return "dropped (insignificant)";
    default:
      return "held";
  }
}

}  // namespace

Section EstimatesSection(const ident::IdentifyResult& result) {
  Section s{"estimates", "Estimates", {}, {}, {}};
  s.paragraphs.push_back(
      "Identification: " + std::string(ident::IdentifyStatusName(result.status)) +
      (result.message.empty() ? "" : " — " + result.message));
  Table t{"Parameters (value ± σ)",
          {"DOF", "parameter", "value", "σ", "unit", "percentile error 100·σ/|θ| (%)", "state",
           "estimator"},
          {}};
  for (const ident::DofIdentification& d : result.dofs) {
    for (const ident::ParameterEstimate& e : d.params) {
      t.rows.push_back({DofText(d.dof), e.name, Number(e.value), Number(e.sigma),
                        model::Unit(e.name, d.dof), Number(e.percentile_error()), StateText(e),
                        std::string(ident::FinalEstimatorName(d.estimator))});
    }
  }
  s.tables.push_back(std::move(t));
  for (const ident::DofIdentification& d : result.dofs) {
    if (!d.message.empty())
      s.paragraphs.push_back(DofText(d.dof) + ": " +
                             std::string(ident::IdentifyStatusName(d.status)) + " — " + d.message);
    for (const auto& w : d.warnings) s.paragraphs.push_back(DofText(d.dof) + " warning: " + w);
  }
  return s;
}

Section ValidationSection(const ident::IdentifyResult& result) {
  Section s{"validation", "Validation", {}, {}, {}};
  s.paragraphs.push_back(
      "Free run of every trial with the identified model (no re-initialisation): "
      "velocity mean absolute error (seed 002 eq. 37) against the zero-velocity "
      "model's, position RMS error, and the residuals' whiteness (seed 004 §5.2).");
  Table t{"Free runs",
          {"trial", "DOF", "use", "velocity MAE", "zero-velocity MAE", "velocity unit",
           "position RMS", "position unit", "lags outside ±1.96/√N (of 20)", "white"},
          {}};
  for (const ident::DofIdentification& d : result.dofs) {
    for (const ident::TrialFit& f : d.fit.trials) {
      t.rows.push_back({f.name, DofText(d.dof), f.use == model::TrialUse::kFit ? "fit" : "validate",
                        Number(f.velocity_mae), Number(f.zero_velocity_mae),
                        std::string(model::VelocityUnit(d.dof)), Number(f.position_rms),
                        std::string(model::PositionUnit(d.dof)),
                        std::to_string(f.residuals.lags_outside),
                        f.residuals.white ? "yes" : "no"});
    }
  }
  s.tables.push_back(std::move(t));
  return s;
}

namespace {

Table FindingTable(const ident::DiagnosisResult& r) {
  Table t{"Findings (largest gain first)",
          {"effect", "DOF", "what goes wrong", "new parameters (value ± σ unit)",
           "velocity MAE before", "after", "unit", "gain (%)", "on"},
          {}};
  for (const ident::Finding& f : r.findings) {
    std::string params;
    for (const auto& p : f.params) {
      params += (params.empty() ? "" : "; ") + p.name + " = " + Number(p.value) + " ± " +
                Number(p.sigma) + " " + model::Unit(p.name, f.dof);
    }
    t.rows.push_back({f.effect, DofText(f.dof), text::FindingSentence(r, f), params,
                      Number(f.gain.before), Number(f.gain.after),
                      std::string(model::VelocityUnit(f.dof)), Number(100 * f.gain.relative),
                      f.gain.on});
  }
  return t;
}

Table TestTable(const ident::DiagnosisResult& r) {
  Table t{"Every candidate tested",
          {"effect", "DOF", "round", "detail", "likelihood ratio D (1)", "p-value (1)",
           "largest z (σ)", "significant", "held-out gain (%)", "accepted"},
          {}};
  for (const ident::CandidateTest& c : r.tests) {
    t.rows.push_back({c.effect, DofText(c.dof), std::to_string(c.round), c.detail,
                      Number(c.statistic), Number(c.p_value), Number(c.max_z),
                      c.significant ? "yes" : "no", Number(100 * c.gain),
                      c.accepted ? "yes" : "no"});
  }
  return t;
}

}  // namespace

Section DiagnosisSection(const ident::DiagnosisResult& r) {
  Section s{"diagnosis", "Diagnosis", {}, {}, {}};
  s.paragraphs.push_back(r.findings.empty() ? "No effect beyond the standard model was found."
                                            : std::to_string(r.findings.size()) +
                                                  " effect(s) found beyond the standard model.");
  for (const auto& [dof, why] : r.not_diagnosed)
    s.paragraphs.push_back(DofText(dof) + " not diagnosed: " + why);
  for (const auto& w : r.warnings) s.paragraphs.push_back("Warning: " + text::NoteText(w));
  s.tables.push_back(FindingTable(r));
  s.tables.push_back(TestTable(r));
  return s;
}

}  // namespace uuvplan::report
