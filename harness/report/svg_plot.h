// A small deterministic SVG chart: line and scatter series on linear or log axes with ticks at
// nice numbers, used for the per-frame error curves and the error-versus-time sweep (with its
// Pareto front highlighted). Identical input gives byte-identical output: coordinates and tick
// labels are printed with fixed, locale-independent formatting and nothing depends on time.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace taa::report {

struct PlotSeries {
  std::string name;  // legend text; empty keeps the series out of the legend
  std::vector<double> x;
  std::vector<double> y;  // same length as x; non-finite points are skipped and break the line
  std::string colour;     // any SVG colour; empty picks one from a fixed palette by index
  bool line = true;
  bool markers = false;
  bool highlight = false;                // thicker, drawn last (a Pareto front, a failure)
  std::vector<std::string> pointLabels;  // optional tooltip per point
  bool showLabels = false;               // also print each point's label beside its marker
};

struct PlotOptions {
  int width = 640;
  int height = 200;
  std::string title;
  std::string xLabel;
  std::string yLabel;
  bool logX = false;  // log axes drop non-positive values
  bool logY = false;
  bool yFromZero = true;       // linear y axis starts at 0 so small errors do not look large
  bool integerX = false;       // x ticks only at integers (frame numbers)
  std::vector<double> xMarks;  // dashed vertical guides, e.g. the frames checked against goldens
  // The x axis covers at least [xMin, xMax] (NaN: the data alone decides), e.g. a case's whole
  // sequence when only one frame of it has a point.
  double xMin = std::numeric_limits<double>::quiet_NaN();
  double xMax = std::numeric_limits<double>::quiet_NaN();
  bool standalone = false;  // add the xmlns attribute needed by a separate .svg file
};

std::string svgPlot(const std::vector<PlotSeries>& series, const PlotOptions& options);

// Up to about maxTicks values of the form k * {1, 2, 5} * 10^n covering [lo, hi]: the first is
// <= lo and the last >= hi. lo == hi gives a range around the value.
std::vector<double> niceTicks(double lo, double hi, int maxTicks);

// Indices of the points no other point beats in both coordinates (smaller x and smaller y are
// better: time and error), sorted by increasing x. Non-finite points never belong to it.
std::vector<size_t> paretoFront(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace taa::report
