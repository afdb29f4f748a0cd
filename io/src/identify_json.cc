// The `identify` result as JSON (contract §identify, docs/formats.md):
//   {"status", "message",
//    "dofs": {<dof>: {"params": {<name>: {"value", "sigma", "percentile_error", "significant",
//                                         "state", ...}},
//                     "fit": {"velocity_mae": {"trials": {<file>: v}, "fit", "validate",
//                                              "overall"}, "position_rms": {...},
//                             "zero_velocity_mae": {"fit", "validate"} (the baseline, ν ≡ 0),
//                             "trials": [...residual analysis...]},
//                     "outside_prior": [{"parameter", "value", "sigma", "range", "side",
//                                        "sigmas_beyond", "finding"}],
//                     "parameter_names", "covariance", "estimator", "stages", ...}},
//    "trials": [{"file", "dof", "use", "outliers", "gaps", "notes"}]}
// NaN (no value) is written as null.
#include "uuvplan/io/identify_json.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>
#include <vector>

#include "uuvplan/io/campaign_yaml.h"
#include "uuvplan/io/json_value.h"
#include "uuvplan/text/identify_table.h"
#include "uuvplan/text/trial_notes_text.h"

namespace uuvplan::io {
namespace {

using nlohmann::json;

json ParamJson(const ident::ParameterEstimate& e, bool reliable) {
  json j = {
      {"value", JsonNumber(e.value)},
      {"sigma", JsonNumber(e.state == ident::ParameterState::kEstimated ? e.sigma : std::nan(""))},
      {"significant", e.significant},
      {"state", std::string(ident::ParameterStateName(e.state))}};
  if (e.state == ident::ParameterState::kEstimated) {
    j["percentile_error"] = JsonNumber(e.percentile_error());
  }
  if (e.state == ident::ParameterState::kDropped) {
    j["value_before_drop"] = JsonNumber(e.value_before_drop);
    j["sigma_before_drop"] = JsonNumber(e.sigma_before_drop);
    j["percentile_error"] = JsonNumber(e.percentile_error());
  }
  if (!reliable) j["reliable"] = false;
  return j;
}

json EstimatesJson(const std::vector<ident::ParameterEstimate>& estimates) {
  json j = json::object();
  for (const auto& e : estimates) j[e.name] = ParamJson(e, true);
  return j;
}

json ResidualJson(const ident::ResidualAnalysis& a) {
  json acf = json::array();
  for (double v : a.autocorrelation) acf.push_back(JsonNumber(v));
  json counts = json::array(), edges = json::array();
  for (int c : a.histogram.counts) counts.push_back(c);
  for (double e : a.histogram.edges) edges.push_back(JsonNumber(e));
  return {{"n", a.n},
          {"mean", JsonNumber(a.mean)},
          {"std", JsonNumber(a.std)},
          {"rms", JsonNumber(a.rms)},
          {"white", a.white},
          {"lags_outside", a.lags_outside},
          {"bound95", JsonNumber(a.bound95)},
          {"lag_step", JsonNumber(a.lag_step_s)},
          {"autocorrelation", acf},
          {"histogram",
           {{"edges", edges},
            {"counts", counts},
            {"skewness", JsonNumber(a.histogram.skewness)},
            {"excess_kurtosis", JsonNumber(a.histogram.excess_kurtosis)}}}};
}

// {"trials": {<file>: v}, "fit", "validate", "overall"} of one fit figure.
json FigureJson(const json& per_trial, double fit, double validate, double overall) {
  return {{"trials", per_trial},
          {"fit", JsonNumber(fit)},
          {"validate", JsonNumber(validate)},
          {"overall", JsonNumber(overall)}};
}

json FitTrialJson(const ident::TrialFit& t) {
  return {{"file", t.name},
          {"use", std::string(model::TrialUseName(t.use))},
          {"velocity_mae", JsonNumber(t.velocity_mae)},
          {"zero_velocity_mae", JsonNumber(t.zero_velocity_mae)},
          {"velocity_reference", t.velocity_reference},
          {"velocity_samples", t.velocity_samples},
          {"position_rms", JsonNumber(t.position_rms)},
          {"position_samples", t.position_samples},
          {"initial_state", {JsonNumber(t.initial_position), JsonNumber(t.initial_velocity)}},
          {"residuals", ResidualJson(t.residuals)},
          {"residual_signal", t.residual_signal}};
}

json FitJson(const ident::FitSummary& f) {
  json mae_trials = json::object(), rms_trials = json::object(), trials = json::array();
  for (const auto& t : f.trials) {
    mae_trials[t.name] = JsonNumber(t.velocity_mae);
    rms_trials[t.name] = JsonNumber(t.position_rms);
    trials.push_back(FitTrialJson(t));
  }
  return {{"velocity_mae",
           FigureJson(mae_trials, f.velocity_mae_fit, f.velocity_mae_validate, f.velocity_mae_all)},
          {"position_rms",
           FigureJson(rms_trials, f.position_rms_fit, f.position_rms_validate, f.position_rms_all)},
          {"zero_velocity_mae",
           {{"fit", JsonNumber(f.zero_velocity_mae_fit)},
            {"validate", JsonNumber(f.zero_velocity_mae_validate)}}},
          {"trials", trials}};
}

json MatrixJson(const Eigen::MatrixXd& m) {
  json rows = json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    json r = json::array();
    for (Eigen::Index k = 0; k < m.cols(); ++k) r.push_back(JsonNumber(m(i, k)));
    rows.push_back(r);
  }
  return rows;
}

// What the linear least-squares stages (steady state, one-step) both report. JSON objects keep
// their keys sorted, so the order in which a stage adds its own keys does not show.
json LinearStageJson(std::string status, const std::string& message, double condition_number,
                     const std::vector<std::string>& not_identifiable,
                     const std::vector<std::string>& not_excited,
                     const std::vector<ident::ParameterEstimate>& estimates) {
  return {{"status", std::move(status)},
          {"message", message},
          {"condition_number", JsonNumber(condition_number)},
          {"not_identifiable", not_identifiable},
          {"not_excited", not_excited},
          {"params", EstimatesJson(estimates)}};
}

json SteadyStageJson(const ident::SteadyStateResult& r) {
  json j = LinearStageJson(std::string(ident::SteadyStatusName(r.status)), r.message,
                           r.condition_number, r.not_identifiable, r.not_excited, r.estimates);
  j["segments"] = r.num_points;
  j["sigma2"] = JsonNumber(r.sigma2);
  return j;
}

json InertiaStageJson(const ident::IntegralInertiaResult& r) {
  return {{"status", std::string(ident::FitStatusName(r.status))},
          {"message", r.message},
          {"samples", r.num_samples},
          {"params", {{"m", {{"value", JsonNumber(r.m)}, {"sigma", JsonNumber(r.sigma)}}}}},
          {"sigma_eq11", JsonNumber(r.sigma_eq11)},
          {"sigma_hac", JsonNumber(r.sigma_hac)},
          {"sigma_known", JsonNumber(r.sigma_known)}};
}

json OneStepStageJson(const ident::OneStepDofResult& r) {
  json o = LinearStageJson(std::string(ident::FitStatusName(r.status)), r.message,
                           r.condition_number, r.not_identifiable, r.not_excited, r.estimates);
  o["rows"] = r.num_rows;
  o["instrumental_variables"] = r.instrumental;
  o["cost"] = JsonNumber(r.cost);
  if (r.standard && r.ok()) {
    const auto& c = r.seed;
    const auto& C = r.seed_covariance;
    const auto coefficient = [&C](double value, int i) {
      return json{{"value", value}, {"sigma", JsonNumber(std::sqrt(C(i, i)))}};
    };
    o["coefficients"] = {{"alpha", coefficient(c.alpha, 0)},
                         {"beta", coefficient(c.beta, 1)},
                         {"gamma", coefficient(c.gamma, 2)},
                         {"delta", coefficient(c.delta, 3)}};
  }
  return o;
}

json OutputErrorStageJson(const ident::OutputErrorResult& oe) {
  json init = json::array();
  for (const auto& i : oe.initial) {
    init.push_back({{"trial", i.trial},
                    {"position", i.chi0_estimated ? JsonNumber(i.chi0) : json(nullptr)},
                    {"velocity", JsonNumber(i.xi0)},
                    {"velocity_estimated", i.xi0_estimated}});
  }
  return {{"status", std::string(ident::OutputErrorStatusName(oe.status))},
          {"message", oe.message},
          {"iterations", oe.iterations},
          {"measurements", oe.num_residuals},
          {"sigma2", JsonNumber(oe.sigma2)},
          {"condition_number", JsonNumber(oe.condition_number)},
          {"residual_lag1", JsonNumber(oe.residual_lag1)},
          {"hac_covariance", oe.hac_covariance},
          {"not_identifiable", oe.not_identifiable},
          {"initial_states", init},
          {"params", EstimatesJson(oe.estimates)}};
}

// Ref 004 eq. 15 with its whole trace: the physical parameters and their σ after every
// update (rows in campaign time), the final estimate with its covariance.
json RlsStageJson(const ident::RlsDofResult& r) {
  json estimated = json::array();
  for (std::size_t j = 0; j < r.names.size(); ++j) {
    if (r.state.size() == r.names.size() && r.state[j] == ident::ParameterState::kEstimated) {
      estimated.push_back(r.names[j]);
    }
  }
  return {
      {"status", std::string(ident::FitStatusName(r.status))},
      {"message", r.message},
      {"forgetting", r.lambda},
      {"rows", r.psi.t.size()},
      {"parameter_names", r.names},
      {"estimated", estimated},
      {"not_excited", r.not_excited},
      {"residual_autocovariance", {JsonNumber(r.psi.gamma0), JsonNumber(r.psi.gamma1)}},
      {"covariance", MatrixJson(r.covariance)},
      {"trace", {{"t", r.psi.t}, {"theta", MatrixJson(r.theta)}, {"sigma", MatrixJson(r.sigma)}}}};
}

json StagesJson(const ident::DofIdentification& d) {
  json s = json::object();
  if (d.steady) s["steady_state"] = SteadyStageJson(*d.steady);
  if (d.inertia) s["integral_inertia"] = InertiaStageJson(*d.inertia);
  if (d.one_step) s["one_step_ls"] = OneStepStageJson(*d.one_step);
  if (d.output_error) s["output_error"] = OutputErrorStageJson(*d.output_error);
  if (d.rls) s["rls"] = RlsStageJson(*d.rls);
  return s;
}

// What the data preparation excluded from a trial: outliers and gaps, on the campaign clock.
json TrialReportJson(const ident::TrialReport& t) {
  json outliers = json::array(), gaps = json::array();
  const auto add = [&](const char* signal, const auto& list) {
    for (const auto& o : list) {
      outliers.push_back({{"signal", signal},
                          {"t", o.t + t.time_offset},
                          {"value", o.value},
                          {"residual", JsonNumber(o.residual)}});
    }
  };
  add("position", t.position_outliers);
  add("velocity", t.velocity_outliers);
  for (const auto& g : t.gaps) {
    gaps.push_back({{"t0", g.t0 + t.time_offset}, {"t1", g.t1 + t.time_offset}});
  }
  return {{"index", t.index},
          {"file", t.file},
          {"dof", std::string(model::DofName(t.dof))},
          {"use", std::string(model::TrialUseName(t.use))},
          {"outliers", outliers},
          {"gaps", gaps},
          {"notes", text::NoteTexts(t.notes)}};
}

}  // namespace

