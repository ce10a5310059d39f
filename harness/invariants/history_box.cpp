#include "invariants/history_box.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace taa::invariants::box {

namespace {

constexpr double kHalfMax = 65504.0;

// Rows of the YCoCg -> RGB matrix.
constexpr double kToRgb[3][3] = {{1, 1, -1}, {1, 0, 1}, {1, -1, -1}};

// The least (most = false) or greatest value RGB channel `k` takes anywhere in the box.
double extremeRgb(const Box& b, int k, bool most) {
  double m = 0.0;
  for (int j = 0; j < 3; ++j) m += kToRgb[k][j] * ((kToRgb[k][j] > 0) == most ? b.hi[j] : b.lo[j]);
  return m;
}

// Smallest excess with channels ks[0..n) of `rgb` lowered by t in [0, limit]. The excess is
// convex in the lowered values, and so is its minimum over the inner channel, so nested
// golden-section searches find the minimum.
double searchLowered(double rgb[3], const int* ks, const double* limits, int n, const Box& b) {
  if (n == 0) return excess(rgb, b, true);
  const int k = ks[0];
  const double saved = rgb[k];
  auto f = [&](double t) {
    rgb[k] = saved - t;
    const double e = searchLowered(rgb, ks + 1, limits + 1, n - 1, b);
    rgb[k] = saved;
    return e;
  };
  constexpr double kPhi = 0.6180339887498949;
  double a = 0.0, c = limits[0];
  const double ends = std::min(f(a), f(c));
  double x1 = c - kPhi * (c - a), x2 = a + kPhi * (c - a);
  double f1 = f(x1), f2 = f(x2);
  for (int i = 0; i < 40 && c - a > 1e-12; ++i) {
    if (f1 <= f2) {
      c = x2, x2 = x1, f2 = f1, x1 = c - kPhi * (c - a), f1 = f(x1);
    } else {
      a = x1, x1 = x2, f1 = f2, x2 = a + kPhi * (c - a), f2 = f(x2);
    }
  }
  return std::min({ends, f1, f2});
}

}  // namespace

void toWorking(const double rgb[3], bool ycocg, double w[3]) {
  if (!ycocg) {
    std::copy(rgb, rgb + 3, w);
    return;
  }
  w[0] = 0.25 * rgb[0] + 0.5 * rgb[1] + 0.25 * rgb[2];
  w[1] = 0.5 * rgb[0] - 0.5 * rgb[2];
  w[2] = -0.25 * rgb[0] + 0.5 * rgb[1] - 0.25 * rgb[2];
}

Box neighbourhoodBox(const Image& cur, int x, int y, bool ycocg, bool shrinkChroma) {
  constexpr double kInf = std::numeric_limits<double>::infinity();
  Box b{{kInf, kInf, kInf}, {-kInf, -kInf, -kInf}};
  double centre[3] = {0, 0, 0}, sum[3] = {0, 0, 0};
  int valid = 0;
  bool centreValid = false;
  // Clamped addressing repeats edge taps, which cannot change a min/max: visit the
  // in-bounds neighbours only.
  for (int j = std::max(y - 1, 0); j <= std::min(y + 1, cur.height - 1); ++j)
    for (int i = std::max(x - 1, 0); i <= std::min(x + 1, cur.width - 1); ++i) {
      double c[3], w[3];
      bool nan = false;
      for (int k = 0; k < 3; ++k) {
        const double v = cur.at(i, j, k);
        nan = nan || std::isnan(v);
        c[k] = std::isnan(v) ? 0.0 : std::clamp(v, 0.0, kHalfMax);
      }
      if (nan) continue;
      toWorking(c, ycocg, w);
      for (int k = 0; k < 3; ++k) {
        b.lo[k] = std::min(b.lo[k], w[k]);
        b.hi[k] = std::max(b.hi[k], w[k]);
        sum[k] += c[k];
      }
      ++valid;
      if (i == x && j == y) centreValid = true, std::copy(c, c + 3, centre);
    }
  if (valid == 0) return Box{{0, 0, 0}, {0, 0, 0}};
  if (ycocg && shrinkChroma) {
    if (!centreValid)
      for (int k = 0; k < 3; ++k) centre[k] = sum[k] / valid;
    double wc[3];
    toWorking(centre, true, wc);
    const double e = 0.125 * (b.hi[0] - b.lo[0]);  // the min/max extent: >= the resolve's
    for (int k = 1; k < 3; ++k) {
      b.lo[k] = std::min(b.lo[k], wc[k] - e);
      b.hi[k] = std::max(b.hi[k], wc[k] + e);
    }
  }
  return b;
}

double excess(const double rgb[3], const Box& b, bool ycocg) {
  double w[3];
  toWorking(rgb, ycocg, w);
  double e = 0.0;
  for (int k = 0; k < 3; ++k) e = std::max({e, b.lo[k] - w[k], w[k] - b.hi[k]});
  return e;
}

double liftedExcess(const double rgb[3], const Box& b, Lift lift) {
  double o[3] = {rgb[0], rgb[1], rgb[2]};
  // Either lift keeps each channel within [max(least, 0), max(greatest, 0)] of the box's RGB
  // range; outside that (with slack for rounding) no search can help.
  for (int k = 0; k < 3; ++k) {
    const double lo = std::max(extremeRgb(b, k, false), 0.0),
                 hi = std::max(extremeRgb(b, k, true), 0.0);
    if (o[k] < lo - std::ldexp(lo, -9) - 1e-6 || o[k] > hi + std::ldexp(hi, -9) + 1e-6)
      return excess(o, b, true);
  }
  int ks[3];
  double limits[3];
  int n = 0;
  for (int k = 0; k < 3; ++k) {
    const double deepest = -extremeRgb(b, k, false);
    if (deepest > 0.0 && (lift == Lift::NegativeChannels || o[k] == 0.0))
      ks[n] = k, limits[n] = deepest, ++n;
  }
  if (n < 3) return searchLowered(o, ks, limits, n, b);
  // Box colours have Y >= 0 (the taps are non-negative), so at most two of their channels
  // are negative: search the pairs rather than all three at once.
  double best = std::numeric_limits<double>::infinity();
  for (int skip = 0; skip < 3; ++skip) {
    int pk[2], m = 0;
    double pl[2];
    for (int i = 0; i < 3; ++i)
      if (i != skip) pk[m] = ks[i], pl[m] = limits[i], ++m;
    best = std::min(best, searchLowered(o, pk, pl, 2, b));
  }
  return best;
}

}  // namespace taa::invariants::box
