// PLplot behind the report's Figure (chart.h). Each figure is drawn on its own plstream into
// an open_memstream buffer (plend closes the stream), so nothing touches the file system.
#include "uuvplan/report/render.h"

#include <plplot/plstream.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

namespace uuvplan::report {

namespace {

struct Rgba {
  int r, g, b;
  double a;
};

// cmap0 index = 1 + Colour (0 is the white background). Okabe–Ito colours; bands at 30%.
constexpr std::array<Rgba, 13> kPalette = {{{0, 0, 0, 1.0},
                                            {0, 114, 178, 1.0},
                                            {230, 159, 0, 1.0},
                                            {0, 158, 115, 1.0},
                                            {213, 94, 0, 1.0},
                                            {204, 121, 167, 1.0},
                                            {86, 180, 233, 1.0},
                                            {240, 228, 66, 1.0},
                                            {128, 128, 128, 1.0},
                                            {0, 114, 178, 0.25},
                                            {230, 159, 0, 0.3},
                                            {128, 128, 128, 0.25},
                                            {213, 94, 0, 0.25}}};

PLINT Index(Colour c) { return 1 + static_cast<PLINT>(c); }

// PLplot's text escape is '#': a literal one is "##".
std::string Text(const std::string& s) {
  std::string out;
  for (char c : s) {
    out += c;
    if (c == '#') out += '#';
  }
  return out;
}

struct Range {
  double lo = INFINITY, hi = -INFINITY;
  void Add(double v) {
    if (!std::isfinite(v)) return;
    lo = std::min(lo, v);
    hi = std::max(hi, v);
  }
  // A range that shows everything with a 10% margin (a steady trial's constant thrust at 5%
  // sat on the frame, unreadable); a single value gets ±1 (or ±10%).
  void Pad() {
    if (!(lo <= hi)) lo = 0, hi = 1;
    const double span = hi - lo;
    const double pad = span > 0 ? 0.1 * span : std::max(std::abs(lo) * 0.1, 1.0);
    lo -= pad;
    hi += pad;
  }
};

double Y(double v, bool log_y) { return log_y ? (v > 0 ? std::log10(v) : NAN) : v; }

void AddRanges(const Panel& p, Range* x, Range* y) {
  for (const Series& s : p.series) {
    for (double v : s.x) x->Add(v);
    for (const auto* ys : {&s.y, &s.y_low, &s.y_high}) {
      for (double v : *ys) y->Add(Y(v, p.log_y));
    }
    if (s.style == Style::kBars) y->Add(p.log_y ? NAN : 0.0);
  }
  for (const Level& l : p.levels) {
    if (l.sets_range) y->Add(Y(l.y, p.log_y));
  }
  if (!p.categories.empty()) {
    x->Add(-0.5);
    x->Add(static_cast<double>(p.categories.size()) - 0.5);
  }
}

void SetStyle(plstream& pls, Colour c, Style s) {
  pls.col0(Index(c));
  pls.lsty(s == Style::kDashed ? 3 : s == Style::kDotted ? 2 : 1);  // as LineStyle
  pls.width(s == Style::kDotted ? 1.5 : 2.0);
}

// The finite runs of (x, f(y)), drawn as separate lines so a gap stays a gap.
void DrawLine(plstream& pls, const std::vector<double>& x, const std::vector<double>& y,
              bool log_y) {
  std::vector<PLFLT> rx, ry;
  auto flush = [&] {
    if (rx.size() > 1) pls.line(static_cast<PLINT>(rx.size()), rx.data(), ry.data());
    rx.clear();
    ry.clear();
  };
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) {
    const double v = Y(y[i], log_y);
    if (!std::isfinite(x[i]) || !std::isfinite(v)) {
      flush();
      continue;
    }
    rx.push_back(x[i]);
    ry.push_back(v);
  }
  flush();
}

void DrawBand(plstream& pls, const Series& s, bool log_y) {
  std::vector<PLFLT> px, py;
  for (std::size_t i = 0; i < s.x.size(); ++i) {
    px.push_back(s.x[i]);
    py.push_back(Y(s.y_high[i], log_y));
  }
  for (std::size_t i = s.x.size(); i-- > 0;) {
    px.push_back(s.x[i]);
    py.push_back(Y(s.y_low[i], log_y));
  }
  for (std::size_t i = 0; i < px.size(); ++i) {
    if (!std::isfinite(py[i])) return;  // a band with a gap is not drawn (log of <= 0)
  }
  pls.col0(Index(s.colour));
  if (px.size() > 2) pls.fill(static_cast<PLINT>(px.size()), px.data(), py.data());
}

void DrawMarkers(plstream& pls, const Series& s, bool log_y) {
  SetStyle(pls, s.colour, Style::kLine);
  std::vector<PLFLT> x, y, lo, hi;
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    const double v = Y(s.y[i], log_y);
    if (!std::isfinite(v)) continue;
    x.push_back(s.x[i]);
    y.push_back(v);
    if (s.style == Style::kErrorBars && i < s.y_low.size() && i < s.y_high.size()) {
      lo.push_back(Y(s.y_low[i], log_y));
      hi.push_back(Y(s.y_high[i], log_y));
    }
  }
  if (x.empty()) return;
  if (lo.size() == x.size()) pls.erry(static_cast<PLINT>(x.size()), x.data(), lo.data(), hi.data());
  pls.ssym(0, 1.2);
  pls.poin(static_cast<PLINT>(x.size()), x.data(), y.data(), 17);  // filled circle
}

