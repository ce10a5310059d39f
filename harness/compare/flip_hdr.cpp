// HDR-FLIP (flip.h): an exposure range from the reference, one LDR-FLIP per exposure through the
// shared core (flip_core.h), and the per-pixel maximum.
#include <algorithm>
#include <cmath>
#include <vector>

#include "compare/flip.h"
#include "compare/flip_common.h"
#include "compare/flip_core.h"

namespace taa::compare {

namespace {

// Narkowicz's ACES fit x (2.51 x + 0.03) / (x (2.43 x + 0.59) + 0.14) applied to 0.6 x, the
// pre-exposure the paper cancels, written as (a x^2 + b x + c) / (d x^2 + e x + f).
constexpr double kAces[6] = {0.6 * 0.6 * 2.51, 0.6 * 0.03, 0.0, 0.6 * 0.6 * 2.43, 0.6 * 0.59, 0.14};

// The input at which the curve reaches t: the positive root of
// (a - t d) x^2 + (b - t e) x + (c - t f) = 0.
double inputReaching(double t) {
  const double qa = kAces[0] - t * kAces[3];
  const double qb = kAces[1] - t * kAces[4];
  const double qc = kAces[2] - t * kAces[5];
  return (-qb + std::sqrt(qb * qb - 4.0 * qa * qc)) / (2.0 * qa);
}

struct ExposureRange {
  double start = 0.0;
  double stop = 0.0;
  int count = 1;
};

ExposureRange exposureRange(const Image& reference) {
  std::vector<float> lum;
  lum.reserve(reference.pixelCount());
  float smallestPositive = INFINITY;
  for (int y = 0; y < reference.height; ++y) {
    for (int x = 0; x < reference.width; ++x) {
      const bool grey = reference.channels < 3;
      float rgb[3];
      for (int c = 0; c < 3; ++c) rgb[c] = std::max(reference.at(x, y, grey ? 0 : c), 0.0f);
      const float l = 0.2126f * rgb[0] + 0.7152f * rgb[1] + 0.0722f * rgb[2];
      if (!std::isfinite(l)) continue;
      lum.push_back(l);
      if (l > 0.0f) smallestPositive = std::min(smallestPositive, l);
    }
  }
  ExposureRange range;
  if (lum.empty()) return range;
  const float yMax = *std::max_element(lum.begin(), lum.end());
  if (!(yMax > 0.0f)) return range;
  const auto mid = lum.begin() + std::ptrdiff_t(lum.size() / 2);
  std::nth_element(lum.begin(), mid, lum.end());
  const float yMedian = *mid > 0.0f ? *mid : smallestPositive;
  const double x85 = inputReaching(0.85);
  range.start = std::log2(x85 / double(yMax));
  range.stop = std::log2(x85 / double(yMedian));
  range.count = int(std::max(2.0, std::ceil(range.stop - range.start)));
  return range;
}

}  // namespace

HdrFlipResult flipHdr(const Image& referenceLinear, const Image& testLinear,
                      const FlipOptions& options) {
  flipdetail::checkInputs(referenceLinear, testLinear, options);
  const ExposureRange range = exposureRange(referenceLinear);
  flipdetail::InputMapping mapping;
  mapping.kind = flipdetail::InputMapping::Kind::ExposedToneMap;
  for (int i = 0; i < 6; ++i) mapping.toneMap[i] = float(kAces[i]);

  HdrFlipResult result;
  result.startExposure = range.start;
  result.stopExposure = range.stop;
  result.exposures = range.count;
  const double step = range.count > 1 ? (range.stop - range.start) / (range.count - 1) : 0.0;
  for (int i = 0; i < range.count; ++i) {
    mapping.exposure = float(std::exp2(range.start + i * step));
    Image map = flipdetail::flipErrorMap(referenceLinear, testLinear, mapping, options);
    if (i == 0) {
      result.errorMap = std::move(map);
      continue;
    }
    for (size_t p = 0; p < map.data.size(); ++p) {
      result.errorMap.data[p] = std::max(result.errorMap.data[p], map.data[p]);
    }
  }
  flipdetail::summarize(result);
  return result;
}

}  // namespace taa::compare
