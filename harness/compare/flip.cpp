// The fast LDR-FLIP: the algorithm of flip.h in float, with the separable filters fused per row.
//
// Per image, each source row is converted once to the four planes the filters read (Y, Cx, Cz of
// YCxCz and luminance), filtered horizontally into seven planes (three CSF channels, the second
// blue-yellow CSF term, and the Gaussian, first and second derivative of luminance) held in a ring
// of 2R + 1 rows, R the larger filter radius. Each output row then takes its vertical passes from
// the ring, converts to Hunt-adjusted Lab and feature magnitudes, and is compared with the other
// image's row at once. Nothing image-sized is allocated but the error map.
//
// Rows are split into strips that threads claim in turn; a strip re-filters the R rows above and
// below it horizontally. Every row's horizontal result depends only on that row, and every output
// pixel's vertical sums run over the same taps in the same order, so each value is the same
// whatever the strip split or thread count (tests/compare/flip_fast_test.cpp checks it).
#include "compare/flip.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <memory>
#include <numbers>
#include <vector>

#include "compare/flip_common.h"
#include "compare/flip_core.h"
#include "compare/flip_math.h"
#include "compare/parallel.h"
#include "core/image_io.h"

namespace taa::compare {

namespace flipdetail {

namespace {

using flipmath::cbrtPositive;
using flipmath::powPositive;

struct FloatKernel {
  std::vector<float> w;  // from the centre outwards, as Kernel
  bool odd = false;
  bool zeroSum = false;
  int radius() const { return int(w.size()) - 1; }
  explicit FloatKernel(const Kernel& k) : odd(k.odd), zeroSum(k.zeroSum) {
    for (double v : k.w) w.push_back(float(v));
  }
};

struct FloatKernels {
  FloatKernel csfH[4];  // Y, Cx, Cz first term, Cz second term
  FloatKernel csfV[4];
  FloatKernel gauss, first, second;
  int radius;  // the larger of the CSF and feature radii: the ring's half height

  explicit FloatKernels(const Kernels& k)
      : csfH{FloatKernel(k.csf[0][0].horizontal), FloatKernel(k.csf[1][0].horizontal),
             FloatKernel(k.csf[2][0].horizontal), FloatKernel(k.csf[2][1].horizontal)},
        csfV{FloatKernel(k.csf[0][0].vertical), FloatKernel(k.csf[1][0].vertical),
             FloatKernel(k.csf[2][0].vertical), FloatKernel(k.csf[2][1].vertical)},
        gauss(k.features.gauss),
        first(k.features.first),
        second(k.features.second),
        radius(std::max(csfH[0].radius(), gauss.radius())) {}
};

enum Plane { kY, kCx, kCz1, kCz2, kGauss, kFirst, kSecond, kPlanes };

// One image's scratch rows in one worker.
struct Side {
  int w = 0;
  int slots = 0;
  std::vector<float> pad[4];  // Y, Cx, Cz, luminance of one row, clamp-padded by radius
  std::vector<float> ring;    // kPlanes x slots x w horizontally filtered rows
  std::vector<float> rgb[3];  // one row of linear RGB
  std::vector<float> acc[7];  // vertical results: Y, Cx, Cz, edge x/y, point x/y
  std::vector<float> tmp;     // the second Cz term
  std::vector<float> lab[3];  // Hunt-adjusted Lab of the output row
  std::vector<float> edge, point;

