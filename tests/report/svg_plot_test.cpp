#include "report/svg_plot.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "support/text.h"

using taa::report::niceTicks;
using taa::report::paretoFront;
using taa::report::PlotOptions;
using taa::report::PlotSeries;
using taa::report::svgPlot;

namespace {

using taa::test::count;

TEST(ReportSvgPlot, NiceTicksCoverTheRangeWithRoundSteps) {
  const auto unit = niceTicks(0.0, 1.0, 6);
  ASSERT_EQ(unit.size(), 6u);
  for (size_t i = 0; i < unit.size(); ++i) EXPECT_NEAR(unit[i], 0.2 * double(i), 1e-12);
  EXPECT_EQ(niceTicks(0.0, 97.0, 5), (std::vector<double>{0.0, 50.0, 100.0}));
  const auto t = niceTicks(0.013, 0.047, 5);
  ASSERT_GE(t.size(), 2u);
  EXPECT_LE(t.front(), 0.013);
  EXPECT_GE(t.back(), 0.047);
  EXPECT_NEAR(t[1] - t[0], 0.01, 1e-12);
  const auto same = niceTicks(5.0, 5.0, 5);  // degenerate range still gives an axis
  EXPECT_LT(same.front(), 5.0);
  EXPECT_GT(same.back(), 5.0);
}

TEST(ReportSvgPlot, ParetoFrontKeepsUndominatedPointsByTime) {
  const std::vector<double> ms = {4.0, 1.0, 2.0, 3.0, 2.0, std::nan(""), 5.0};
  const std::vector<double> err = {0.01, 0.5, 0.1, 0.2, 0.05, 0.0, 0.01};
  // (1, .5) (2, .05) (4, .01); (5, .01) ties in error but is slower; NaN never counts.
  EXPECT_EQ(paretoFront(ms, err), (std::vector<size_t>{1, 4, 0}));
  EXPECT_TRUE(paretoFront({}, {}).empty());
}

TEST(ReportSvgPlot, ByteIdenticalAndWellFormed) {
  PlotSeries a{.name = "rmse", .x = {0, 1, 2, 3}, .y = {0.05, 0.02, 0.011, 0.01}};
  PlotSeries b{.name = "front",
               .x = {1, 3},
               .y = {0.02, 0.01},
               .markers = true,
               .highlight = true,
               .pointLabels = {"cfg <a>", "cfg b"}};
  PlotOptions o{.title = "err & time", .xLabel = "frame", .yLabel = "RMSE", .xMarks = {1, 3}};
  const std::string svg = svgPlot({a, b}, o);
  EXPECT_EQ(svg, svgPlot({a, b}, o));
  EXPECT_EQ(svg.rfind("<svg ", 0), 0u);
  EXPECT_EQ(svg.find("xmlns"), std::string::npos);  // inline in HTML needs none
  EXPECT_NE(svg.find(">err &amp; time<"), std::string::npos);
  EXPECT_NE(svg.find("<title>cfg &lt;a&gt;</title>"), std::string::npos);
  EXPECT_EQ(count(svg, "class=\"mark\""), 2u);
  EXPECT_EQ(count(svg, "<circle"), 3u);              // two points and the legend's marker
  EXPECT_NE(svg.find(">0.06<"), std::string::npos);  // y tick labels at round numbers
  EXPECT_NE(svg.find(">0.00<"), std::string::npos);
  // The highlighted series is drawn after the other one.
  EXPECT_LT(svg.find("data-name=\"rmse\""), svg.find("data-name=\"front\""));
  EXPECT_EQ(count(svg, "<g "), count(svg, "</g>"));
  EXPECT_EQ(svg.find("point-label"), std::string::npos);  // tooltips only, unless asked
  b.showLabels = true;
  const std::string labelled = svgPlot({a, b}, o);
  EXPECT_EQ(count(labelled, "class=\"point-label\""), 2u);
  EXPECT_NE(labelled.find(">cfg &lt;a&gt;</text>"), std::string::npos);
  EXPECT_NE(svgPlot({a}, {.standalone = true}).find("xmlns=\"http://www.w3.org/2000/svg\""),
            std::string::npos);
}

TEST(ReportSvgPlot, NonFiniteAndLogScaleBreakLines) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  PlotSeries s{.x = {0, 1, 2, 3, 4}, .y = {1, 2, nan, 3, 4}};
  EXPECT_EQ(count(svgPlot({s}, {}), "<polyline points=\"") - 1, 2u);  // minus the axes
  PlotSeries logs{.x = {1, 10, 100, 1000}, .y = {0.1, 0.0, 0.001, 0.0001}};
  const std::string svg = svgPlot({logs}, {.logX = true, .logY = true});
  EXPECT_EQ(count(svg, "<polyline points=\"") - 1, 2u);  // y = 0 has no place on a log axis
  EXPECT_NE(svg.find(">1000<"), std::string::npos);
  EXPECT_NE(svg.find(">0.0001<"), std::string::npos);
  EXPECT_EQ(svg.find("nan"), std::string::npos);
  EXPECT_NE(svgPlot({}, {}).find(">no data<"), std::string::npos);
}

}  // namespace
