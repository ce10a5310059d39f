// Pixel-difference statistics between a golden and a test frame.
//
// Which channels: RGB (the first three; all of them for 1- and 2-channel images). Alpha, the
// fourth channel, joins only with MetricOptions::includeAlpha.
//
// Per-sample error e(a, b) for two values of the same channel at the same pixel:
//   both NaN                          -> 0        (the same defect in both: equal)
//   exactly one NaN                   -> +Inf     (a NaN appearing or vanishing is a failure)
//   both +Inf or both -Inf            -> 0
//   any other pair with an infinity   -> +Inf
//   otherwise                         -> |a - b|, computed in double
// Every statistic is then an ordinary function of these errors, so one infinite error makes
// maxAbsError, meanAbsError and rmse +Inf and psnr -Inf, and the pixel counts as over any
// threshold. nonFinitePixels counts such pixels so a report can say why.
//
// PSNR uses a peak of 1.0 (frames are linear HDR with 1.0 as nominal white, so values above 1
// can give a negative PSNR) and is +Inf for identical images: 10 * log10(1 / MSE).
#pragma once

#include <cstddef>

#include "core/image.h"

namespace taa::compare {

struct MetricOptions {
  bool includeAlpha = false;
  // A pixel is "over" when its largest per-channel error is strictly greater than this.
  double threshold = 1.0 / 255.0;
};

struct Metrics {
  double maxAbsError = 0.0;   // over every compared sample
  double meanAbsError = 0.0;  // mean of per-sample errors
  double rmse = 0.0;          // sqrt(mean of squared per-sample errors)
  double psnr = 0.0;          // dB, peak 1.0
  size_t pixelsOverThreshold = 0;
  double shareOverThreshold = 0.0;  // pixelsOverThreshold / pixel count, in [0, 1]
  size_t nonFinitePixels = 0;       // pixels with at least one infinite sample error
  int channelsCompared = 0;
};

// Throws std::invalid_argument when the images differ in shape or are empty.
Metrics computeMetrics(const Image& a, const Image& b, const MetricOptions& options = {});
// computeMetrics(image, image, options) without reading a pixel: every sample error of an image
// against its own bytes is 0, NaN against NaN and an infinity against itself included.
Metrics metricsOfIdentical(const Image& image, const MetricOptions& options = {});

// One channel per pixel: the largest per-sample error over the compared channels (the quantity
// the threshold is applied to); +Inf where the rules above say so.
Image errorImage(const Image& a, const Image& b, const MetricOptions& options = {});

// The per-sample error rule above, exposed for callers and tests.
double sampleError(float a, float b);

}  // namespace taa::compare
