// FLIP in results.json is computed on exactly the 8-bit images the report shows.
#include "compare/tolerance.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>

#include "compare/flip.h"
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

}  // namespace
}  // namespace taa::compare
