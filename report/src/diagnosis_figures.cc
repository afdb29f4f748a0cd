#include "uuvplan/report/diagnosis_figures.h"

#include <cmath>

#include "figure_parts.h"

namespace uuvplan::report {

Figure ResidualsBeforeAfterFigure(const BeforeAfter& runs) {
  Figure f = StartFigure(
      "diagnosis-" + DofText(runs.dof) + "-residuals",
      DofText(runs.dof) + ": residuals before and after the extension",
      "Residual (measured − free run) of each trial of " + DofText(runs.dof) +
          " with the standard model (before) and with the extended model diagnosis chose "
          "(after), both scored as `uuvplan score` does.");
  for (const ident::TrialScore& b : runs.before.trials) {
    if (b.dof != runs.dof) continue;
    Panel p;
    p.title = b.fit.name;
    p.x_label = "t (s)";
    p.y_label = b.fit.residual_signal + " residual (" + SignalUnit(b.fit, runs.dof) + ")";
    p.series.push_back(ResidualSeries(b.fit, "before", Colour::kVermillion, Style::kLine));
    for (const ident::TrialScore& a : runs.after.trials) {
      if (a.fit.trial == b.fit.trial)
        p.series.push_back(ResidualSeries(a.fit, "after", Colour::kBlue, Style::kLine));
    }
    p.levels.push_back({0.0, "", Colour::kBlack, Style::kLine});
    f.panels.push_back(std::move(p));
  }
  LayOutTwoColumns(&f);
  return f;
}

Figure CandidateGainFigure(const ident::DiagnosisResult& diagnosis, model::Dof dof) {
  Figure f = StartFigure(
      "diagnosis-" + DofText(dof) + "-gains", DofText(dof) + ": held-out gain per candidate effect",
      "Every candidate effect tested on " + DofText(dof) +
          " (round: greedy step): its "
          "held-out gain, the relative reduction of the free-run velocity MAE on data the "
          "fit did not see; only significant candidates are scored (others at 0), and an "
          "effect is accepted when its gain reaches the threshold.");
  Panel p;
  p.x_label = "";
  p.y_label = "held-out gain (%)";
  Series accepted{"accepted", Style::kBars, Colour::kGreen, {}, {}, {}, {}};
  Series other{"not accepted", Style::kBars, Colour::kGrey, {}, {}, {}, {}};
  for (const ident::CandidateTest& t : diagnosis.tests) {
    if (t.dof != dof) continue;
    const double x = static_cast<double>(p.categories.size());
    p.categories.push_back(t.effect +
                           (t.detail.empty() || t.detail.size() > 14 ? "" : " " + t.detail) + " (" +
                           std::to_string(t.round) + ")");
    Series& s = t.accepted ? accepted : other;
    s.x.push_back(x);
    s.y.push_back(std::isfinite(t.gain) ? 100 * t.gain : 0.0);
  }
  p.series = {accepted, other};
  p.levels.push_back({0.0, "", Colour::kBlack, Style::kLine});
  p.title = std::to_string(p.categories.size()) + " candidates tested: effect (greedy round)";
  f.panels.push_back(std::move(p));
  f.height = 560;
  return f;
}

}  // namespace uuvplan::report
