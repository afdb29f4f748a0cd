// A figure as data: panels of series (lines, bands, points with error bars, bars) with their
// labels and units, drawn by one renderer (PLplot, render.h). The figure builders of the
// report (schedule_figures.h, identification_figures.h, loop_figures.h, diagnosis_figures.h)
// say what to draw in the model's words; only render.cc knows the plotting library.
#pragma once

#include <string>
#include <vector>

namespace uuvplan::report {

/// The report's palette (colour-blind safe, Okabe–Ito), plus light fills for bands.
enum class Colour {
  kBlack,
  kBlue,
  kOrange,
  kGreen,
  kVermillion,
  kPurple,
  kSky,
  kYellow,
  kGrey,
  kBandBlue,
  kBandOrange,
  kBandGrey,
  kBandRed
};

enum class Style {
  kLine,  ///< y against x
  kDashed,
  kDotted,
  kBand,       ///< filled between y_low and y_high over x
  kPoints,     ///< markers at (x, y)
  kErrorBars,  ///< markers at (x, y) with a bar from y_low to y_high
  kBars,       ///< vertical bars from 0 to y at x (categories)
};

struct Series {
  std::string label;  ///< legend text; empty: not in the legend
  Style style = Style::kLine;
  Colour colour = Colour::kBlue;
  std::vector<double> x, y;
  std::vector<double> y_low, y_high;  ///< bands and error bars
};

/// A horizontal line across the panel (a limit, a wall, the zero line).
struct Level {
  double y = 0.0;
  std::string label;  ///< written at the line's right end
  Colour colour = Colour::kGrey;
  Style style = Style::kDashed;
  /// false: drawn only when the series' range reaches it (a limit far beyond the data would
  /// flatten them), and then left out of the legend.
  bool sets_range = true;
};

struct Panel {
  std::string title;
  std::string x_label, y_label;  ///< with units, e.g. "t (s)"
  std::vector<Series> series;
  std::vector<Level> levels;
  /// Named positions 0, 1, ... on the x axis instead of numbers (e.g. parameter names).
  std::vector<std::string> categories;
  bool log_y = false;  ///< logarithmic y axis (values <= 0 are left out)
};

struct Figure {
  std::string name;     ///< file stem, e.g. "schedule-surge_sine_1"
  std::string title;    ///< one line above the panels
  std::string caption;  ///< what the figure shows, for the report
  std::vector<Panel> panels;
  int columns = 1;   ///< panels laid out in rows of this many
  int width = 1100;  ///< pixels of the PNG (the SVG has the same size in points)
  int height = 0;    ///< 0: 330 per row of panels plus the title
};

}  // namespace uuvplan::report
