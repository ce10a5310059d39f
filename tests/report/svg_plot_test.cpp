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

namespace {

// Every point label's box as drawn: 6 px per character at font-size 10, extending right of x,
// or left of it when anchored at its end; from 9 px above the baseline to 2 below.
struct DrawnLabel {
  double x0, y0, x1, y1;
};

std::vector<DrawnLabel> drawnLabels(const std::string& svg) {
  std::vector<DrawnLabel> out;
  for (size_t at = svg.find("class=\"point-label\""); at != std::string::npos;
       at = svg.find("class=\"point-label\"", at + 1)) {
    const size_t close = svg.find('>', at), end = svg.find("</text>", close);
    const double x = std::stod(svg.substr(svg.find("x=\"", at) + 3));
    const double y = std::stod(svg.substr(svg.find("y=\"", at) + 3));
    const double width = 6.0 * double(end - close - 1);
    const bool anchorEnd =
        svg.substr(at, close - at).find("text-anchor=\"end\"") != std::string::npos;
    out.push_back({anchorEnd ? x - width : x, y - 9.0, anchorEnd ? x : x + width, y + 2.0});
  }
  return out;
}

TEST(ReportSvgPlot, PointLabelsOfNearbyPointsDoNotOverlap) {
  // Three presets within a few pixels of each other: each label takes another side.
  PlotSeries front{.x = {10.0, 10.3, 10.6},
                   .y = {0.010, 0.0101, 0.0102},
                   .markers = true,
                   .pointLabels = {"msaa_4x", "tscmaa", "default"},
                   .showLabels = true};
  PlotSeries wide{.x = {1.0, 100.0}, .y = {0.0, 0.2}};
  const auto boxes = drawnLabels(svgPlot({wide, front}, {.logX = true}));
  ASSERT_EQ(boxes.size(), 3u);
  for (size_t i = 0; i < boxes.size(); ++i)
    for (size_t j = i + 1; j < boxes.size(); ++j) {
      const auto &a = boxes[i], &b = boxes[j];
      EXPECT_FALSE(a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1)
          << "labels " << i << " and " << j << " overlap";
    }
}

// An exact match plots RMSE 0 on an axis from 0 to 1 (no negative errors), over the whole
// sequence when the options ask for it.
TEST(ReportSvgPlot, AllZeroFromZeroAndForcedXRange) {
  PlotSeries one{.x = {23.0}, .y = {0.0}, .line = false, .markers = true};
  const std::string svg = svgPlot({one}, {.integerX = true, .xMin = 0.0, .xMax = 23.0});
  EXPECT_EQ(svg.find(">-"), std::string::npos);  // no negative tick label
  EXPECT_NE(svg.find(">1.0<"), std::string::npos);
  EXPECT_NE(svg.find(">0<"), std::string::npos);  // frame 0 is on the axis
  EXPECT_NE(svg.find(">20<"), std::string::npos);
  const std::string bare = svgPlot({one}, {.integerX = true});
  EXPECT_EQ(bare.find(">0<"), std::string::npos);  // without the range the axis starts at 23
}

}  // namespace
