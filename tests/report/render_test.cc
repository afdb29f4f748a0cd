// The report library without the tool: a figure drawn by PLplot into PNG and SVG bytes, the
// base64 of the data URIs, the HTML's escaping and units, and the figures of a schedule.
#include "uuvplan/report/render.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "uuvplan/io/pool_yaml.h"
#include "uuvplan/io/vehicle_yaml.h"
#include "uuvplan/planner/schedule_planner.h"
#include "uuvplan/report/html.h"
#include "uuvplan/report/schedule_figures.h"
#include "uuvplan/report/sections.h"

namespace uuvplan::report {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;

Figure SineFigure() {
  Figure f;
  f.name = "sine";
  f.title = "a sine # with a hash";
  Panel p;
  p.x_label = "t (s)";
  p.y_label = "x (m)";
  Series s{"sin", Style::kLine, Colour::kBlue, {}, {}, {}, {}};
  for (int i = 0; i <= 100; ++i) s.x.push_back(0.1 * i), s.y.push_back(std::sin(0.1 * i));
  p.series.push_back(s);
  p.levels.push_back({2.0, "far limit", Colour::kVermillion, Style::kDashed, false});
  f.panels.push_back(p);
  return f;
}

TEST(ReportRender, PngAndSvgOfAFigure) {
  const std::string png = Render(SineFigure(), Format::kPng);
  ASSERT_GT(png.size(), 8u);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
  // IHDR holds the width and height (big-endian) at bytes 16..23: the figure's 1100 × 370.
  const auto be32 = [&](int at) {
    return (static_cast<unsigned char>(png[at]) << 24) |
           (static_cast<unsigned char>(png[at + 1]) << 16) |
           (static_cast<unsigned char>(png[at + 2]) << 8) | static_cast<unsigned char>(png[at + 3]);
  };
  EXPECT_EQ(be32(16), 1100);
  EXPECT_EQ(be32(20), 40 + 330);
  const std::string svg = Render(SineFigure(), Format::kSvg);
  EXPECT_THAT(svg, HasSubstr("<svg"));
  EXPECT_THAT(svg, HasSubstr("</svg>"));
}

TEST(ReportHtml, Base64OfRfc4648Vectors) {
  EXPECT_EQ(Base64(""), "");
  EXPECT_EQ(Base64("f"), "Zg==");
  EXPECT_EQ(Base64("fo"), "Zm8=");
  EXPECT_EQ(Base64("foo"), "Zm9v");
  EXPECT_EQ(Base64("foobar"), "Zm9vYmFy");
}

TEST(ReportHtml, EscapesTextAndEmbedsFigures) {
  Document d{"<title>", "a & b", {}};
  Section s{
      "one", "One", {"x < y"}, {{"t", {"duration (s)"}, {{"12.5"}}}}, {{"fig", "cap", "PNG"}}};
  d.sections.push_back(s);
  const std::string html = Html(d);
  EXPECT_THAT(html, HasSubstr("&lt;title&gt;"));
  EXPECT_THAT(html, HasSubstr("a &amp; b"));
  EXPECT_THAT(html, HasSubstr("x &lt; y"));
  EXPECT_THAT(html, HasSubstr("<th>duration (s)</th>"));
  EXPECT_THAT(html, HasSubstr("src=\"data:image/png;base64,UE5H\""));
  EXPECT_THAT(html, Not(HasSubstr("http")));  // nothing fetched from the network
}

// The schedule's figures on ROMEO surge: one per trial, the envelope inside the pool's free
// length (the planner only keeps trials the pool check passed), thrust panels with the zero line.
TEST(ReportFigures, ScheduleFiguresOfRomeoSurge) {
  const std::string cases = std::string(UUVPLAN_SOURCE_DIR) + "/cases/romeo/";
  const model::Vehicle vehicle = io::ReadVehicle(cases + "vehicle.yaml");
  const model::Pool pool = io::ReadPool(cases + "pool.yaml");
  planner::ScheduleOptions options;
  options.dofs = {model::Dof::kSurge};
  const planner::ScheduleResult plan = planner::PlanSchedule(vehicle, pool, options);
  ASSERT_FALSE(plan.schedule.trials.empty());
  std::vector<std::string> notes;
  const auto figures = ScheduleFigures(vehicle, pool, plan.schedule, options.planner, &notes);
  ASSERT_EQ(figures.size(), plan.schedule.trials.size());
  for (const Figure& f : figures) {
    ASSERT_EQ(f.panels.size(), 3u) << f.name;
    const Series& band = f.panels[0].series[0];
    ASSERT_EQ(band.style, Style::kBand);
    double lo = 0, hi = 0;
    for (std::size_t i = 0; i < band.x.size(); ++i)
      lo = std::min(lo, band.y_low[i]), hi = std::max(hi, band.y_high[i]);
    // The same grid as the pool check: the span fits the free length (1 mm for the coarser grid).
    EXPECT_LE(hi - lo, pool.FreeTravel(model::Dof::kSurge) + 1e-3) << f.name;
    EXPECT_GT(hi - lo, 0.0) << f.name;
    bool zero_line = false;
    for (const Level& l : f.panels[1].levels)
      zero_line = zero_line || (l.y == 0 && l.style == Style::kLine);
    EXPECT_TRUE(zero_line) << f.name;
  }
}

}  // namespace
}  // namespace uuvplan::report
