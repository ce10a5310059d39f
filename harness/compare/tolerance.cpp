#include "compare/tolerance.h"

#include <cmath>
#include <stdexcept>

#include "compare/flip.h"
#include "compare/metric_table.h"
#include "compare/metrics.h"
#include "core/image_io.h"

namespace taa::compare {

Image displayedPng(const Image& hdr) {
  Image d = toDisplaySrgb(hdr);  // no NaN left: NaN pixels are magenta
  // The same rounding as writePng's 8-bit quantization (core/image_io.cpp), expression for
  // expression.
  for (float& v : d.data) {
    const float clamped = v < 0.0f ? 0.0f : (v > 1.0f ? 1.0f : v);
    v = float(std::lround(clamped * 255.0f)) / 255.0f;
  }
  return d;
}

namespace {

// FLIP of an image against its own bytes: 0 at every pixel, as every metric of
// metricsOfIdentical. Most frames of a run match their golden exactly, and this skips three
// passes over each (the metrics, and FLIP's two display conversions and its filters).
FlipResult flipOfIdentical(const Image& image) {
  FlipResult flip;
  flip.errorMap = Image(image.width, image.height, 1);
  return flip;
}

}  // namespace

Measured measureAgainstGolden(const Image& golden, const Image& actual, float pixelThreshold) {
  MetricOptions options;
  options.threshold = pixelThreshold;
  const bool same = actual.pixelCount() > 0 && sameBits(golden, actual);
  const Metrics lin =
      same ? metricsOfIdentical(actual, options) : computeMetrics(golden, actual, options);
  const FlipResult flip =
      same ? flipOfIdentical(actual) : flipLdr(displayedPng(golden), displayedPng(actual));
  Measured out;
  for (const auto* row : goldenMetrics()) out.metrics.*row->golden = row->value(lin, flip);
  out.errorMap = flip.errorMap;
  return out;
}

std::vector<std::string> toleranceViolations(const run::ImageMetrics& m,
                                             const spec::ToleranceSpec& t) {
  std::vector<std::string> out;
  for (const auto* row : goldenMetrics()) {
    if (row->bound == nullptr) continue;
    const double value = m.*row->golden, bound = t.*row->bound;
    if (violates(*row, value, bound)) out.push_back(violationLine(*row, value, bound));
  }
  return out;
}

double metricByName(const run::ImageMetrics& m, const std::string& name) {
  const MetricInfo* row = findMetric(name);
  if (row == nullptr || row->golden == nullptr)
    throw std::invalid_argument("unknown metric '" + name + "'; use one of " +
                                metricList(goldenMetrics()));
  return m.*row->golden;
}

}  // namespace taa::compare
