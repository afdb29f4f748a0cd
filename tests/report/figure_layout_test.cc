// No text of a figure meets another or leaves the page, at any number of panels: the text boxes
// are read back from the SVG that cairo writes (each string a <g> of glyph <use>s placed at x, y;
// each glyph a <symbol> whose path gives its extent), and no two boxes intersect.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "uuvplan/report/chart.h"
#include "uuvplan/report/render.h"

namespace uuvplan::report {
namespace {

struct Box {
  double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
  bool Empty() const { return !(x0 < x1 && y0 < y1); }
  void Add(double x, double y) {
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  void Add(const Box& b, double dx, double dy) {
    if (!b.Empty()) Add(b.x0 + dx, b.y0 + dy), Add(b.x1 + dx, b.y1 + dy);
  }
  bool Meets(const Box& o) const { return x0 < o.x1 && o.x0 < x1 && y0 < o.y1 && o.y0 < y1; }
};

// Each glyph's extent from the numbers of its path (control points included: a box that can
// only be larger than the outline's).
std::map<std::string, Box> GlyphBoxes(const std::string& svg) {
  std::map<std::string, Box> glyphs;
  const std::regex symbol(R"re(<symbol[^>]*id="([^"]+)">\s*<path[^>]*d="([^"]*)")re");
  const std::regex number(R"(-?[0-9]*\.?[0-9]+(?:e-?[0-9]+)?)");
  for (std::sregex_iterator s(svg.begin(), svg.end(), symbol), end; s != end; ++s) {
    const std::string d = (*s)[2];
    std::vector<double> v;
    for (std::sregex_iterator n(d.begin(), d.end(), number); n != end; ++n) {
      v.push_back(std::stod(n->str()));
    }
    Box b;
    for (std::size_t i = 0; i + 1 < v.size(); i += 2) b.Add(v[i], v[i + 1]);
    glyphs[(*s)[1]] = b;
  }
  return glyphs;
}

// One box per text string: the <use>s of one <g>.
std::vector<Box> TextBoxes(const std::string& svg) {
  const std::map<std::string, Box> glyphs = GlyphBoxes(svg);
  const std::regex group(R"(<g style="fill:[^"]*">((?:\s*<use[^>]*/>)+)\s*</g>)");
  const std::regex use(R"re(<use xlink:href="#([^"]+)" x="([^"]+)" y="([^"]+)"/>)re");
  std::vector<Box> boxes;
  for (std::sregex_iterator g(svg.begin(), svg.end(), group), end; g != end; ++g) {
    const std::string uses = (*g)[1];
    Box text;
    for (std::sregex_iterator u(uses.begin(), uses.end(), use); u != end; ++u) {
      const auto glyph = glyphs.find((*u)[1]);
      if (glyph != glyphs.end()) text.Add(glyph->second, std::stod((*u)[2]), std::stod((*u)[3]));
    }
    if (!text.Empty()) boxes.push_back(text);
  }
  return boxes;
}

// `n` panels of a trial's free run as the report draws them: a long title, axis labels with
// units, a two-entry legend.
Figure FreeRuns(int n, int columns) {
  Figure f;
  f.name = "free-run";
  f.title = "surge: measured and simulated free run per trial";
  f.columns = columns;
  for (int i = 0; i < n; ++i) {
    Panel p;
    p.title = "trials/surge-switched-square-" + std::to_string(i) + ".csv (fit)";
    p.x_label = "t (s)";
    p.y_label = "position (m)";
    Series measured{"measured", Style::kLine, Colour::kGrey, {}, {}, {}, {}};
    Series free{"free run", Style::kLine, Colour::kBlue, {}, {}, {}, {}};
    for (int k = 0; k <= 200; ++k) {
      const double t = 0.6 * k;
      measured.x.push_back(t), measured.y.push_back(-0.04 * t + std::sin(0.25 * t));
      free.x.push_back(t), free.y.push_back(-0.04 * t + 0.95 * std::sin(0.25 * t));
    }
    p.series = {measured, free};
    f.panels.push_back(p);
  }
  return f;
}

TEST(FigureLayout, NoTextMeetsAnotherOrLeavesThePageAtAnyNumberOfPanels) {
  for (const int columns : {1, 2}) {
    for (const int n : {1, 2, 3, 5, 10, 13}) {
      const Figure f = FreeRuns(n, columns);
      const std::vector<Box> boxes = TextBoxes(Render(f, Format::kSvg));
      const double height = 40 + 330 * ((n + columns - 1) / columns);
      // The figure title, then per panel its title, 2 labels, 2 legend texts and tick labels.
      ASSERT_GE(boxes.size(), static_cast<std::size_t>(1 + 5 * n)) << n << " panels";
      for (std::size_t i = 0; i < boxes.size(); ++i) {
        const Box& b = boxes[i];
        EXPECT_TRUE(b.x0 >= 0 && b.x1 <= f.width && b.y0 >= 0 && b.y1 <= height)
            << n << " panels, " << columns << " column(s): text " << i << " [" << b.x0 << ", "
            << b.x1 << "] × [" << b.y0 << ", " << b.y1 << "] leaves the page";
        for (std::size_t k = i + 1; k < boxes.size(); ++k) {
          EXPECT_FALSE(b.Meets(boxes[k]))
              << n << " panels, " << columns << " column(s): texts " << i << " and " << k
              << " meet at [" << b.x0 << ", " << b.x1 << "] × [" << b.y0 << ", " << b.y1
              << "] and [" << boxes[k].x0 << ", " << boxes[k].x1 << "] × [" << boxes[k].y0 << ", "
              << boxes[k].y1 << "]";
        }
      }
    }
  }
}

}  // namespace
}  // namespace uuvplan::report