json ParamsJson(const ident::DofIdentification& d) {
  json p = json::object();
  for (const auto& e : d.params) {
    p[e.name] = {{"value", JsonNumber(e.value)}, {"sigma", JsonNumber(e.sigma)}};
  }
  return p;
}

// Each estimate outside the vehicle file's a priori range, with the finding's sentence.
json OutsidePriorJson(const ident::DofIdentification& d) {
  json list = json::array();
  for (const auto& o : d.outside_prior) {
    list.push_back({{"parameter", o.parameter},
                    {"value", JsonNumber(o.value)},
                    {"sigma", JsonNumber(o.sigma)},
                    {"range", {JsonNumber(o.lo), JsonNumber(o.hi)}},
                    {"side", o.above() ? "above" : "below"},
                    {"sigmas_beyond", JsonNumber(o.SigmasBeyond())},
                    {"finding", text::OutsidePriorText(d.dof, o)}});
  }
  return list;
}

json DofIdentificationJson(const ident::DofIdentification& d) {
  json params = json::object();
  for (const auto& e : d.params) {
    const bool reliable =
        std::find(d.unreliable.begin(), d.unreliable.end(), e.name) == d.unreliable.end();
    params[e.name] = ParamJson(e, reliable);
  }
  json segments = json::array();
  for (const auto& p : d.steady_points) {
    segments.push_back({{"trial", p.trial},
                        {"t0", p.t0},
                        {"t1", p.t1},
                        {"speed", JsonNumber(p.xi)},
                        {"sigma", JsonNumber(p.sigma_xi)},
                        {"force", p.phi},
                        {"ballast_steps", p.ballast_steps},
                        {"user_marked", p.user_marked}});
  }
  return {{"status", std::string(ident::IdentifyStatusName(d.status))},
          {"message", d.message},
          {"estimator", std::string(ident::FinalEstimatorName(d.estimator))},
          {"params", params},
          {"fit", FitJson(d.fit)},
          {"parameter_names", d.parameter_names},
          {"covariance", MatrixJson(d.covariance)},
          {"fit_trials", d.fit_trials},
          {"validate_trials", d.validate_trials},
          {"steady_segments", segments},
          {"stages", StagesJson(d)},
          {"closed_loop_suspected", d.closed_loop_suspected},
          {"outside_prior", OutsidePriorJson(d)},
          {"notes", d.notes},
          {"warnings", d.warnings}};
}

json IdentifyJson(const ident::IdentifyResult& r) {
  json dofs = json::object();
  for (const auto& d : r.dofs) dofs[std::string(model::DofName(d.dof))] = DofIdentificationJson(d);
  json trials = json::array();
  for (const auto& t : r.trials) trials.push_back(TrialReportJson(t));
  return {{"status", std::string(ident::IdentifyStatusName(r.status))},
          {"message", r.message},
          {"method", std::string(ident::MethodName(r.method))},
          {"dofs", dofs},
          {"trials", trials},
          {"notes", r.notes}};
}

}  // namespace uuvplan::io
