// What the figure builders share: a DOF's name as text, a figure's heading, the two-column
// layout, and a trial's residual signal (the free run's error, ident/validation.h).
#pragma once

#include <algorithm>
#include <string>
#include <utility>

#include "uuvplan/ident/validation.h"
#include "uuvplan/model/dof.h"
#include "uuvplan/report/chart.h"

namespace uuvplan::report {

inline std::string DofText(model::Dof dof) { return std::string(model::DofName(dof)); }

/// A figure with its file stem, title and caption, and no panel yet.
inline Figure StartFigure(std::string name, std::string title, std::string caption) {
  Figure f;
  f.name = std::move(name);
  f.title = std::move(title);
  f.caption = std::move(caption);
  return f;
}

/// Lays a figure's panels out two to a row, each row 260 px high below its 40 px title.
inline void LayOutTwoColumns(Figure* f) {
  f->columns = 2;
  const int rows = (static_cast<int>(f->panels.size()) + 1) / 2;
  f->height = 40 + 260 * std::max(rows, 1);
}

/// The unit of the signal a trial's residuals are of: position, else velocity.
inline std::string SignalUnit(const ident::TrialFit& t, model::Dof dof) {
  return std::string(t.residual_signal == "position" ? model::PositionUnit(dof)
                                                     : model::VelocityUnit(dof));
}

/// A trial's residual, measured − free run, at its sample times.
inline Series ResidualSeries(const ident::TrialFit& t, const std::string& label, Colour c,
                             Style s) {
  Series r{label, s, c, t.curve.t, {}, {}, {}};
  for (std::size_t i = 0; i < t.curve.t.size(); ++i)
    r.y.push_back(t.curve.measured[i] - t.curve.simulated[i]);
  return r;
}

}  // namespace uuvplan::report
