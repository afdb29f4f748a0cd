// The `diagnose` result as JSON (contract §diagnose): the nominal identification, the findings
// ordered by gain, every candidate test and the standard model's error breakdown.
#include "uuvplan/io/diagnosis_json.h"

#include "uuvplan/io/identify_json.h"
#include "uuvplan/io/json_value.h"
#include "uuvplan/text/diagnosis_notes_text.h"
#include "uuvplan/text/finding_text.h"

namespace uuvplan::io {
namespace {

using nlohmann::json;

json GroupsJson(const std::vector<ident::ErrorGroup>& groups) {
  json out = json::array();
  for (const auto& g : groups) {
    out.push_back({{"label", g.label},
                   {"relative", g.relative},
                   {"velocity_mae", g.mae},
                   {"samples", g.samples}});
  }
  return out;
}

json ThrustMapJson(const ident::CorrectedThrustMap& m) {
  json rows = json::array();
  for (const auto& r : m.rows) {
    rows.push_back({{"command", r.command},
                    {"nominal", r.nominal},
                    {"delivered", r.delivered},
                    {"sigma", r.sigma}});
  }
  for (std::size_t i = 0; i < m.chosen_force.size() && i < rows.size(); ++i) {
    rows[i]["chosen"] = JsonNumber(m.chosen_force[i]);
  }
  return {{"mapping", m.mapping},
          {"thruster", m.thruster},
          {"shape", m.shape},
          {"command_exponent", JsonNumber(m.command_exponent)},
          {"command_exponent_sigma", JsonNumber(m.command_exponent_sigma)},
          {"command_range", {m.smallest_command, m.largest_command}},
          {"thrust", {{"model", "poly2"}, {"a", m.poly2_a}, {"b", m.poly2_b}}},
          {"rows", rows}};
}

// A model of one DOF: {"params": {<name>: {value, sigma}}, "settings", "velocity_mae":
// {fit, validate}} (its free runs, as `uuvplan score` computes them).
json ModelJson(const ident::DofIdentification& d) {
  json params = json::object();
  for (std::size_t i = 0; i < d.parameter_names.size(); ++i) {
    const ident::ParameterEstimate* e = d.Param(d.parameter_names[i]);
    params[d.parameter_names[i]] = {{"value", d.theta[static_cast<Eigen::Index>(i)]},
                                    {"sigma", JsonNumber(e ? e->sigma : 0.0)}};
  }
  return {{"params", params},
          {"settings", d.structure.settings},
          {"velocity_mae",
           {{"fit", JsonNumber(d.fit.velocity_mae_fit)},
            {"validate", JsonNumber(d.fit.velocity_mae_validate)}}}};
}

// The static maps compared in place of a thrust_map's power law (SI; NaN as null).
json StaticMapsJson(const ident::Finding& f) {
  json out = json::array();
  for (const auto& c : f.static_maps) {
    json params = json::object();
    for (const auto& p : c.params) params[p.name] = {{"value", p.value}, {"sigma", p.sigma}};
    out.push_back({{"shape", c.shape},
                   {"params", params},
                   {"aic", JsonNumber(c.aic)},
                   {"validate_mae", JsonNumber(c.validate_mae)},
                   {"vs_power_law", JsonNumber(c.vs_power_law)},
                   {"vs_power_law_sigma", JsonNumber(c.vs_power_law_sigma)},
                   {"scored", c.scored},
                   {"physical", c.physical}});
  }
  return out;
}

}  // namespace

json GainJson(const ident::DiagnosisGain& gain) {
  return {{"metric", gain.metric},
          {"before", gain.before},
          {"after", gain.after},
          {"relative", JsonNumber(gain.relative)},
          {"on", gain.on}};
}

namespace {

json FindingJson(const ident::DiagnosisResult& r, const ident::Finding& f) {
  json params = json::object();
  for (const auto& p : f.params) params[p.name] = {{"value", p.value}, {"sigma", p.sigma}};
  json maps = json::array();
  for (const auto& m : f.thrust_maps) maps.push_back(ThrustMapJson(m));
  return {{"effect", f.effect},
          {"dof", std::string(model::DofName(f.dof))},
          {"what", text::FindingSentence(r, f)},
          {"extension", {{"params", params}}},
          {"gain", GainJson(f.gain)},
          {"thrust_maps", maps},
          {"static_maps", StaticMapsJson(f)},
          {"chosen_map", f.chosen_map},
          {"statistic", f.statistic},
          {"p_value", f.p_value},
          {"added_parameters", f.added_parameters}};
}

json CandidateTestJson(const ident::CandidateTest& t) {
  return {{"effect", t.effect},
          {"dof", std::string(model::DofName(t.dof))},
          {"detail", t.detail},
          {"round", t.round},
          {"statistic", t.statistic},
          {"added_parameters", t.added_parameters},
          {"p_value", t.p_value},
          {"max_z", JsonNumber(t.max_z)},
          {"significant", t.significant},
          {"gain", JsonNumber(t.gain)},
          {"unscored", t.unscored},
          {"non_physical", t.non_physical},
          {"accepted", t.accepted},
          {"not_chosen", text::NotChosenText(t)},
          {"removed", text::RemovedText(t)}};
}

json BreakdownJson(const ident::ErrorBreakdown& b) {
  return {{"by_thrust", GroupsJson(b.by_thrust)},
          {"by_motion", GroupsJson(b.by_motion)},
          {"by_speed", GroupsJson(b.by_speed)},
          {"by_command", GroupsJson(b.by_command)},
          {"lag_s", b.lag_s},
          {"lag_sigma_s", JsonNumber(b.lag_sigma_s)},
          {"drift_per_hour", JsonNumber(b.drift_per_hour)},
          {"drift_sigma_per_hour", JsonNumber(b.drift_sigma_per_hour)},
          {"velocity_mae", b.velocity_mae}};
}

}  // namespace

json DiagnosisJson(const ident::DiagnosisResult& r) {
  json findings = json::array(), tests = json::array(), breakdown = json::object();
  for (const auto& f : r.findings) findings.push_back(FindingJson(r, f));
  for (const auto& t : r.tests) tests.push_back(CandidateTestJson(t));
  json extended = json::object(), standard = json::object();
  for (const auto& e : r.extended) extended[std::string(model::DofName(e.dof))] = ModelJson(e);
  for (const auto& e : r.standard) standard[std::string(model::DofName(e.dof))] = ModelJson(e);
  json not_diagnosed = json::object();
  for (const auto& [dof, why] : r.not_diagnosed)
    not_diagnosed[std::string(model::DofName(dof))] = why;
  for (const auto& b : r.breakdowns)
    breakdown[std::string(model::DofName(b.dof))] = BreakdownJson(b);
  return {{"nominal", IdentifyJson(r.nominal)},
          {"findings", findings},
          {"tests", tests},
          {"breakdown", breakdown},
          {"standard", standard},
          {"extended", extended},
          {"not_diagnosed", not_diagnosed},
          {"warnings", text::NoteTexts(r.warnings)},
          {"notes", text::NoteTexts(r.notes)}};
}

}  // namespace uuvplan::io
