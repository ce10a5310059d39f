#include "report/svg_plot.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "report/text_util.h"

namespace taa::report {

namespace {

constexpr const char* kPalette[] = {"#2f6fdb", "#e07b00", "#2a9d4b",
                                    "#c0392b", "#8e44ad", "#16a5a5"};
constexpr double kMarginLeft = 58, kMarginRight = 14, kMarginTop = 24, kMarginBottom = 38;

// One axis: the data range mapped to a pixel range, optionally through log10.
struct Axis {
  bool log = false;
  double lo = 0, hi = 1;      // in axis space (log10 of the value on a log axis)
  double p0 = 0, p1 = 1;      // pixels for lo and hi
  std::vector<double> ticks;  // values, not axis space
  int decimals = -1;          // fixed decimals for tick labels; -1: significant digits

  double toAxis(double v) const { return log ? std::log10(v) : v; }
  double pixel(double v) const { return p0 + (toAxis(v) - lo) / (hi - lo) * (p1 - p0); }
  bool usable(double v) const { return std::isfinite(v) && (!log || v > 0); }
  std::string label(double v) const {
    if (log) {
      // Decades read best as plain numbers ("1000", "0.001") until they get long.
      const int e = int(std::floor(std::log10(v) + 1e-9));
      return e > -6 && e < 6 ? formatFixed(v, std::max(0, -e)) : formatNumber(v, 3);
    }
    return decimals >= 0 ? formatFixed(v, decimals) : formatNumber(v, 3);
  }
};

std::string px(double v) {
  return formatFixed(v, 1);
}

constexpr double kCharWidth = 6.6;  // monospace at font-size 11

// Where a point label goes: its box, its baseline and whether it is anchored at its end.
struct LabelBox {
  double x0, y0, x1, y1;
  double baseline;
  bool anchorEnd;
};

bool labelsOverlap(const LabelBox& a, const LabelBox& b) {
  return a.x0 < b.x1 && b.x0 < a.x1 && a.y0 < b.y1 && b.y0 < a.y1;
}

// Beside its marker at (cx, cy), in the first of four places (above or below, right or left;
// left first near the plot's right edge, so it is not cut off) that overlaps no label placed
// before; the first place when every one does. Pareto fronts of close presets stay readable.
LabelBox placeLabel(double cx, double cy, size_t chars, double rightEdge,
                    const std::vector<LabelBox>& placed) {
  constexpr double kLabelCharWidth = 6.0;  // font-size 10
  const double width = double(chars) * kLabelCharWidth;
  const bool leftFirst = cx > rightEdge - 80.0;
  std::vector<LabelBox> candidates;
  for (const bool left : {leftFirst, !leftFirst})
    for (const bool above : {true, false}) {
      const double baseline = above ? cy - 5.0 : cy + 13.0;
      const double x0 = left ? cx - 5.0 - width : cx + 5.0;
      candidates.push_back({x0, baseline - 9.0, x0 + width, baseline + 2.0, baseline, left});
    }
  for (const auto& c : candidates)
    if (std::none_of(placed.begin(), placed.end(),
                     [&](const LabelBox& p) { return labelsOverlap(c, p); }))
      return c;
  return candidates.front();
}

std::string colourOf(const std::vector<PlotSeries>& series, size_t i) {
  return series[i].colour.empty() ? kPalette[i % std::size(kPalette)] : series[i].colour;
}
const char* strokeOf(const PlotSeries& s) {
  return s.highlight ? "2.5" : "1.5";
}

// Legend entries in series order, right-aligned after the title; on a row of their own below it
// when both do not fit on one line. Returns the extra top margin the legend needs.
double legend(const std::vector<PlotSeries>& series, const PlotOptions& o, double w,
              std::string& out) {
  double total = 0;
  for (const auto& ps : series)
    if (!ps.name.empty()) total += 16 + kCharWidth * double(ps.name.size()) + 12;
  if (total == 0) return 0;
  const double titleEnd = kMarginLeft + kCharWidth * double(o.title.size()) + 16;
  double x = w - kMarginRight - total;
  double y = 15, extra = 0;
  if (!o.title.empty() && x < titleEnd) {
    y = 29;
    extra = 14;
    x = std::max(kMarginLeft, x);
  }
  for (size_t i = 0; i < series.size(); ++i) {
    const PlotSeries& ps = series[i];
    if (ps.name.empty()) continue;
    if (ps.line)
      out += "<line x1=\"" + px(x) + "\" y1=\"" + px(y - 4) + "\" x2=\"" + px(x + 12) + "\" y2=\"" +
             px(y - 4) + "\" stroke=\"" + colourOf(series, i) + "\" stroke-width=\"" +
             strokeOf(ps) + "\"/>\n";
    if (ps.markers)
      out += "<circle cx=\"" + px(x + 6) + "\" cy=\"" + px(y - 4) + "\" r=\"2.5\" fill=\"" +
             colourOf(series, i) + "\"/>\n";
    out +=
        "<text x=\"" + px(x + 16) + "\" y=\"" + px(y) + "\">" + escapeMarkup(ps.name) + "</text>\n";
    x += 16 + kCharWidth * double(ps.name.size()) + 12;
  }
  return extra;
}

// Ranges in axis space from the usable values; linear ranges snap outward to nice ticks.
Axis makeAxis(std::vector<double> values, bool log, bool fromZero, bool snap, bool integer,
              int maxTicks) {
  Axis a;
  a.log = log;
  std::vector<double> v;
  for (double x : values)
    if (a.usable(x)) v.push_back(x);
  if (v.empty()) v = {log ? 1.0 : 0.0, log ? 10.0 : 1.0};
  double lo = *std::min_element(v.begin(), v.end());
  double hi = *std::max_element(v.begin(), v.end());
  if (log) {
    double l0 = std::floor(std::log10(lo)), l1 = std::ceil(std::log10(hi));
    if (l1 <= l0) l1 = l0 + 1;
    a.lo = l0;
    a.hi = l1;
    // One tick per decade, thinned when there are many decades; 2 and 5 in between when there
    // are only one or two, so a narrow range still has something to read values against.
    const int stride = std::max(1, int(std::ceil((l1 - l0 + 1) / maxTicks)));
    for (int e = int(l0); e <= int(l1); e += stride) {
      a.ticks.push_back(std::pow(10.0, e));
      if (l1 - l0 <= 2 && e < int(l1))
        for (const double m : {2.0, 5.0}) a.ticks.push_back(m * std::pow(10.0, e));
    }
    return a;
  }
  if (fromZero) lo = std::min(lo, 0.0), hi = std::max(hi, 0.0);
  // All zero (an exact match) on an axis from zero: show [0, 1], not a range around 0 that
  // would offer negative errors.
  if (fromZero && hi == lo) hi = lo + 1.0;
  if (integer && hi - lo < 1) hi = lo + 1;
  a.ticks = niceTicks(lo, hi, maxTicks);
  const double step = a.ticks.size() > 1 ? a.ticks[1] - a.ticks[0] : 1.0;
  if (integer && step < 1) {
    a.ticks.clear();
    for (double t = std::ceil(lo); t <= hi; t += 1) a.ticks.push_back(t);
  }
  if (snap) {
    lo = std::min(lo, a.ticks.front());
    hi = std::max(hi, a.ticks.back());
  } else if (hi == lo) {
    hi = lo + 1;
  }
  std::erase_if(a.ticks,
                [&](double t) { return t < lo - 1e-9 * (hi - lo) || t > hi + 1e-9 * (hi - lo); });
  a.lo = lo;
  a.hi = hi;
  a.decimals = std::clamp(int(-std::floor(std::log10(step) + 1e-9)), 0, 6);
  if (std::abs(hi) >= 1e6 || std::abs(lo) >= 1e6 || step < 1e-6) a.decimals = -1;
  if (integer) a.decimals = 0;
  return a;
}

}  // namespace

std::vector<double> niceTicks(double lo, double hi, int maxTicks) {
  if (!std::isfinite(lo) || !std::isfinite(hi)) return {0.0, 1.0};
  if (lo > hi) std::swap(lo, hi);
  if (hi == lo) {
    const double pad = lo == 0 ? 1.0 : std::abs(lo) * 0.5;
    lo -= pad;
    hi += pad;
  }
  const double raw = (hi - lo) / std::max(1, maxTicks - 1);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  double step = magnitude * 10;
  for (const double m : {1.0, 2.0, 5.0}) {
    if (magnitude * m >= raw) {
      step = magnitude * m;
      break;
    }
  }
  // Integer multiples of the step, never accumulated sums, so values come out exact-ish and the
  // same on every run.
  const long long first = static_cast<long long>(std::floor(lo / step + 1e-9));
  const long long last = static_cast<long long>(std::ceil(hi / step - 1e-9));
  std::vector<double> ticks;
  for (long long i = first; i <= last; ++i) ticks.push_back(double(i) * step);
  return ticks;
}

std::vector<size_t> paretoFront(const std::vector<double>& x, const std::vector<double>& y) {
  std::vector<size_t> order;
  for (size_t i = 0; i < std::min(x.size(), y.size()); ++i)
    if (std::isfinite(x[i]) && std::isfinite(y[i])) order.push_back(i);
  std::stable_sort(order.begin(), order.end(),
                   [&](size_t a, size_t b) { return x[a] != x[b] ? x[a] < x[b] : y[a] < y[b]; });
  std::vector<size_t> front;
  double best = std::numeric_limits<double>::infinity();
  for (size_t i : order) {
    if (y[i] < best) {
      front.push_back(i);
      best = y[i];
    }
  }
  return front;
}

std::string svgPlot(const std::vector<PlotSeries>& series, const PlotOptions& o) {
  const double w = std::max(o.width, 160), h = std::max(o.height, 100);
  std::vector<double> xs, ys;
  for (const auto& s : series) {
    xs.insert(xs.end(), s.x.begin(), s.x.end());
    ys.insert(ys.end(), s.y.begin(), s.y.end());
  }
  for (const double bound : {o.xMin, o.xMax})
    if (std::isfinite(bound)) xs.push_back(bound);
  const bool anyData = [&] {
    for (const auto& s : series)
      for (size_t i = 0; i < std::min(s.x.size(), s.y.size()); ++i)
        if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) return true;
    return false;
  }();
  // Frame axes end at the first and last frame; other axes end on a labelled tick.
  Axis ax = makeAxis(xs, o.logX, false, !o.integerX, o.integerX, std::max(2, int(w / 70)));
  Axis ay = makeAxis(ys, o.logY, o.yFromZero, true, false, std::max(2, int(h / 40)));
  ax.p0 = kMarginLeft;
  ax.p1 = w - kMarginRight;
  ay.p0 = h - kMarginBottom;
  std::string legendSvg;
  ay.p1 = kMarginTop + legend(series, o, w, legendSvg);