  Side(int width, int radius) : w(width), slots(2 * radius + 1) {
    for (auto& p : pad) p.resize(size_t(width + 2 * radius));
    ring.resize(size_t(kPlanes) * size_t(slots) * size_t(width));
    for (auto& v : rgb) v.resize(size_t(width));
    for (auto& v : acc) v.resize(size_t(width));
    for (auto& v : lab) v.resize(size_t(width));
    tmp.resize(size_t(width));
    edge.resize(size_t(width));
    point.resize(size_t(width));
  }
  float* ringRow(int plane, int slot) {
    return ring.data() + (size_t(plane) * size_t(slots) + size_t(slot)) * size_t(w);
  }
};

float srgbToLinear(float v) {
  const float c = std::isnan(v) ? 0.0f : std::clamp(v, 0.0f, 1.0f);
  return c > 0.04045f ? powPositive((c + 0.055f) * (1.0f / 1.055f), 2.4f) : c * (1.0f / 12.92f);
}

// HDR-FLIP's per-exposure mapping of linear samples, in place. A NaN anywhere shows the pixel
// magenta, as the harness's PNGs do; negatives count as 0 and +Inf as a value the curve has
// saturated long before. Written without branches so the loop vectorizes.
void exposeAndToneMap(int w, const InputMapping& m, float* __restrict r, float* __restrict g,
                      float* __restrict b) {
  const float* t = m.toneMap;
  auto curve = [&](float sample) {
    const float v = std::clamp(sample * m.exposure, 0.0f, 1e18f);
    return std::clamp((v * v * t[0] + v * t[1] + t[2]) / (v * v * t[3] + v * t[4] + t[5]), 0.0f,
                      1.0f);
  };
  for (int x = 0; x < w; ++x) {
    // Bitwise on ints, not ||: no branch, so the loop stays vectorizable.
    const bool nan = (int(std::isnan(r[x])) | int(std::isnan(g[x])) | int(std::isnan(b[x]))) != 0;
    const float mr = curve(r[x]), mg = curve(g[x]), mb = curve(b[x]);
    r[x] = nan ? 1.0f : mr;
    g[x] = nan ? 0.0f : mg;
    b[x] = nan ? 1.0f : mb;
  }
}

// Source row y of `image` as linear RGB in [0, 1], channel-planar.
void linearRow(const Image& image, int y, const InputMapping& m, Side& s) {
  const int w = image.width;
  const int ch = image.channels;
  const float* src = image.data.data() + image.index(0, y);
  for (int c = 0; c < 3; ++c) {
    const int from = ch < 3 ? 0 : c;
    float* dst = s.rgb[c].data();
    for (int x = 0; x < w; ++x) dst[x] = src[size_t(x) * size_t(ch) + size_t(from)];
  }
  if (m.kind == InputMapping::Kind::Srgb) {
    for (auto& plane : s.rgb)
      for (int x = 0; x < w; ++x) plane[size_t(x)] = srgbToLinear(plane[size_t(x)]);
    return;
  }
  exposeAndToneMap(w, m, s.rgb[0].data(), s.rgb[1].data(), s.rgb[2].data());
}

// Linear RGB to the opponent planes the filters read. __restrict (on parameters, where compilers
// honour it) spares the vectorized loop run-time checks that seven rows do not overlap.
void toOpponent(int w, const float* __restrict rr, const float* __restrict gg,
                const float* __restrict bb, float* __restrict y, float* __restrict cx,
                float* __restrict cz, float* __restrict lum) {
  constexpr float m00 = float(kRgbToXyz[0][0] / kWhite[0]),
                  m01 = float(kRgbToXyz[0][1] / kWhite[0]),
                  m02 = float(kRgbToXyz[0][2] / kWhite[0]);
  constexpr float m10 = float(kRgbToXyz[1][0]), m11 = float(kRgbToXyz[1][1]),
                  m12 = float(kRgbToXyz[1][2]);
  constexpr float m20 = float(kRgbToXyz[2][0] / kWhite[2]),
                  m21 = float(kRgbToXyz[2][1] / kWhite[2]),
                  m22 = float(kRgbToXyz[2][2] / kWhite[2]);
  for (int x = 0; x < w; ++x) {
    const float xn = m00 * rr[x] + m01 * gg[x] + m02 * bb[x];
    const float yn = m10 * rr[x] + m11 * gg[x] + m12 * bb[x];
    const float zn = m20 * rr[x] + m21 * gg[x] + m22 * bb[x];
    y[x] = 116.0f * yn - 16.0f;
    cx[x] = 500.0f * (xn - yn);
    cz[x] = 200.0f * (yn - zn);
    lum[x] = yn;
  }
}

// Converts source row clamp(v) and filters it horizontally into ring slot `slot`.
void horizontalRow(const Image& image, int v, int slot, const InputMapping& m,
                   const FloatKernels& k, Side& s) {
  const int w = image.width;
  const int r = k.radius;
  linearRow(image, std::clamp(v, 0, image.height - 1), m, s);
  float* y = s.pad[0].data() + r;
  float* cx = s.pad[1].data() + r;
  float* cz = s.pad[2].data() + r;
  float* lum = s.pad[3].data() + r;
  toOpponent(w, s.rgb[0].data(), s.rgb[1].data(), s.rgb[2].data(), y, cx, cz, lum);
  for (auto& p : s.pad) {
    std::fill(p.begin(), p.begin() + r, p[size_t(r)]);
    std::fill(p.end() - r, p.end(), p[size_t(r + w - 1)]);
  }
  auto shifted = [](const float* base) { return [base](int i) { return base + i; }; };
  applyKernel(k.csfH[0], w, shifted(y), s.ringRow(kY, slot));
  applyKernel(k.csfH[1], w, shifted(cx), s.ringRow(kCx, slot));
  applyKernel(k.csfH[2], w, shifted(cz), s.ringRow(kCz1, slot));
  applyKernel(k.csfH[3], w, shifted(cz), s.ringRow(kCz2, slot));
  applyKernel(k.gauss, w, shifted(lum), s.ringRow(kGauss, slot));
  applyKernel(k.first, w, shifted(lum), s.ringRow(kFirst, slot));
  applyKernel(k.second, w, shifted(lum), s.ringRow(kSecond, slot));
}

// CSF-filtered YCxCz back to linear RGB, clamped to [0, 1], then to Hunt-adjusted Lab.
void toHuntLab(int w, const float* __restrict fy, const float* __restrict fcx,
               const float* __restrict fcz, float* __restrict labL, float* __restrict labA,
               float* __restrict labB) {
  constexpr float inv[3][3] = {
      {float(kXyzToRgb[0][0]), float(kXyzToRgb[0][1]), float(kXyzToRgb[0][2])},
      {float(kXyzToRgb[1][0]), float(kXyzToRgb[1][1]), float(kXyzToRgb[1][2])},
      {float(kXyzToRgb[2][0]), float(kXyzToRgb[2][1]), float(kXyzToRgb[2][2])}};
  constexpr float fwd[3][3] = {
      {float(kRgbToXyz[0][0] / kWhite[0]), float(kRgbToXyz[0][1] / kWhite[0]),
       float(kRgbToXyz[0][2] / kWhite[0])},
      {float(kRgbToXyz[1][0]), float(kRgbToXyz[1][1]), float(kRgbToXyz[1][2])},
      {float(kRgbToXyz[2][0] / kWhite[2]), float(kRgbToXyz[2][1] / kWhite[2]),
       float(kRgbToXyz[2][2] / kWhite[2])}};
  constexpr float wx = float(kWhite[0]), wz = float(kWhite[2]);
  constexpr float delta3 = float(216.0 / 24389.0);  // (6/29)^3
  constexpr float slope = float(841.0 / 108.0);     // 1 / (3 (6/29)^2)
  constexpr float offset = float(4.0 / 29.0);
  auto labF = [&](float t) { return t > delta3 ? cbrtPositive(t) : t * slope + offset; };
  for (int x = 0; x < w; ++x) {
    const float yy = (fy[x] + 16.0f) * (1.0f / 116.0f);
    const float xyz[3] = {(yy + fcx[x] * (1.0f / 500.0f)) * wx, yy,
                          (yy - fcz[x] * (1.0f / 200.0f)) * wz};
    auto row = [&](int c) {
      const float v = inv[c][0] * xyz[0] + inv[c][1] * xyz[1] + inv[c][2] * xyz[2];
      return std::clamp(v, 0.0f, 1.0f);
    };
    const float rgb[3] = {row(0), row(1), row(2)};
    const float tx = fwd[0][0] * rgb[0] + fwd[0][1] * rgb[1] + fwd[0][2] * rgb[2];
    const float ty = fwd[1][0] * rgb[0] + fwd[1][1] * rgb[1] + fwd[1][2] * rgb[2];
    const float tz = fwd[2][0] * rgb[0] + fwd[2][1] * rgb[1] + fwd[2][2] * rgb[2];
    const float lx = labF(tx), ly = labF(ty), lz = labF(tz);
    const float l = 116.0f * ly - 16.0f;
    labL[x] = l;
    labA[x] = 5.0f * l * (lx - ly);  // 0.01 L * 500 (fx - fy)
    labB[x] = 2.0f * l * (ly - lz);  // 0.01 L * 200 (fy - fz)
  }
}

// Vertical passes for output row y (the ring holds rows y - R .. y + R), then Lab and features.
// Vertical passes for output row y, then Lab and feature magnitudes. The ring holds virtual rows
// y - R .. y + R, each filled from its clamped source row, so edge clamping is already done.
void verticalRow(int y, int firstRow, const FloatKernels& k, Side& s) {
  const int w = s.w;
  auto rows = [&](int plane) {
    return [&, plane](int i) { return s.ringRow(plane, (y + i - firstRow) % s.slots); };
  };
  applyKernel(k.csfV[0], w, rows(kY), s.acc[0].data());
  applyKernel(k.csfV[1], w, rows(kCx), s.acc[1].data());
  applyKernel(k.csfV[2], w, rows(kCz1), s.acc[2].data());
  applyKernel(k.csfV[3], w, rows(kCz2), s.tmp.data());
  for (int x = 0; x < w; ++x) s.acc[2][size_t(x)] += s.tmp[size_t(x)];
  applyKernel(k.gauss, w, rows(kFirst), s.acc[3].data());
  applyKernel(k.first, w, rows(kGauss), s.acc[4].data());
  applyKernel(k.gauss, w, rows(kSecond), s.acc[5].data());
  applyKernel(k.second, w, rows(kGauss), s.acc[6].data());

  toHuntLab(w, s.acc[0].data(), s.acc[1].data(), s.acc[2].data(), s.lab[0].data(), s.lab[1].data(),
            s.lab[2].data());
  for (int x = 0; x < w; ++x) {
    const float ex = s.acc[3][size_t(x)], ey = s.acc[4][size_t(x)];
    const float px = s.acc[5][size_t(x)], py = s.acc[6][size_t(x)];
    s.edge[size_t(x)] = std::sqrt(ex * ex + ey * ey);
    s.point[size_t(x)] = std::sqrt(px * px + py * py);
  }
}

void compareRow(const Side& a, const Side& b, float cmaxValue, float* err) {
  const float pcCmax = float(kPc) * cmaxValue;
  const float lowSlope = float(kPt) / pcCmax;
  const float highSlope = float(1.0 - kPt) / (cmaxValue - pcCmax);
  for (int x = 0; x < a.w; ++x) {
    const size_t i = size_t(x);
    const float dl = std::fabs(a.lab[0][i] - b.lab[0][i]);
    const float da = a.lab[1][i] - b.lab[1][i];
    const float db = a.lab[2][i] - b.lab[2][i];
    const float distance = dl + std::sqrt(da * da + db * db);
    const float powered = distance == 0.0f ? 0.0f : powPositive(std::max(distance, FLT_MIN), 0.7f);
    const float colour =
        powered < pcCmax ? lowSlope * powered : float(kPt) + (powered - pcCmax) * highSlope;
    const float featureDiff =
        std::max(std::fabs(a.edge[i] - b.edge[i]), std::fabs(a.point[i] - b.point[i]));
    // qf = 0.5: the feature exponent is a square root.
    const float feature = std::sqrt(featureDiff * float(1.0 / std::numbers::sqrt2));
    const float exponent = 1.0f - feature;
    // pow(c, 1) == c and pow(0, e > 0) == 0 exactly, as in the double implementation.
    const float general = powPositive(std::max(colour, FLT_MIN), std::max(exponent, 0.0f));
    err[x] = exponent == 1.0f ? colour : colour == 0.0f ? (exponent > 0.0f ? 0.0f : 1.0f) : general;
  }
}

// Strip height: results do not depend on it; one strip per thread would be fastest on an idle
// machine, four per thread keeps both cores busy when another process takes one for a while.
int stripRows(int height, int threads, int radius) {
  const int strips = threads == 1 ? 1 : 4 * threads;
  return std::max((height + strips - 1) / strips, 2 * radius);
}

}  // namespace

Image flipErrorMap(const Image& reference, const Image& test, const InputMapping& mapping,
                   const FlipOptions& options) {
  const Kernels kernels(options.pixelsPerDegree);
  const FloatKernels k(kernels);
  const int w = reference.width;
  const int h = reference.height;
  const int r = k.radius;
  static const float kCmax = float(cmax());
  Image err(w, h, 1);

  const int threads = resolveThreads(options.threads, h);
  const int rowsPerStrip = stripRows(h, threads, r);
  const int strips = (h + rowsPerStrip - 1) / rowsPerStrip;
  struct Scratch {
    Side ref, test;
  };
  std::vector<std::unique_ptr<Scratch>> scratch(size_t(resolveThreads(threads, strips)));
  parallelFor(strips, threads, [&](int worker, int strip) {
    auto& sc = scratch[size_t(worker)];
    if (!sc) sc = std::make_unique<Scratch>(Scratch{Side(w, r), Side(w, r)});
    const int y0 = strip * rowsPerStrip;
    const int y1 = std::min(h, y0 + rowsPerStrip);
    const int firstRow = y0 - r;  // the ring's first virtual row
    for (int v = firstRow; v < y0 + r; ++v) {
      horizontalRow(reference, v, (v - firstRow) % sc->ref.slots, mapping, k, sc->ref);
      horizontalRow(test, v, (v - firstRow) % sc->test.slots, mapping, k, sc->test);
    }
    for (int y = y0; y < y1; ++y) {
      const int v = y + r;
      horizontalRow(reference, v, (v - firstRow) % sc->ref.slots, mapping, k, sc->ref);
      horizontalRow(test, v, (v - firstRow) % sc->test.slots, mapping, k, sc->test);
      verticalRow(y, firstRow, k, sc->ref);
      verticalRow(y, firstRow, k, sc->test);
      compareRow(sc->ref, sc->test, kCmax, err.data.data() + size_t(y) * size_t(w));
    }
  });
  return err;
}

}  // namespace flipdetail

double pixelsPerDegree(double distanceM, double widthM, int widthPx) {
  return distanceM * double(widthPx) / widthM * std::numbers::pi / 180.0;
}

FlipResult flipLdr(const Image& referenceSrgb, const Image& testSrgb, const FlipOptions& options) {
  flipdetail::checkInputs(referenceSrgb, testSrgb, options);
  FlipResult result;
  result.errorMap = flipdetail::flipErrorMap(referenceSrgb, testSrgb, {}, options);
  flipdetail::summarize(result);
  return result;
}

FlipResult flipLdrFromHdr(const Image& referenceHdr, const Image& testHdr,
                          const FlipOptions& options) {
  flipdetail::checkInputs(referenceHdr, testHdr, options);
  return flipLdr(toDisplaySrgb(referenceHdr), toDisplaySrgb(testHdr), options);
}

}  // namespace taa::compare
