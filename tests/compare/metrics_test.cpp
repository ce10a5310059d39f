#include "compare/metrics.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

using taa::Image;
using taa::compare::computeMetrics;
using taa::compare::errorImage;
using taa::compare::MetricOptions;
using taa::compare::sampleError;

namespace {

constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

Image ramp(int w, int h, int c) {
  Image img(w, h, c);
  // Multiples of 1/64 so adding 1/8 below stays exact in float.
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = float(i % 61) / 64.0f;
  return img;
}

}  // namespace

TEST(MetricBasics, IdenticalImagesHaveZeroErrorAndInfinitePsnr) {
  const Image a = ramp(8, 5, 4);
  const auto m = computeMetrics(a, a);
  EXPECT_EQ(m.maxAbsError, 0.0);
  EXPECT_EQ(m.meanAbsError, 0.0);
  EXPECT_EQ(m.rmse, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr) && m.psnr > 0);
  EXPECT_EQ(m.pixelsOverThreshold, 0u);
  EXPECT_EQ(m.shareOverThreshold, 0.0);
  EXPECT_EQ(m.channelsCompared, 3);
}

TEST(MetricBasics, ConstantOffsetGivesAnalyticValues) {
  // Offsets of 1/8 are exact in float, so every error is exactly 0.125.
  const Image a = ramp(16, 9, 3);
  Image b = a;
  for (float& v : b.data) v += 0.125f;
  const auto m = computeMetrics(a, b);
  EXPECT_DOUBLE_EQ(m.maxAbsError, 0.125);
  EXPECT_DOUBLE_EQ(m.meanAbsError, 0.125);
  EXPECT_DOUBLE_EQ(m.rmse, 0.125);
  EXPECT_NEAR(m.psnr, 20.0 * std::log10(8.0), 1e-12);  // 18.0618 dB
  EXPECT_EQ(m.pixelsOverThreshold, 144u);
  EXPECT_DOUBLE_EQ(m.shareOverThreshold, 1.0);
}

TEST(MetricBasics, OffsetInOneChannelAveragesOverChannels) {
  Image a(4, 4, 3, 0.5f);
  Image b = a;
  for (int y = 0; y < 4; ++y)
    for (int x = 0; x < 4; ++x) b.at(x, y, 1) = 0.25f;
  const auto m = computeMetrics(a, b);
  EXPECT_DOUBLE_EQ(m.maxAbsError, 0.25);
  EXPECT_DOUBLE_EQ(m.meanAbsError, 0.25 / 3.0);
  EXPECT_DOUBLE_EQ(m.rmse, std::sqrt(0.0625 / 3.0));
  EXPECT_NEAR(m.psnr, 10.0 * std::log10(3.0 / 0.0625), 1e-12);
}

TEST(MetricBasics, AlphaIgnoredUnlessAsked) {
  Image a(3, 3, 4, 0.5f);
  Image b = a;
  b.at(1, 1, 3) = 0.0f;
  EXPECT_EQ(computeMetrics(a, b).maxAbsError, 0.0);
  MetricOptions withAlpha;
  withAlpha.includeAlpha = true;
  const auto m = computeMetrics(a, b, withAlpha);
  EXPECT_EQ(m.channelsCompared, 4);
  EXPECT_DOUBLE_EQ(m.maxAbsError, 0.5);
  EXPECT_DOUBLE_EQ(m.meanAbsError, 0.5 / 36.0);
}

TEST(MetricThreshold, CountsPixelsStrictlyOverThreshold) {
  Image a(10, 10, 3, 0.0f);
  Image b = a;
  // 7 pixels clearly over, 5 exactly at the threshold (not over), 3 just under.
  for (int i = 0; i < 7; ++i) b.at(i, 0, 2) = 0.5f;
  for (int i = 0; i < 5; ++i) b.at(i, 1, 0) = 0.25f;
  for (int i = 0; i < 3; ++i) b.at(i, 2, 1) = 0.2499f;
  MetricOptions opt;
  opt.threshold = 0.25;
  const auto m = computeMetrics(a, b, opt);
  EXPECT_EQ(m.pixelsOverThreshold, 7u);
  EXPECT_DOUBLE_EQ(m.shareOverThreshold, 0.07);
  opt.threshold = 0.2;
  EXPECT_EQ(computeMetrics(a, b, opt).pixelsOverThreshold, 15u);
  // Errors in several channels of one pixel count that pixel once.
  b.at(0, 0, 0) = 0.5f;
  b.at(0, 0, 1) = 0.5f;
  EXPECT_EQ(computeMetrics(a, b, opt).pixelsOverThreshold, 15u);
}

