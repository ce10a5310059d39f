#include "compare/flip_double.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "compare/flip_common.h"

namespace taa::compare {

namespace {

using namespace flipdetail;

struct Plane {
  int w = 0;
  int h = 0;
  std::vector<double> v;
  Plane() = default;
  Plane(int width, int height) : w(width), h(height), v(size_t(width) * size_t(height), 0.0) {}
  double* row(int y) { return v.data() + size_t(y) * size_t(w); }
  const double* row(int y) const { return v.data() + size_t(y) * size_t(w); }
};

// Along rows, clamp-to-edge.
void filterRows(const Plane& in, const Kernel& k, Plane& out) {
  const int r = k.radius();
  out = Plane(in.w, in.h);
  std::vector<double> padded(size_t(in.w) + 2 * size_t(r));
  for (int y = 0; y < in.h; ++y) {
    const double* src = in.row(y);
    for (int i = 0; i < int(padded.size()); ++i) {
      padded[size_t(i)] = src[std::clamp(i - r, 0, in.w - 1)];
    }
    applyKernel(
        k, in.w, [&](int i) { return padded.data() + r + i; }, out.row(y));
  }
}

// Along columns, clamp-to-edge; whole rows at a time so memory is walked linearly.
void filterCols(const Plane& in, const Kernel& k, Plane& out) {
  out = Plane(in.w, in.h);
  for (int y = 0; y < in.h; ++y) {
    applyKernel(
        k, in.w, [&](int i) { return in.row(std::clamp(y + i, 0, in.h - 1)); }, out.row(y));
  }
}

void applyCsf(const Plane& in, const std::vector<CsfTerm>& terms, Plane& out) {
  Plane rows;
  Plane cols;
  out = Plane(in.w, in.h);
  for (const CsfTerm& t : terms) {
    filterRows(in, t.horizontal, rows);
    filterCols(rows, t.vertical, cols);
    for (size_t i = 0; i < out.v.size(); ++i) out.v[i] += cols.v[i];
  }
}

double srgbToLinear(double c) {
  return c > 0.04045 ? std::pow((c + 0.055) / 1.055, 2.4) : c / 12.92;
}

void mul3(const double m[3][3], const double in[3], double out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = m[i][0] * in[0] + m[i][1] * in[1] + m[i][2] * in[2];
}

// What one image contributes to the per-pixel comparison.
struct Prepared {
  Plane lab[3];  // Hunt-adjusted L*a*b* of the CSF-filtered image
  Plane edge;    // length of the (x, y) edge response
  Plane point;   // length of the (x, y) point response
};

Prepared prepare(const Image& srgb, const Kernels& kernels) {
  const int w = srgb.width;
  const int h = srgb.height;
  const bool grey = srgb.channels < 3;
  Plane opp[3] = {Plane(w, h), Plane(w, h), Plane(w, h)};
  Plane luminance(w, h);
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      double rgb[3];
      for (int c = 0; c < 3; ++c) {
        const double v = srgb.at(x, y, grey ? 0 : c);
        rgb[c] = srgbToLinear(std::isnan(v) ? 0.0 : std::clamp(v, 0.0, 1.0));
      }
      double xyz[3];
      mul3(kRgbToXyz, rgb, xyz);
      const double yy = xyz[1] / kWhite[1];
      const size_t i = size_t(y) * size_t(w) + size_t(x);
      opp[0].v[i] = 116.0 * yy - 16.0;
      opp[1].v[i] = 500.0 * (xyz[0] / kWhite[0] - yy);
      opp[2].v[i] = 200.0 * (yy - xyz[2] / kWhite[2]);
      luminance.v[i] = yy;
    }
  }

