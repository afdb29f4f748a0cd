#include "ident_json.h"

#include <cmath>
#include <cstdio>
#include <iomanip>
#include <sstream>

#include "uuvplan/ident/significance.h"

namespace uuvplan::tool {
namespace {

using nlohmann::json;

json Num(double v) { return std::isfinite(v) ? json(v) : json(nullptr); }

std::string UseName(model::TrialUse u) { return u == model::TrialUse::kFit ? "fit" : "validate"; }

json ParamJson(const ident::ParameterEstimate& e, bool reliable) {
  json j = {{"value", Num(e.value)},
            {"sigma", Num(e.state == ident::ParameterState::kEstimated ? e.sigma : std::nan(""))},
            {"significant", e.significant},
            {"state", std::string(ident::ParameterStateName(e.state))}};
  if (e.state == ident::ParameterState::kEstimated) {
    j["percentile_error"] = Num(e.percentile_error());
  }
  if (e.state == ident::ParameterState::kDropped) {
    j["value_before_drop"] = Num(e.value_before_drop);
    j["sigma_before_drop"] = Num(e.sigma_before_drop);
    j["percentile_error"] = Num(e.percentile_error());
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
  for (double v : a.autocorrelation) acf.push_back(Num(v));
  json counts = json::array(), edges = json::array();
  for (int c : a.histogram.counts) counts.push_back(c);
  for (double e : a.histogram.edges) edges.push_back(Num(e));
  return {{"n", a.n},
          {"mean", Num(a.mean)},
          {"std", Num(a.std)},
          {"rms", Num(a.rms)},
          {"white", a.white},
          {"lags_outside", a.lags_outside},
          {"bound95", Num(a.bound95)},
          {"lag_step", Num(a.lag_step_s)},
          {"autocorrelation", acf},
          {"histogram", {{"edges", edges},
                         {"counts", counts},
                         {"skewness", Num(a.histogram.skewness)},
                         {"excess_kurtosis", Num(a.histogram.excess_kurtosis)}}}};
}

json FitJson(const ident::FitSummary& f) {
  json mae_trials = json::object(), rms_trials = json::object(), trials = json::array();
  for (const auto& t : f.trials) {
    mae_trials[t.name] = Num(t.velocity_mae);
    rms_trials[t.name] = Num(t.position_rms);
    trials.push_back({{"file", t.name},
                      {"use", UseName(t.use)},
                      {"velocity_mae", Num(t.velocity_mae)},
                      {"velocity_reference", t.velocity_reference},
                      {"velocity_samples", t.velocity_samples},
                      {"position_rms", Num(t.position_rms)},
                      {"position_samples", t.position_samples},
                      {"initial_state", {Num(t.initial_position), Num(t.initial_velocity)}},
                      {"residuals", ResidualJson(t.residuals)},
                      {"residual_signal", t.residual_signal}});
  }
  return {{"velocity_mae",
           {{"trials", mae_trials},
            {"fit", Num(f.velocity_mae_fit)},
            {"validate", Num(f.velocity_mae_validate)},
            {"overall", Num(f.velocity_mae_all)}}},
          {"position_rms",
           {{"trials", rms_trials},
            {"fit", Num(f.position_rms_fit)},
            {"validate", Num(f.position_rms_validate)},
            {"overall", Num(f.position_rms_all)}}},
          {"trials", trials}};
}

json MatrixJson(const Eigen::MatrixXd& m) {
  json rows = json::array();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    json r = json::array();
    for (Eigen::Index k = 0; k < m.cols(); ++k) r.push_back(Num(m(i, k)));
    rows.push_back(r);
  }
  return rows;
}

json StagesJson(const ident::DofIdentification& d) {
  json s = json::object();
  if (d.steady) {
    s["steady_state"] = {{"status", std::string(ident::SteadyStatusName(d.steady->status))},
                         {"message", d.steady->message},
                         {"segments", d.steady->num_points},
                         {"condition_number", Num(d.steady->condition_number)},
                         {"sigma2", Num(d.steady->sigma2)},
                         {"not_identifiable", d.steady->not_identifiable},
                         {"not_excited", d.steady->not_excited},
                         {"params", EstimatesJson(d.steady->estimates)}};
  }
  if (d.inertia) {
    s["integral_inertia"] = {{"status", std::string(ident::FitStatusName(d.inertia->status))},
                             {"message", d.inertia->message},
                             {"samples", d.inertia->num_samples},
                             {"params", {{"m", {{"value", Num(d.inertia->m)},
                                                {"sigma", Num(d.inertia->sigma)}}}}},
                             {"sigma_eq11", Num(d.inertia->sigma_eq11)},
                             {"sigma_hac", Num(d.inertia->sigma_hac)},
                             {"sigma_known", Num(d.inertia->sigma_known)}};
  }
  if (d.one_step) {
    json o = {{"status", std::string(ident::FitStatusName(d.one_step->status))},
              {"message", d.one_step->message},
              {"rows", d.one_step->num_rows},
              {"instrumental_variables", d.one_step->instrumental},
              {"condition_number", Num(d.one_step->condition_number)},
              {"cost", Num(d.one_step->cost)},
              {"not_identifiable", d.one_step->not_identifiable},
              {"not_excited", d.one_step->not_excited},
              {"params", EstimatesJson(d.one_step->estimates)}};
    if (d.one_step->standard && d.one_step->ok()) {
      const auto& c = d.one_step->seed;
      const auto& C = d.one_step->seed_covariance;
      o["coefficients"] = {{"alpha", {{"value", c.alpha}, {"sigma", Num(std::sqrt(C(0, 0)))}}},
                           {"beta", {{"value", c.beta}, {"sigma", Num(std::sqrt(C(1, 1)))}}},
                           {"gamma", {{"value", c.gamma}, {"sigma", Num(std::sqrt(C(2, 2)))}}},
                           {"delta", {{"value", c.delta}, {"sigma", Num(std::sqrt(C(3, 3)))}}}};
    }
    s["one_step_ls"] = o;
  }
  if (d.output_error) {
    const auto& oe = *d.output_error;
    json init = json::array();
    for (const auto& i : oe.initial) {
      init.push_back({{"trial", i.trial},
                      {"position", i.chi0_estimated ? Num(i.chi0) : json(nullptr)},
                      {"velocity", Num(i.xi0)},
                      {"velocity_estimated", i.xi0_estimated}});
    }
    s["output_error"] = {{"status", std::string(ident::OutputErrorStatusName(oe.status))},
                         {"message", oe.message},
                         {"iterations", oe.iterations},
                         {"measurements", oe.num_residuals},
                         {"sigma2", Num(oe.sigma2)},
                         {"condition_number", Num(oe.condition_number)},
                         {"residual_lag1", Num(oe.residual_lag1)},
                         {"hac_covariance", oe.hac_covariance},
                         {"not_identifiable", oe.not_identifiable},
                         {"initial_states", init},
                         {"params", EstimatesJson(oe.estimates)}};
  }
  return s;
}

}  // namespace

json ParamsJson(const ident::DofIdentification& d) {
  json p = json::object();
  for (const auto& e : d.params) {
    p[e.name] = {{"value", Num(e.value)}, {"sigma", Num(e.sigma)}};
  }
  return p;
}

json DofIdentificationJson(const ident::DofIdentification& d) {
  json params = json::object();
  for (const auto& e : d.params) {
    const bool reliable = std::find(d.unreliable.begin(), d.unreliable.end(), e.name) == d.unreliable.end();
    params[e.name] = ParamJson(e, reliable);
  }
  json segments = json::array();
  for (const auto& p : d.steady_points) {
    segments.push_back({{"trial", p.trial},
                        {"t0", p.t0},
                        {"t1", p.t1},
                        {"speed", Num(p.xi)},
                        {"sigma", Num(p.sigma_xi)},
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
          {"notes", d.notes},
          {"warnings", d.warnings}};
}

json IdentifyJson(const ident::IdentifyResult& r) {
  json dofs = json::object();
  for (const auto& d : r.dofs) dofs[std::string(model::DofName(d.dof))] = DofIdentificationJson(d);
  json trials = json::array();
  for (const auto& t : r.trials) {
    json outliers = json::array(), gaps = json::array();
    for (const auto& o : t.position_outliers) {
      outliers.push_back({{"signal", "position"}, {"t", o.t + t.time_offset}, {"value", o.value},
                          {"residual", Num(o.residual)}});
    }
    for (const auto& o : t.velocity_outliers) {
      outliers.push_back({{"signal", "velocity"}, {"t", o.t + t.time_offset}, {"value", o.value},
                          {"residual", Num(o.residual)}});
    }
    for (const auto& g : t.gaps) gaps.push_back({{"t0", g.t0 + t.time_offset}, {"t1", g.t1 + t.time_offset}});
    trials.push_back({{"index", t.index},
                      {"file", t.file},
                      {"dof", std::string(model::DofName(t.dof))},
                      {"use", UseName(t.use)},
                      {"outliers", outliers},
                      {"gaps", gaps},
                      {"notes", t.notes}});
  }
  return {{"status", std::string(ident::IdentifyStatusName(r.status))},
          {"message", r.message},
          {"dofs", dofs},
          {"trials", trials},
          {"notes", r.notes}};
}

std::string Cell(double v, int precision) {
  if (!std::isfinite(v)) return "-";
  std::ostringstream os;
  os << std::setprecision(precision) << v;
  return os.str();
}

void PrintIdentifyTable(const ident::IdentifyResult& r, std::ostream& out) {
  for (const auto& d : r.dofs) {
    const std::string dof(model::DofName(d.dof));
    out << dof << " (" << ident::IdentifyStatusName(d.status) << ", estimator "
        << ident::FinalEstimatorName(d.estimator) << "; " << d.fit_trials.size() << " fit, "
        << d.validate_trials.size() << " validate trial(s))\n";
    out << "  " << std::left << std::setw(26) << "parameter" << std::right << std::setw(13) << "value"
        << std::setw(12) << "sigma" << std::setw(10) << "error %" << "  significance\n";
    for (const auto& e : d.params) {
      std::string sig;
      double value = e.value, sigma = e.sigma;
      switch (e.state) {
        case ident::ParameterState::kEstimated:
          sig = e.significant ? "significant" : "NOT significant (> 51.02%)";
          break;

        case ident::ParameterState::kDropped:
          sig = "dropped (insignificant, set to 0)";
          value = e.value_before_drop;
          sigma = e.sigma_before_drop;
          break;
        case ident::ParameterState::kFixed:
          sig = "fixed (not estimated)";
          break;
      }
      if (std::find(d.unreliable.begin(), d.unreliable.end(), e.name) != d.unreliable.end()) {
        sig += "; NOT RELIABLE (see warnings)";
      }
      const double pe = e.state == ident::ParameterState::kFixed ? std::nan("") : e.percentile_error();
      out << "  " << std::left << std::setw(26) << e.name << std::right << std::setw(13) << Cell(value, 6)
          << std::setw(12) << Cell(sigma, 3) << std::setw(10) << Cell(pe, 3) << "  " << sig << "\n";
    }
    const auto& f = d.fit;
    out << "  fit: velocity MAE (seed 002 eq. 37) fit " << Cell(f.velocity_mae_fit) << ", validate "
        << Cell(f.velocity_mae_validate) << " " << model::VelocityUnit(d.dof)
        << "; position RMS fit " << Cell(f.position_rms_fit) << ", validate "
        << Cell(f.position_rms_validate) << " " << model::PositionUnit(d.dof) << "\n";
    out << "  " << std::left << std::setw(34) << "trial" << std::setw(10) << "use" << std::right
        << std::setw(12) << "vel. MAE" << std::setw(12) << "pos. RMS" << "  residuals\n";
    for (const auto& t : f.trials) {
      std::ostringstream res;
      res << t.residual_signal << " mean " << Cell(t.residuals.mean, 3) << ", "
          << (t.residuals.white ? "white" : "NOT white") << " (" << t.residuals.lags_outside << "/"
          << (t.residuals.autocorrelation.empty() ? 0 : t.residuals.autocorrelation.size() - 1)
          << " lags outside ±" << Cell(t.residuals.bound95, 2) << ")";
      out << "  " << std::left << std::setw(34) << t.name << std::setw(10)
          << (t.use == model::TrialUse::kFit ? "fit" : "validate") << std::right << std::setw(12)
          << Cell(t.velocity_mae) << std::setw(12) << Cell(t.position_rms) << "  " << res.str()
          << (t.velocity_reference == "estimated" ? " [velocity estimated from positions]" : "")
          << "\n";
    }
    if (d.one_step && d.one_step->ok() && d.one_step->standard) {
      const auto& c = d.one_step->seed;
      out << "  one-step LS coefficients (seed 002 eq. 4): alpha " << Cell(c.alpha) << ", beta "
          << Cell(c.beta) << ", gamma " << Cell(c.gamma) << ", delta " << Cell(c.delta) << "\n";
    }
    for (const auto& w : d.warnings) out << "  WARNING: " << w << "\n";
    for (const auto& n : d.notes) out << "  note: " << n << "\n";
    out << "\n";
  }
  for (const auto& t : r.trials) {
    const std::size_t excluded = t.position_outliers.size() + t.velocity_outliers.size();
    if (excluded == 0 && t.gaps.empty()) continue;
    out << "data: " << t.file << ": " << excluded << " outlier(s) excluded";
    if (excluded > 0) {
      out << " at t =";
      int shown = 0;
      for (const auto* list : {&t.position_outliers, &t.velocity_outliers}) {
        for (const auto& o : *list) {
          if (shown++ < 6) out << " " << Cell(o.t + t.time_offset);
        }
      }
      if (shown > 6) out << " …";
      out << " s";
    }
    out << "; " << t.gaps.size() << " gap(s)\n";
  }
  out << r.message << " — status " << ident::IdentifyStatusName(r.status) << "\n";
}

}  // namespace uuvplan::tool
