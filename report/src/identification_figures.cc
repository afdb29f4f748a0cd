#include "uuvplan/report/identification_figures.h"

#include <cmath>

#include "figure_parts.h"
#include "uuvplan/model/parameter.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::report {

namespace {

std::string UseName(model::TrialUse use) {
  return use == model::TrialUse::kFit ? "fit" : "validate";
}

// A trial's panel against time: its file and use, `quantity` in the unit of its signal.
Panel TrialPanel(const ident::TrialFit& t, model::Dof dof, const std::string& quantity) {
  Panel p;
  p.title = t.name + " (" + UseName(t.use) + ")";
  p.x_label = "t (s)";
  p.y_label = quantity + " (" + SignalUnit(t, dof) + ")";
  return p;
}

}  // namespace

Figure FreeRunFigure(const ident::DofIdentification& dof, const std::string& stem) {
  Figure f = StartFigure(
      stem + "-free-run", DofText(dof.dof) + ": measured and simulated free run per trial",
      "Each trial of " + DofText(dof.dof) +
          ": the measured signal (position when logged, "
          "else velocity) and the free-run simulation of the identified model from the "
          "trial's initial state with the logged input (no re-initialisation).");
  for (const ident::TrialFit& t : dof.fit.trials) {
    Panel p = TrialPanel(t, dof.dof, t.residual_signal);
    p.series.push_back(
        {"measured", Style::kLine, Colour::kGrey, t.curve.t, t.curve.measured, {}, {}});
    p.series.push_back(
        {"free run", Style::kLine, Colour::kBlue, t.curve.t, t.curve.simulated, {}, {}});
    f.panels.push_back(std::move(p));
  }
  LayOutTwoColumns(&f);
  return f;
}

namespace {

Panel AutocorrelationPanel(const ident::TrialFit& t) {
  const ident::ResidualAnalysis& a = t.residuals;
  Panel p;
  p.title = "autocorrelation: " + std::to_string(a.lags_outside) + " lags outside, " +
            (a.white ? "white" : "not white");
  p.x_label = "lag (s)";
  p.y_label = "rho (1)";
  Series rho{"rho(lag)", Style::kErrorBars, Colour::kBlue, {}, {}, {}, {}};
  for (std::size_t l = 1; l < a.autocorrelation.size(); ++l) {
    rho.x.push_back(l * a.lag_step_s);
    rho.y.push_back(a.autocorrelation[l]);
    rho.y_low.push_back(0.0);
    rho.y_high.push_back(a.autocorrelation[l]);
  }
  p.series.push_back(std::move(rho));
  p.levels = {{a.bound95, "±1.96/√N", Colour::kVermillion, Style::kDashed},
              {-a.bound95, "±1.96/√N", Colour::kVermillion, Style::kDashed},
              {0.0, "", Colour::kBlack, Style::kLine}};
  return p;
}

}  // namespace

Figure ResidualFigure(const ident::DofIdentification& dof, const std::string& stem) {
  Figure f = StartFigure(
      stem + "-residuals", DofText(dof.dof) + ": residuals and their autocorrelation",
      "Residual (measured − free run) of each trial of " + DofText(dof.dof) +
          " against time, and its normalised autocorrelation with the 95% whiteness "
          "bounds ±1.96/√N (seed 004 §5.2; white unless more lags fall outside than white "
          "noise puts there 99% of the time).");
  for (const ident::TrialFit& t : dof.fit.trials) {
    Panel r = TrialPanel(t, dof.dof, "residual");
    r.series.push_back(ResidualSeries(t, "", Colour::kBlue, Style::kLine));
    r.levels.push_back({0.0, "", Colour::kBlack, Style::kLine});
    f.panels.push_back(std::move(r));
    f.panels.push_back(AutocorrelationPanel(t));
  }
  LayOutTwoColumns(&f);
  return f;
}

