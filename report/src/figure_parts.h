// What the figure builders share: a DOF's name as text and a figure's heading.
#pragma once

#include <string>
#include <utility>

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

}  // namespace uuvplan::report