void DrawBars(plstream& pls, const Series& s) {
  pls.col0(Index(s.colour));
  for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
    if (!std::isfinite(s.y[i])) continue;
    const PLFLT x[4] = {s.x[i] - 0.3, s.x[i] - 0.3, s.x[i] + 0.3, s.x[i] + 0.3};
    const PLFLT y[4] = {0.0, s.y[i], s.y[i], 0.0};
    pls.fill(4, x, y);
  }
}

void DrawSeries(plstream& pls, const Series& s, bool log_y) {
  switch (s.style) {
    case Style::kBand:
      DrawBand(pls, s, log_y);
      break;
    case Style::kPoints:
    case Style::kErrorBars:
      DrawMarkers(pls, s, log_y);
      break;
    case Style::kBars:
      DrawBars(pls, s);
      break;
    default:
      SetStyle(pls, s.colour, s.style);
      DrawLine(pls, s.x, s.y, log_y);
  }
}

bool Shown(const Level& l, const Range& y, bool log_y) {
  const double v = Y(l.y, log_y);
  return std::isfinite(v) && (l.sets_range || (v >= y.lo && v <= y.hi));
}

void DrawLevels(plstream& pls, const Panel& p, const Range& x, const Range& y_range) {
  for (const Level& l : p.levels) {
    if (!Shown(l, y_range, p.log_y)) continue;
    const double y = Y(l.y, p.log_y);
    SetStyle(pls, l.colour, l.style);
    pls.join(x.lo, y, x.hi, y);
  }
}

PLINT LineStyle(Style s) { return s == Style::kDashed ? 3 : s == Style::kDotted ? 2 : 1; }

// One legend entry: how it is drawn, its colour and line style, its text.
struct Entry {
  PLINT opt, colour, style;
  std::string text;
};

PLINT LegendOpt(Style s) {
  if (s == Style::kBand || s == Style::kBars) return PL_LEGEND_COLOR_BOX;
  if (s == Style::kPoints || s == Style::kErrorBars) return PL_LEGEND_SYMBOL;
  return PL_LEGEND_LINE;
}

// The labelled series, then the labelled levels (each label once), for the legend.
std::vector<Entry> LegendEntries(const Panel& p, const Range& y) {
  std::vector<Entry> entries;
  for (const Series& s : p.series) {
    if (!s.label.empty())
      entries.push_back({LegendOpt(s.style), Index(s.colour), LineStyle(s.style), Text(s.label)});
  }
  for (const Level& l : p.levels) {
    if (l.label.empty() || !Shown(l, y, p.log_y)) continue;
    const std::string text = Text(l.label);
    const bool seen =
        std::any_of(entries.begin(), entries.end(), [&](const Entry& e) { return e.text == text; });
    if (!seen) entries.push_back({PL_LEGEND_LINE, Index(l.colour), LineStyle(l.style), text});
  }
  return entries;
}