  std::string s = "<svg";
  if (o.standalone) s += " xmlns=\"http://www.w3.org/2000/svg\"";
  s += " class=\"plot\" width=\"" + px(w) + "\" height=\"" + px(h) + "\" viewBox=\"0 0 " + px(w) +
       " " + px(h) + "\" font-family=\"monospace\" font-size=\"11\" role=\"img\"";
  s += " aria-label=\"" + escapeMarkup(o.title) + "\">\n";
  s += "<rect x=\"0\" y=\"0\" width=\"" + px(w) + "\" height=\"" + px(h) + "\" fill=\"#fff\"/>\n";
  if (!o.title.empty())
    s += "<text x=\"" + px(kMarginLeft) + "\" y=\"15\" font-weight=\"bold\">" +
         escapeMarkup(o.title) + "</text>\n";

  // Grid and tick labels first so data draws on top.
  for (double t : ax.ticks) {
    const std::string x = px(ax.pixel(t));
    s += "<line x1=\"" + x + "\" y1=\"" + px(ay.p1) + "\" x2=\"" + x + "\" y2=\"" + px(ay.p0) +
         "\" stroke=\"#e6e6e6\"/>\n";
    s += "<line x1=\"" + x + "\" y1=\"" + px(ay.p0) + "\" x2=\"" + x + "\" y2=\"" + px(ay.p0 + 4) +
         "\" stroke=\"#333\"/>\n";
    s += "<text x=\"" + x + "\" y=\"" + px(ay.p0 + 15) + "\" text-anchor=\"middle\">" +
         escapeMarkup(ax.label(t)) + "</text>\n";
  }
  for (double t : ay.ticks) {
    const std::string y = px(ay.pixel(t));
    s += "<line x1=\"" + px(ax.p0) + "\" y1=\"" + y + "\" x2=\"" + px(ax.p1) + "\" y2=\"" + y +
         "\" stroke=\"#e6e6e6\"/>\n";
    s += "<line x1=\"" + px(ax.p0 - 4) + "\" y1=\"" + y + "\" x2=\"" + px(ax.p0) + "\" y2=\"" + y +
         "\" stroke=\"#333\"/>\n";
    s += "<text x=\"" + px(ax.p0 - 6) + "\" y=\"" + px(ay.pixel(t) + 4) +
         "\" text-anchor=\"end\">" + escapeMarkup(ay.label(t)) + "</text>\n";
  }
  for (double m : o.xMarks) {
    if (!ax.usable(m) || ax.toAxis(m) < ax.lo || ax.toAxis(m) > ax.hi) continue;
    const std::string x = px(ax.pixel(m));
    s += "<line class=\"mark\" x1=\"" + x + "\" y1=\"" + px(ay.p1) + "\" x2=\"" + x + "\" y2=\"" +
         px(ay.p0) + "\" stroke=\"#999\" stroke-dasharray=\"3 3\"/>\n";
  }
  // Axes.
  s += "<polyline points=\"" + px(ax.p0) + "," + px(ay.p1) + " " + px(ax.p0) + "," + px(ay.p0) +
       " " + px(ax.p1) + "," + px(ay.p0) + "\" fill=\"none\" stroke=\"#333\"/>\n";
  if (!o.xLabel.empty())
    s += "<text x=\"" + px((ax.p0 + ax.p1) / 2) + "\" y=\"" + px(h - 6) +
         "\" text-anchor=\"middle\">" + escapeMarkup(o.xLabel) + "</text>\n";
  if (!o.yLabel.empty())
    s += "<text transform=\"translate(12," + px((ay.p0 + ay.p1) / 2) +
         ") rotate(-90)\" text-anchor=\"middle\">" + escapeMarkup(o.yLabel) + "</text>\n";
  if (!anyData)
    s += "<text x=\"" + px((ax.p0 + ax.p1) / 2) + "\" y=\"" + px((ay.p0 + ay.p1) / 2) +
         "\" text-anchor=\"middle\" fill=\"#888\">no data</text>\n";

