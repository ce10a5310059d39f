#include "compare/metrics.h"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace taa::compare {

namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

void checkPair(const Image& a, const Image& b) {
  if (!a.sameShape(b)) {
    throw std::invalid_argument("compare: shapes differ: " + std::to_string(a.width) + "x" +
                                std::to_string(a.height) + "x" + std::to_string(a.channels) +
                                " vs " + std::to_string(b.width) + "x" + std::to_string(b.height) +
                                "x" + std::to_string(b.channels));
  }
  if (a.pixelCount() == 0 || a.channels <= 0) throw std::invalid_argument("compare: empty image");
}

int comparedChannels(const Image& img, const MetricOptions& options) {
  if (img.channels >= 4) return options.includeAlpha ? 4 : 3;
  return img.channels;
}

}  // namespace

double sampleError(float a, float b) {
  const bool nanA = std::isnan(a);
  const bool nanB = std::isnan(b);
  if (nanA || nanB) return nanA && nanB ? 0.0 : kInf;
  if (std::isinf(a) || std::isinf(b)) return a == b ? 0.0 : kInf;
  return std::fabs(double(a) - double(b));
}

Image errorImage(const Image& a, const Image& b, const MetricOptions& options) {
  checkPair(a, b);
  const int channels = comparedChannels(a, options);
  Image out(a.width, a.height, 1);
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      double worst = 0.0;
      for (int c = 0; c < channels; ++c) {
        const double e = sampleError(a.at(x, y, c), b.at(x, y, c));
        if (e > worst) worst = e;
      }
      out.at(x, y) = float(worst);
    }
  }
  return out;
}

Metrics computeMetrics(const Image& a, const Image& b, const MetricOptions& options) {
  checkPair(a, b);
  Metrics m;
  m.channelsCompared = comparedChannels(a, options);
  // Accumulated in a fixed order in double: for a 4K frame float sums would lose the small
  // errors a regression harness exists to catch, and the order keeps results bit-stable.
  double sumAbs = 0.0;
  double sumSq = 0.0;
  for (int y = 0; y < a.height; ++y) {
    for (int x = 0; x < a.width; ++x) {
      double worst = 0.0;
      for (int c = 0; c < m.channelsCompared; ++c) {
        const double e = sampleError(a.at(x, y, c), b.at(x, y, c));
        sumAbs += e;
        sumSq += e * e;
        if (e > worst) worst = e;
      }
      if (worst > m.maxAbsError) m.maxAbsError = worst;
      if (worst > options.threshold) ++m.pixelsOverThreshold;
      if (std::isinf(worst)) ++m.nonFinitePixels;
    }
  }
  const double samples = double(a.pixelCount()) * double(m.channelsCompared);
  const double mse = sumSq / samples;
  m.meanAbsError = sumAbs / samples;
  m.rmse = std::sqrt(mse);
  m.psnr = mse == 0.0 ? kInf : 10.0 * std::log10(1.0 / mse);
  m.shareOverThreshold = double(m.pixelsOverThreshold) / double(a.pixelCount());
  return m;
}

Metrics metricsOfIdentical(const Image& image, const MetricOptions& options) {
  checkPair(image, image);
  Metrics m;
  m.channelsCompared = comparedChannels(image, options);
  m.psnr = kInf;
  if (0.0 > options.threshold) m.pixelsOverThreshold = image.pixelCount();
  m.shareOverThreshold = double(m.pixelsOverThreshold) / double(image.pixelCount());
  return m;
}

}  // namespace taa::compare