// The legend outside the plot box, on its right, centred vertically.
void DrawLegend(plstream& pls, const Panel& p, const Range& y) {
  const std::vector<Entry> entries = LegendEntries(p, y);
  if (entries.empty()) return;
  const std::size_t n = entries.size();
  std::vector<PLINT> opt(n), colours(n), black(n, Index(Colour::kBlack)), patterns(n, 0), styles(n),
      numbers(n, 1);
  std::vector<PLFLT> scales(n, 0.8), widths(n, 2.0), box_widths(n, 1.0);
  std::vector<const char*> text(n), symbols(n, "•");
  for (std::size_t i = 0; i < n; ++i) {
    opt[i] = entries[i].opt;
    colours[i] = entries[i].colour;
    styles[i] = entries[i].style;
    text[i] = entries[i].text.c_str();
  }
  PLFLT w = 0, h = 0;
  pls.schr(0, 0.75);
  pls.legend(&w, &h, PL_LEGEND_BACKGROUND, PL_POSITION_RIGHT | PL_POSITION_OUTSIDE, 0.01, 0.0, 0.05,
             0, 1, 1, static_cast<PLINT>(n), 1, static_cast<PLINT>(n), opt.data(), 0.5, 0.7, 1.8,
             0.0, black.data(), text.data(), colours.data(), patterns.data(), scales.data(),
             box_widths.data(), colours.data(), styles.data(), widths.data(), colours.data(),
             scales.data(), numbers.data(), symbols.data());
  pls.schr(0, 0.75);
}

void DrawAxes(plstream& pls, const Panel& p) {
  pls.col0(Index(Colour::kBlack));
  pls.lsty(1);
  pls.width(1.0);
  const char* yopt = p.log_y ? "bcnstvl" : "bcnstv";
  if (p.categories.empty()) {
    pls.box("bcnst", 0, 0, yopt, 0, 0);
  } else {
    pls.box("bc", 1, 0, yopt, 0, 0);
    const double n = static_cast<double>(p.categories.size());
    for (std::size_t i = 0; i < p.categories.size(); ++i) {  // vertical, ending at the axis
      pls.mtex("bv", 0.7, (i + 0.5) / n, 1.0, Text(p.categories[i]).c_str());
    }
  }
  if (p.categories.empty()) pls.mtex("b", 3.0, 0.5, 0.5, Text(p.x_label).c_str());
  pls.mtex("l", 4.6, 0.5, 0.5, Text(p.y_label).c_str());
  pls.mtex("t", 0.8, 0.0, 0.0, Text(p.title).c_str());
}

// One character height (PLplot's, at the panels' scale) as a fraction of the page's width and
// height. PLplot draws text at an absolute size while panels scale with the figure, so the room
// around a panel is counted in characters: its labels never meet the next panel's, at any
// number of panels and any figure height (tests/report/figure_layout_test.cc reads the SVG's
// text boxes).
struct CharSize {
  double x = 0.0, y = 0.0;
};

CharSize CharFractions(plstream& pls) {
  PLFLT def = 0, height = 0, x0 = 0, x1 = 0, y0 = 0, y1 = 0;
  pls.gchr(def, height);
  pls.gspa(x0, x1, y0, y1);
  return {height / (x1 - x0), height / (y1 - y0)};
}

// A character's advance in PLplot character heights, measured on the SVG's glyphs: "measured"
// at the legend's scale 0.7 spans 64 px where the character height is 11 px (8 px a character,
// 1.04 heights); 1.1 keeps a margin for wider letters.
constexpr double kAdvance = 1.1;

// The legend's width as a fraction of the page: its line sample (0.05 of the plot's width, as
// DrawLegend asks), the gaps, and its longest text at the legend's scale 0.7.
double LegendWidth(const std::vector<Entry>& entries, CharSize c, double panel_width) {
  if (entries.empty()) return c.x;
  std::size_t longest = 0;
  for (const Entry& e : entries) longest = std::max(longest, e.text.size());
  return 0.06 * panel_width + (2.0 + 0.7 * kAdvance * static_cast<double>(longest)) * c.x;
}

// The panel's ranges, padded as drawn.
void PanelRanges(const Panel& p, Range* x, Range* y) {
  AddRanges(p, x, y);
  if (!(x->lo < x->hi)) x->Pad();
  y->Pad();
}

// The room on the right of every panel: the widest legend of the figure, so that the plots of
// one column line up.
double RightMargin(const Figure& f, CharSize c) {
  const double panel_width = 1.0 / std::max(1, f.columns);
  double right = c.x;
  for (const Panel& p : f.panels) {
    Range x, y;
    PanelRanges(p, &x, &y);
    right = std::max(right, LegendWidth(LegendEntries(p, y), c, panel_width));
  }
  return right;
}