  // Series, highlighted ones last so they stay visible where they overlap others.
  std::vector<size_t> order(series.size());
  std::iota(order.begin(), order.end(), size_t{0});
  std::stable_partition(order.begin(), order.end(), [&](size_t i) { return !series[i].highlight; });
  std::vector<LabelBox> placedLabels;
  for (const size_t i : order) {
    const PlotSeries& ps = series[i];
    const std::string colour = colourOf(series, i);
    const std::string width = strokeOf(ps);
    s += "<g class=\"series\" data-name=\"" + escapeMarkup(ps.name) + "\">\n";
    const size_t n = std::min(ps.x.size(), ps.y.size());
    if (ps.line) {
      std::string points;
      auto flush = [&] {
        if (points.empty()) return;
        s += "<polyline points=\"" + points + "\" fill=\"none\" stroke=\"" + colour +
             "\" stroke-width=\"" + width + "\" stroke-linejoin=\"round\"/>\n";
        points.clear();
      };
      for (size_t j = 0; j < n; ++j) {
        if (!ax.usable(ps.x[j]) || !ay.usable(ps.y[j])) {
          flush();
          continue;
        }
        if (!points.empty()) points += ' ';
        points += px(ax.pixel(ps.x[j])) + "," + px(ay.pixel(ps.y[j]));
      }
      flush();
    }
    if (ps.markers) {
      for (size_t j = 0; j < n; ++j) {
        if (!ax.usable(ps.x[j]) || !ay.usable(ps.y[j])) continue;
        s += "<circle cx=\"" + px(ax.pixel(ps.x[j])) + "\" cy=\"" + px(ay.pixel(ps.y[j])) +
             "\" r=\"" + (ps.highlight ? "3.5" : "2.5") + "\" fill=\"" + colour + "\"";
        if (j < ps.pointLabels.size())
          s += "><title>" + escapeMarkup(ps.pointLabels[j]) + "</title></circle>\n";
        else
          s += "/>\n";
        if (ps.showLabels && j < ps.pointLabels.size()) {
          const LabelBox b = placeLabel(ax.pixel(ps.x[j]), ay.pixel(ps.y[j]),
                                        ps.pointLabels[j].size(), ax.p1, placedLabels);
          placedLabels.push_back(b);
          s += "<text class=\"point-label\" x=\"" + px(b.anchorEnd ? b.x1 : b.x0) + "\" y=\"" +
               px(b.baseline) + "\" font-size=\"10\"" +
               (b.anchorEnd ? " text-anchor=\"end\"" : "") + ">" + escapeMarkup(ps.pointLabels[j]) +
               "</text>\n";
        }
      }
    }
    s += "</g>\n";
  }
  s += legendSvg;
  s += "</svg>\n";
  return s;
}

}  // namespace taa::report