TEST(MetricNan, SampleErrorRules) {
  EXPECT_EQ(sampleError(kNan, kNan), 0.0);
  EXPECT_TRUE(std::isinf(sampleError(kNan, 0.0f)));
  EXPECT_TRUE(std::isinf(sampleError(1.0f, kNan)));
  EXPECT_EQ(sampleError(kInf, kInf), 0.0);
  EXPECT_EQ(sampleError(-kInf, -kInf), 0.0);
  EXPECT_TRUE(std::isinf(sampleError(kInf, -kInf)));
  EXPECT_TRUE(std::isinf(sampleError(kInf, 1e30f)));
  EXPECT_TRUE(std::isinf(sampleError(kNan, kInf)));
  EXPECT_EQ(sampleError(-1.0f, 2.0f), 3.0);
}

TEST(MetricNan, NanInBothImagesAtSamePlaceIsEqual) {
  Image a = ramp(5, 5, 3);
  a.at(2, 3, 1) = kNan;
  const Image b = a;
  const auto m = computeMetrics(a, b);
  EXPECT_EQ(m.maxAbsError, 0.0);
  EXPECT_TRUE(std::isinf(m.psnr) && m.psnr > 0);
  EXPECT_EQ(m.nonFinitePixels, 0u);
  EXPECT_EQ(errorImage(a, b).at(2, 3), 0.0f);
}

TEST(MetricNan, NanInOneImageIsInfiniteErrorAtThatPixel) {
  const Image a = ramp(5, 5, 3);
  Image b = a;
  b.at(4, 1, 0) = kNan;
  MetricOptions opt;
  opt.threshold = 1e30;
  const auto m = computeMetrics(a, b, opt);
  EXPECT_TRUE(std::isinf(m.maxAbsError));
  EXPECT_TRUE(std::isinf(m.meanAbsError));
  EXPECT_TRUE(std::isinf(m.rmse));
  EXPECT_TRUE(std::isinf(m.psnr) && m.psnr < 0);
  EXPECT_EQ(m.nonFinitePixels, 1u);
  EXPECT_EQ(m.pixelsOverThreshold, 1u);  // over any finite threshold
  const Image e = errorImage(a, b);
  EXPECT_TRUE(std::isinf(e.at(4, 1)));
  EXPECT_EQ(e.at(3, 1), 0.0f);
  // Symmetric, and NaN at different places in both images is two bad pixels.
  Image c = a;
  c.at(0, 0, 2) = kNan;
  EXPECT_EQ(computeMetrics(b, c).nonFinitePixels, 2u);
  EXPECT_EQ(computeMetrics(b, a).nonFinitePixels, 1u);
}

TEST(MetricNan, NanInIgnoredAlphaDoesNotCount) {
  Image a(2, 2, 4, 0.5f);
  Image b = a;
  b.at(0, 0, 3) = kNan;
  EXPECT_EQ(computeMetrics(a, b).nonFinitePixels, 0u);
}

TEST(MetricErrors, ErrorImageIsMaxChannelError) {
  Image a(3, 2, 3, 0.0f);
  Image b = a;
  b.at(1, 0, 0) = 0.25f;
  b.at(1, 0, 2) = -0.5f;
  b.at(2, 1, 1) = 0.125f;
  const Image e = errorImage(a, b);
  ASSERT_EQ(e.channels, 1);
  EXPECT_EQ(e.at(1, 0), 0.5f);
  EXPECT_EQ(e.at(2, 1), 0.125f);
  EXPECT_EQ(e.at(0, 0), 0.0f);
}

TEST(MetricErrors, ShapeMismatchOrEmptyThrows) {
  EXPECT_THROW(computeMetrics(Image(2, 2, 3), Image(2, 3, 3)), std::invalid_argument);
  EXPECT_THROW(computeMetrics(Image(2, 2, 3), Image(2, 2, 4)), std::invalid_argument);
  EXPECT_THROW(computeMetrics(Image(), Image()), std::invalid_argument);
  EXPECT_THROW(errorImage(Image(1, 1, 3), Image(1, 2, 3)), std::invalid_argument);
}