Figure ParameterFigure(const ident::DofIdentification& dof, const std::string& stem) {
  Figure f = StartFigure(
      stem + "-parameters", DofText(dof.dof) + ": estimates with their σ band",
      "Each estimated parameter of " + DofText(dof.dof) +
          " relative to its estimate "
          "(θ/θ̂ = 1): the bars span ±1σ (dark) and ±2σ (light), σ from the fit's covariance; "
          "the table gives the values with units.");
  Panel p;
  p.x_label = "";
  p.y_label = "theta / estimate (1)";
  Series two{"±2σ", Style::kErrorBars, Colour::kSky, {}, {}, {}, {}};
  Series one{"±1σ", Style::kErrorBars, Colour::kBlue, {}, {}, {}, {}};
  for (const ident::ParameterEstimate& e : dof.params) {
    if (e.state != ident::ParameterState::kEstimated || !std::isfinite(e.sigma) || e.value == 0)
      continue;
    const double x = static_cast<double>(p.categories.size());
    const double rel = e.sigma / std::abs(e.value);
    p.categories.push_back(e.name + " (" + model::Unit(e.name, dof.dof) + ")");
    two.x.push_back(x), two.y.push_back(1), two.y_low.push_back(1 - 2 * rel),
        two.y_high.push_back(1 + 2 * rel);
    one.x.push_back(x), one.y.push_back(1), one.y_low.push_back(1 - rel),
        one.y_high.push_back(1 + rel);
  }
  p.series = {two, one};
  p.levels.push_back({1.0, "", Colour::kGrey, Style::kDotted});
  p.title = std::to_string(p.categories.size()) + " parameters estimated";
  f.panels.push_back(std::move(p));
  f.height = 520;
  return f;
}

namespace {

// The unit of an RLS coefficient (rls.h): γ = 1/m, "<name>/m" = θ_name/m.
std::string CoefficientUnit(const std::string& coefficient, model::Dof dof) {
  const std::string m = model::Unit("m", dof);
  if (coefficient == "gamma") return "1/" + m;
  const std::string name = coefficient.substr(0, coefficient.size() - 2);
  return "(" + model::Unit(name, dof) + ")/" + m;
}

}  // namespace

Figure RlsConvergenceFigure(const ident::DofIdentification& dof, const std::string& stem) {
  Figure f = StartFigure(
      stem + "-rls", DofText(dof.dof) + ": RLS convergence (seed 004 Fig. 11)",
      "Each coefficient of the recursive least squares of " + DofText(dof.dof) +
          " (seed 004 eq. 15; γ = 1/m, θ/m of each other parameter, α = k/m and δ = bias/m "
          "in the seed's eq. 2) after every update against the campaign time, with its ±1σ "
          "band (rls.h) once the rows say enough of the residual variance; the dotted line "
          "is the final estimate.");
  const ident::RlsDofResult& r = *dof.rls;
  for (std::size_t j = 0; j < r.coefficient_names.size(); ++j) {
    Panel p;
    p.title = r.coefficient_names[j] + (r.coefficient_names[j] == "gamma" ? " = 1/m" : "");
    p.x_label = "campaign time (s)";
    p.y_label =
        r.coefficient_names[j] + " (" + CoefficientUnit(r.coefficient_names[j], dof.dof) + ")";
    Series band{"±1σ", Style::kBand, Colour::kSky, {}, {}, {}, {}};
    Series line{"estimate", Style::kLine, Colour::kBlue, {}, {}, {}, {}};
    const int col = static_cast<int>(j);
    for (int k = 0; k < r.psi.theta.rows(); ++k) {
      const double theta = r.psi.theta(k, col), sigma = r.psi.sigma(k, col);
      if (!std::isfinite(sigma)) continue;  // before 2p rows: no residual variance yet
      line.x.push_back(r.psi.t[k]), line.y.push_back(theta);
      band.x.push_back(r.psi.t[k]), band.y.push_back(theta);
      band.y_low.push_back(theta - sigma), band.y_high.push_back(theta + sigma);
    }
    const double final_value = r.psi.theta(r.psi.theta.rows() - 1, col);
    p.series = {band, line};
    p.levels.push_back({final_value, "final", Colour::kGrey, Style::kDotted});
    f.panels.push_back(std::move(p));
  }
  return f;
}

std::vector<Figure> IdentificationFigures(const ident::IdentifyResult& result) {
  std::vector<Figure> figures;
  for (const ident::DofIdentification& d : result.dofs) {
    if (d.fit.trials.empty()) continue;
    const std::string stem = "identification-" + DofText(d.dof);
    figures.push_back(FreeRunFigure(d, stem));
    figures.push_back(ResidualFigure(d, stem));
    figures.push_back(ParameterFigure(d, stem));
    if (d.rls && d.rls->ok()) figures.push_back(RlsConvergenceFigure(d, stem));
  }
  return figures;
}

}  // namespace uuvplan::report
