// FLIP in results.json is computed on exactly the 8-bit images the report shows.
#include "compare/tolerance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "compare/flip.h"
#include "compare/metric_table.h"
#include "compare/metrics.h"
#include "core/image_io.h"

namespace taa::compare {
namespace {

namespace fs = std::filesystem;

// Every kind of value a frame can hold: dark, mid, HDR highlights, negative, NaN, infinities,
// and values that sit close to an 8-bit rounding boundary.
Image awkwardFrame() {
  Image img(23, 7, 4);
  const float special[] = {std::numeric_limits<float>::quiet_NaN(),
                           std::numeric_limits<float>::infinity(),
                           -std::numeric_limits<float>::infinity(),
                           -0.5f,
                           0.0f,
                           1.0f,
                           40.0f};
  for (size_t i = 0; i < img.data.size(); ++i)
    img.data[i] =
        i % 11 == 0 ? special[(i / 11) % 7] : float(i % 97) / 37.0f + 1e-4f * float(i % 5);
  return img;
}

TEST(DisplayedPng, IsExactlyWhatThePngHolds) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "tolerance";
  fs::create_directories(dir);
  const Image hdr = awkwardFrame();
  writePng(dir / "frame.png", hdr);
  const Image png = readImage(dir / "frame.png");
  const Image shown = displayedPng(hdr);
  ASSERT_EQ(shown.width, png.width);
  ASSERT_EQ(shown.height, png.height);
  ASSERT_EQ(png.channels, 3);
  ASSERT_EQ(shown.channels, 3);
  for (size_t i = 0; i < shown.data.size(); ++i) {
    // Same 8-bit code, and the value is that code / 255 exactly.
    const long code = std::lround(png.data[i] * 255.0f);
    ASSERT_EQ(std::lround(shown.data[i] * 255.0f), code) << "sample " << i;
    ASSERT_EQ(shown.data[i], float(code) / 255.0f) << "sample " << i;
  }
}

TEST(DisplayedPng, FlipInTheMetricsIsFlipOfThePngs) {
  const Image golden = awkwardFrame();
  Image actual = golden;
  for (size_t i = 0; i < actual.data.size(); i += 3)
    actual.data[i] *= 1.01f;  // sub-8-bit changes mostly
  const auto measured = measureAgainstGolden(golden, actual, 1.0f / 255.0f);
  EXPECT_DOUBLE_EQ(measured.metrics.flipMean,
                   flipLdr(displayedPng(golden), displayedPng(actual)).mean);
  // The unrounded tonemapped images give another figure: the two are not the same measurement.
  EXPECT_NE(measured.metrics.flipMean, flipLdrFromHdr(golden, actual).mean);
}

// A frame equal to its golden skips the metrics and FLIP (most frames of a run): what it
// reports must be what the computation gives, for every kind of value a frame holds.
TEST(IdenticalFrames, MeasureAsTheFullComputationDoes) {
  std::vector<Image> frames = {awkwardFrame()};
  for (int channels : {1, 2, 3}) {
    Image img(9, 5, channels);
    for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = i % 4 == 0 ? -2.0f : float(i) / 7.0f;
    frames.push_back(img);
  }
  for (const Image& frame : frames) {
    for (float threshold : {0.0f, 1.0f / 255.0f, -1.0f}) {
      for (bool alpha : {false, true}) {
        MetricOptions options;
        options.threshold = threshold;
        options.includeAlpha = alpha;
        const Metrics full = computeMetrics(frame, frame, options);
        const Metrics skipped = metricsOfIdentical(frame, options);
        EXPECT_EQ(skipped.maxAbsError, full.maxAbsError);
        EXPECT_EQ(skipped.meanAbsError, full.meanAbsError);
        EXPECT_EQ(skipped.rmse, full.rmse);
        EXPECT_EQ(skipped.psnr, full.psnr);
        EXPECT_EQ(skipped.pixelsOverThreshold, full.pixelsOverThreshold) << threshold;
        EXPECT_EQ(skipped.shareOverThreshold, full.shareOverThreshold) << threshold;
        EXPECT_EQ(skipped.nonFinitePixels, full.nonFinitePixels);
        EXPECT_EQ(skipped.channelsCompared, full.channelsCompared) << frame.channels << alpha;
      }
    }
    const FlipResult flip = flipLdr(displayedPng(frame), displayedPng(frame));
    const Image copy = frame;  // another buffer with the same bytes: the shortcut's case
    const float threshold = 1.0f / 255.0f;
    const Measured measured = measureAgainstGolden(frame, copy, threshold);
    MetricOptions options;
    options.threshold = threshold;
    const Metrics full = computeMetrics(frame, frame, options);
    for (const auto* row : goldenMetrics())
      EXPECT_EQ(measured.metrics.*row->golden, row->value(full, flip)) << row->name;
    ASSERT_TRUE(measured.errorMap.sameShape(flip.errorMap));
    EXPECT_TRUE(measured.errorMap.data == flip.errorMap.data) << "FLIP of a frame against itself";
    EXPECT_EQ(measured.metrics.psnr, std::numeric_limits<double>::infinity());
  }
}

}  // namespace
}  // namespace taa::compare
