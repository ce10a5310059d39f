#include "compare/flip.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/image_io.h"

namespace taa::compare {

namespace {

// Constants of the paper (section 3) and its supplementary material.
constexpr double kQc = 0.7;  // colour error exponent
// The feature exponent qf = 0.5 appears as a square root in flipLdr.
constexpr double kPc = 0.4;                  // share of cmax mapped onto [0, pt)
constexpr double kPt = 0.95;                 // error value at pc * cmax
constexpr double kEdgePeakToTrough = 0.082;  // degrees; twice the detector's sigma

// D65 white in XYZ and the sRGB primaries' matrices (exact rational forms of IEC 61966-2-1).
constexpr double kWhite[3] = {0.950428545, 1.0, 1.088900371};
constexpr double kRgbToXyz[3][3] = {
    {10135552.0 / 24577794.0, 8788810.0 / 24577794.0, 4435075.0 / 24577794.0},
    {2613072.0 / 12288897.0, 8788810.0 / 12288897.0, 887015.0 / 12288897.0},
    {1425312.0 / 73733382.0, 8788810.0 / 73733382.0, 70074185.0 / 73733382.0}};
constexpr double kXyzToRgb[3][3] = {{3.241003275, -1.537398934, -0.498615861},
                                    {-0.969224334, 1.875930071, 0.041554224},
                                    {0.055639423, -0.204011202, 1.057148933}};

struct Plane {
  int w = 0;
  int h = 0;
  std::vector<double> v;
  Plane() = default;
  Plane(int width, int height) : w(width), h(height), v(size_t(width) * size_t(height), 0.0) {}
  double* row(int y) { return v.data() + size_t(y) * size_t(w); }
  const double* row(int y) const { return v.data() + size_t(y) * size_t(w); }
};

// A centred kernel that is even (k(-i) = k(i)) or odd (k(-i) = -k(i)), stored from its centre
// outwards. Every FLIP filter is one or the other, and folding the mirrored taps halves the
// multiplications. Odd kernels sum to zero by construction; `zeroSum` marks an even one that does
// in exact arithmetic (the second-derivative detector): it is applied as
// sum_i k(i) * ((in(x + i) - in(x)) + (in(x - i) - in(x))), which is the same filter but gives
// exactly zero on flat input. That matters because FLIP takes the square root of feature
// differences and would turn a rounding residue of 1e-17 into a visible error.
struct Kernel {
  std::vector<double> w;  // w[i]: weight at offset +i
  bool odd = false;
  bool zeroSum = false;
  int radius() const { return int(w.size()) - 1; }
};

// dst[x] = sum_i k(i) * at(i)[x] for i in [-r, r] (a correlation), where at(i) is the source
// sequence shifted by i. Taps are accumulated over the whole row so the inner loops vectorize.
template <class At>
void applyKernel(const Kernel& k, int n, At at, double* dst) {
  const double* c = at(0);
  const double w0 = k.odd || k.zeroSum ? 0.0 : k.w[0];
  for (int x = 0; x < n; ++x) dst[x] = w0 * c[x];
  for (int i = 1; i <= k.radius(); ++i) {
    const double* plus = at(i);
    const double* minus = at(-i);
    const double wi = k.w[size_t(i)];
    if (k.odd) {
      for (int x = 0; x < n; ++x) dst[x] += wi * (plus[x] - minus[x]);
    } else if (k.zeroSum) {
      for (int x = 0; x < n; ++x) dst[x] += wi * ((plus[x] - c[x]) + (minus[x] - c[x]));
    } else {
      for (int x = 0; x < n; ++x) dst[x] += wi * (plus[x] + minus[x]);
    }
  }
}

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

struct CsfTerm {
  Kernel horizontal;  // carries the term's weight and the kernel's normalization
  Kernel vertical;
};

// The contrast sensitivity kernel of one opponent channel as separable terms. The 2D kernel is
// sum_i a_i sqrt(pi/b_i) g_i(x) g_i(y) / S, with g_i(x) = exp(-pi^2 (x/ppd)^2 / b_i) and S its
// sum over the square, so each term factors into a row and a column pass.
std::vector<CsfTerm> csfKernel(double ppd, std::initializer_list<std::pair<double, double>> ab) {
  const double maxB = 0.04;  // the widest of all three channels sets one common radius
  const double pi2 = std::numbers::pi * std::numbers::pi;
  const int r = int(std::ceil(3.0 * std::sqrt(maxB / (2.0 * pi2)) * ppd));
  std::vector<CsfTerm> terms;
  double total = 0.0;
  for (const auto& [a, b] : ab) {
    CsfTerm t;
    double sum = 0.0;
    for (int x = 0; x <= r; ++x) {
      const double deg = x / ppd;
      t.vertical.w.push_back(std::exp(-pi2 * deg * deg / b));
      sum += (x == 0 ? 1.0 : 2.0) * t.vertical.w.back();
    }
    const double s = a * std::sqrt(std::numbers::pi / b);
    total += s * sum * sum;
    t.horizontal.w = t.vertical.w;
    for (double& v : t.horizontal.w) v *= s;
    terms.push_back(std::move(t));
  }
  for (CsfTerm& t : terms) {
    for (double& v : t.horizontal.w) v /= total;
  }
  return terms;
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

struct FeatureKernels {
  Kernel gauss;   // normalized to sum 1
  Kernel first;   // positive weights sum to 1, negative to -1
  Kernel second;  // likewise
};

// The 2D detectors are d(x) * e(y) with e > 0, so normalizing positive and negative 2D weights
// separately equals normalizing d's signed parts in 1D and e to sum 1.
FeatureKernels featureKernels(double ppd) {
  const double sd = 0.5 * kEdgePeakToTrough * ppd;
  const int r = int(std::ceil(3.0 * sd));
  FeatureKernels k;
  k.first.odd = true;
  k.second.zeroSum = true;
  double eSum = 0.0, firstSide = 0.0, secondPos = 0.0, secondNeg = 0.0;
  for (int x = 0; x <= r; ++x) {
    // x == 0 spelled out so a vanishing sigma (tiny ppd) cannot produce 0/0.
    const double x2 = double(x) * double(x);
    const double g = x == 0 ? 1.0 : std::exp(-x2 / (2.0 * sd * sd));
    const double second = ((x == 0 ? 0.0 : x2 / (sd * sd)) - 1.0) * g;
    const double mirrored = x == 0 ? 1.0 : 2.0;
    k.gauss.w.push_back(g);
    k.first.w.push_back(-x * g);
    k.second.w.push_back(second);
    eSum += mirrored * g;
    firstSide += x * g;  // both signs of the odd kernel have this magnitude
    (second > 0.0 ? secondPos : secondNeg) += mirrored * std::fabs(second);
  }
  for (double& v : k.gauss.w) v /= eSum;
  for (double& v : k.first.w) v = firstSide > 0.0 ? v / firstSide : 0.0;
  for (double& v : k.second.w) {
    const double d = v > 0.0 ? secondPos : secondNeg;
    v = d > 0.0 ? v / d : 0.0;
  }
  return k;
}

double srgbToLinear(double c) {
  return c > 0.04045 ? std::pow((c + 0.055) / 1.055, 2.4) : c / 12.92;
}

void mul3(const double m[3][3], const double in[3], double out[3]) {
  for (int i = 0; i < 3; ++i) out[i] = m[i][0] * in[0] + m[i][1] * in[1] + m[i][2] * in[2];
}

double labF(double t) {
  constexpr double delta = 6.0 / 29.0;
  return t > delta * delta * delta ? std::cbrt(t) : t / (3.0 * delta * delta) + 4.0 / 29.0;
}

// Linear RGB to Hunt-adjusted CIELAB.
void huntLab(const double rgb[3], double out[3]) {
  double xyz[3];
  mul3(kRgbToXyz, rgb, xyz);
  const double fx = labF(xyz[0] / kWhite[0]);
  const double fy = labF(xyz[1] / kWhite[1]);
  const double fz = labF(xyz[2] / kWhite[2]);
  const double l = 116.0 * fy - 16.0;
  out[0] = l;
  out[1] = 0.01 * l * 500.0 * (fx - fy);
  out[2] = 0.01 * l * 200.0 * (fy - fz);
}

double hyab(const double a[3], const double b[3]) {
  const double da = a[1] - b[1];
  const double db = a[2] - b[2];
  return std::fabs(a[0] - b[0]) + std::sqrt(da * da + db * db);
}

double cmax() {
  const double green[3] = {0.0, 1.0, 0.0};
  const double blue[3] = {0.0, 0.0, 1.0};
  double g[3], b[3];
  huntLab(green, g);
  huntLab(blue, b);
  return std::pow(hyab(g, b), kQc);
}

// What one image contributes to the per-pixel comparison.
struct Prepared {
  Plane lab[3];  // Hunt-adjusted L*a*b* of the CSF-filtered image
  Plane edge;    // length of the (x, y) edge response
  Plane point;   // length of the (x, y) point response
};

struct Kernels {
  std::vector<CsfTerm> csf[3];  // achromatic, red-green, blue-yellow
  FeatureKernels features;

  explicit Kernels(double ppd)
      : csf{csfKernel(ppd, {{1.0, 0.0047}}), csfKernel(ppd, {{1.0, 0.0053}}),
            csfKernel(ppd, {{34.1, 0.04}, {13.5, 0.025}})},
        features(featureKernels(ppd)) {}
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

void checkInputs(const Image& a, const Image& b, const FlipOptions& options) {
  if (!a.sameShape(b)) throw std::invalid_argument("flip: reference and test differ in shape");
  if (a.pixelCount() == 0 || a.channels <= 0) throw std::invalid_argument("flip: empty image");
  if (!(options.pixelsPerDegree > 0.0) || !std::isfinite(options.pixelsPerDegree)) {
    throw std::invalid_argument("flip: pixelsPerDegree must be positive and finite, got " +
                                std::to_string(options.pixelsPerDegree));
  }
}

float nearestRank(std::vector<float>& values, double percent) {
  const size_t n = values.size();
  const double rank = std::ceil(percent / 100.0 * double(n));
  const size_t k = size_t(std::clamp(rank, 1.0, double(n))) - 1;
  std::nth_element(values.begin(), values.begin() + std::ptrdiff_t(k), values.end());
  return values[k];
}

}  // namespace

double pixelsPerDegree(double distanceM, double widthM, int widthPx) {
  return distanceM * double(widthPx) / widthM * std::numbers::pi / 180.0;
}

FlipResult flipLdr(const Image& referenceSrgb, const Image& testSrgb, const FlipOptions& options) {
  checkInputs(referenceSrgb, testSrgb, options);
  const Kernels kernels(options.pixelsPerDegree);
  const Prepared ref = prepare(referenceSrgb, kernels);
  const Prepared test = prepare(testSrgb, kernels);

  static const double kCmax = cmax();
  const double pcCmax = kPc * kCmax;
  FlipResult result;
  result.errorMap = Image(referenceSrgb.width, referenceSrgb.height, 1);
  std::vector<float>& err = result.errorMap.data;
  double sum = 0.0;
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
    sum += err[i];
  }
  result.mean = sum / double(err.size());
  std::vector<float> sorted = err;
  result.max = *std::max_element(sorted.begin(), sorted.end());
  result.p50 = nearestRank(sorted, 50.0);
  result.p95 = nearestRank(sorted, 95.0);
  result.p99 = nearestRank(sorted, 99.0);
  return result;
}

FlipResult flipLdrFromHdr(const Image& referenceHdr, const Image& testHdr,
                          const FlipOptions& options) {
  checkInputs(referenceHdr, testHdr, options);
  return flipLdr(toDisplaySrgb(referenceHdr), toDisplaySrgb(testHdr), options);
}

}  // namespace taa::compare
