#include "uuvplan/report/loop_figures.h"

#include <cmath>

#include "figure_parts.h"
#include "uuvplan/model/util/text.h"

namespace uuvplan::report {

namespace {

double Percent(double sigma, double value) {
  return std::isfinite(sigma) && value != 0 ? 100 * sigma / std::abs(value) : NAN;
}

Panel DofPanel(model::Dof dof, const std::map<std::string, std::vector<io::LoopPoint>>& params,
               double target) {
  Panel p;
  p.title = std::string(model::DofName(dof)) + ": solid achieved, dashed predicted";
  p.x_label = "accumulated pool time (min)";
  p.y_label = "100·σ/|θ| (%)";
  p.log_y = true;
  const Colour colours[] = {Colour::kBlue, Colour::kOrange,     Colour::kGreen, Colour::kPurple,
                            Colour::kSky,  Colour::kVermillion, Colour::kBlack, Colour::kGrey};
  int k = 0;
  for (const auto& [name, points] : params) {
    Series achieved{name, Style::kLine, colours[k % 8], {}, {}, {}, {}};
    Series marks{"", Style::kPoints, colours[k % 8], {}, {}, {}, {}};
    Series predicted{"", Style::kDashed, colours[k % 8], {}, {}, {}, {}};
    for (const io::LoopPoint& q : points) {
      const double minutes = q.pool_time / 60;
      achieved.x.push_back(minutes);
      achieved.y.push_back(Percent(q.sigma, q.value));
      if (std::isfinite(q.predicted)) {
        predicted.x.push_back(minutes);
        predicted.y.push_back(Percent(q.predicted, q.value));
      }
    }
    marks.x = achieved.x;
    marks.y = achieved.y;
    p.series.push_back(std::move(achieved));
    p.series.push_back(std::move(marks));
    if (predicted.x.size() > 0) p.series.push_back(std::move(predicted));
    ++k;
  }
  if (target > 0)
    p.levels.push_back({target, "target " + model::Significant(target, 3) + " %",
                        Colour::kVermillion, Style::kDotted});
  return p;
}

}  // namespace

Figure LoopFigure(const io::LoopHistory& history) {
  Figure f = StartFigure(
      "loop-percentile-error", "Loop: percentile error against pool time (" + history.status + ")",
      "Each parameter's percentile error 100·σ/|θ| (seed 000 §III-A, log scale) after "
      "each trial of the loop against the accumulated pool time: achieved (solid, "
      "markers: the identification's σ) and predicted by the planner for the DOF whose "
      "trial it planned (dashed), with the target.");
  for (const auto& [dof, params] : history.series) {
    f.panels.push_back(DofPanel(dof, params, history.target_percent));
  }
  f.height = 40 + 360 * std::max<int>(1, static_cast<int>(f.panels.size()));
  return f;
}

}  // namespace uuvplan::report