  Prepared p;
  // Colour pipeline.
  Plane filtered[3];
  for (int c = 0; c < 3; ++c) applyCsf(opp[c], kernels.csf[c], filtered[c]);
  for (int c = 0; c < 3; ++c) p.lab[c] = Plane(w, h);
  for (size_t i = 0; i < luminance.v.size(); ++i) {
    const double yy = (filtered[0].v[i] + 16.0) / 116.0;
    const double xyz[3] = {(yy + filtered[1].v[i] / 500.0) * kWhite[0], yy * kWhite[1],
                           (yy - filtered[2].v[i] / 200.0) * kWhite[2]};
    double rgb[3];
    mul3(kXyzToRgb, xyz, rgb);
    for (double& c : rgb) c = std::clamp(c, 0.0, 1.0);
    double lab[3];
    huntLab(rgb, lab);
    for (int c = 0; c < 3; ++c) p.lab[c].v[i] = lab[c];
  }

  // Feature pipeline: three row passes shared by four column passes.
  const FeatureKernels& fk = kernels.features;
  Plane rowGauss, rowFirst, rowSecond, edgeX, edgeY, pointX, pointY;
  filterRows(luminance, fk.gauss, rowGauss);
  filterRows(luminance, fk.first, rowFirst);
  filterRows(luminance, fk.second, rowSecond);
  filterCols(rowFirst, fk.gauss, edgeX);
  filterCols(rowGauss, fk.first, edgeY);
  filterCols(rowSecond, fk.gauss, pointX);
  filterCols(rowGauss, fk.second, pointY);
  p.edge = Plane(w, h);
  p.point = Plane(w, h);
  for (size_t i = 0; i < luminance.v.size(); ++i) {
    p.edge.v[i] = std::sqrt(edgeX.v[i] * edgeX.v[i] + edgeY.v[i] * edgeY.v[i]);
    p.point.v[i] = std::sqrt(pointX.v[i] * pointX.v[i] + pointY.v[i] * pointY.v[i]);
  }
  return p;
}

}  // namespace

FlipResult flipLdrDouble(const Image& referenceSrgb, const Image& testSrgb,
                         const FlipOptions& options) {
  checkInputs(referenceSrgb, testSrgb, options);
  const Kernels kernels(options.pixelsPerDegree);
  const Prepared ref = prepare(referenceSrgb, kernels);
  const Prepared test = prepare(testSrgb, kernels);

  static const double kCmax = cmax();
  const double pcCmax = kPc * kCmax;
  FlipResult result;
  result.errorMap = Image(referenceSrgb.width, referenceSrgb.height, 1);
  std::vector<float>& err = result.errorMap.data;
  for (size_t i = 0; i < err.size(); ++i) {
    const double a[3] = {ref.lab[0].v[i], ref.lab[1].v[i], ref.lab[2].v[i]};
    const double b[3] = {test.lab[0].v[i], test.lab[1].v[i], test.lab[2].v[i]};
    const double distance = hyab(a, b);
    const double powered = distance == 0.0 ? 0.0 : std::pow(distance, kQc);
    const double colour = powered < pcCmax
                              ? kPt / pcCmax * powered
                              : kPt + (powered - pcCmax) / (kCmax - pcCmax) * (1.0 - kPt);
    const double edgeDiff = std::fabs(ref.edge.v[i] - test.edge.v[i]);
    const double pointDiff = std::fabs(ref.point.v[i] - test.point.v[i]);
    // qf = 0.5, so the feature exponent is a square root (exact, unlike pow).
    const double feature = std::sqrt(std::max(edgeDiff, pointDiff) / std::numbers::sqrt2);
    // pow(c, 1) == c and pow(0, e) == 0 for e > 0: skipping those calls is exact and makes
    // the common unchanged-pixel case cheap.
    const double exponent = 1.0 - feature;
    const double e = exponent == 1.0                   ? colour
                     : colour == 0.0 && exponent > 0.0 ? 0.0
                                                       : std::pow(colour, exponent);
    err[i] = float(e);
  }
  summarize(result);
  return result;
}

}  // namespace taa::compare