void DrawPanel(plstream& pls, const Panel& p, double x0, double x1, double y0, double y1,
               CharSize c, double right) {
  Range x, y;
  PanelRanges(p, &x, &y);
  // Room for the y label (4.6 characters out, DrawAxes) on the left, the legend (`right`) on
  // the right, the tick labels and x label (3.0 characters down) or the vertical category
  // names below, the title (0.8 characters up) above; each with a character to spare.
  const double left = 6.2 * c.x;
  const double bottom = p.categories.empty() ? 4.6 * c.y : 0.5 * (y1 - y0);
  const double top = 2.3 * c.y;
  pls.vpor(x0 + left, x1 - right, y0 + bottom, y1 - top);
  pls.wind(x.lo, x.hi, y.lo, y.hi);
  for (const Series& s : p.series) {
    if (s.style == Style::kBand) DrawSeries(pls, s, p.log_y);  // bands under everything
  }
  DrawLevels(pls, p, x, y);
  for (const Series& s : p.series) {
    if (s.style != Style::kBand) DrawSeries(pls, s, p.log_y);
  }
  DrawAxes(pls, p);
  DrawLegend(pls, p, y);
}

// PLplot's default character height grows with the page (5.2 mm on a 370 px figure, 15.7 mm on
// a 3340 px one): held at the one-row figure's, 14.7 px, so that every figure's text reads alike
// and a figure of many panels keeps room between them.
constexpr double kCharHeightPx = 14.7;

void Draw(plstream& pls, const Figure& f) {
  pls.adv(0);
  PLFLT page_x0 = 0, page_x1 = 0, page_y0 = 0, page_y1 = 0;
  pls.gspa(page_x0, page_x1, page_y0, page_y1);
  pls.schr(kCharHeightPx * (page_x1 - page_x0) / f.width, 0.75);  // mm per px: the page's
  const int columns = std::max(1, f.columns);
  const int rows = (static_cast<int>(f.panels.size()) + columns - 1) / columns;
  const double title = 40.0 / std::max(f.height, 1);  // fraction of the page for the title
  pls.vpor(0, 1, 0, 1);
  pls.wind(0, 1, 0, 1);
  pls.col0(Index(Colour::kBlack));
  pls.schr(0, 0.95);
  pls.ptex(0.5, 1 - title * 0.6, 1, 0, 0.5, Text(f.title).c_str());
  pls.schr(0, 0.75);
  const CharSize chars = CharFractions(pls);
  const double right = RightMargin(f, chars);
  for (std::size_t i = 0; i < f.panels.size(); ++i) {
    const int r = static_cast<int>(i) / columns, c = static_cast<int>(i) % columns;
    const double h = (1 - title) / rows;
    DrawPanel(pls, f.panels[i], static_cast<double>(c) / columns,
              static_cast<double>(c + 1) / columns, 1 - title - (r + 1) * h, 1 - title - r * h,
              chars, right);
  }
}

// PLplot exits the program when asked for a device it does not have: ask first.
bool HasDevice(const char* name) {
  const char** menu = nullptr;
  const char** devices = nullptr;
  int n = 64;
  std::vector<const char*> m(n), d(n);
  menu = m.data();
  devices = d.data();
  plgDevs(&menu, &devices, &n);
  for (int i = 0; i < n; ++i) {
    if (devices[i] && std::string(devices[i]) == name) return true;
  }
  return false;
}

}  // namespace

std::string Render(const Figure& figure, Format format) {
  const char* device = format == Format::kPng ? "pngcairo" : "svgcairo";
  if (!HasDevice(device)) {
    throw std::runtime_error(
        std::string("PLplot has no '") + device +
        "' driver: install Debian's plplot-driver-cairo (scripts/install-deps.sh)");
  }
  Figure f = figure;
  const int rows =
      (static_cast<int>(f.panels.size()) + std::max(1, f.columns) - 1) / std::max(1, f.columns);
  if (f.height <= 0) f.height = 40 + 330 * std::max(rows, 1);
  char* buffer = nullptr;
  std::size_t size = 0;
  FILE* memory = open_memstream(&buffer, &size);
  if (!memory) throw std::runtime_error("cannot open a memory stream for figure " + f.name);
  {
    plstream pls;
    pls.sdev(device);
    pls.sfile(memory);  // plend (the destructor) closes it
    pls.spage(0, 0, f.width, f.height, 0, 0);
    pls.scolbg(255, 255, 255);
    pls.init();
    for (std::size_t i = 0; i < kPalette.size(); ++i) {
      const Rgba& c = kPalette[i];
      pls.scol0a(static_cast<PLINT>(i) + 1, c.r, c.g, c.b, c.a);
    }
    Draw(pls, f);
  }
  std::string bytes(buffer ? buffer : "", size);
  std::free(buffer);
  if (bytes.empty()) throw std::runtime_error("PLplot drew nothing for figure " + f.name);
  return bytes;
}

}  // namespace uuvplan::report
