#include "compare/heatmap.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <limits>
#include <stdexcept>

#include "compare/flip.h"
#include "core/image_io.h"

using taa::Image;
using taa::compare::crop;
using taa::compare::heatmap;
using taa::compare::magma;
using taa::compare::upscaleNearest;
using taa::compare::worstRegion;

namespace {

double relativeLuminance(const std::array<float, 3>& srgb) {
  auto lin = [](double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); };
  return 0.2126 * lin(srgb[0]) + 0.7152 * lin(srgb[1]) + 0.0722 * lin(srgb[2]);
}

Image indexed(int w, int h, int c) {
  Image img(w, h, c);
  for (size_t i = 0; i < img.data.size(); ++i) img.data[i] = float(i);
  return img;
}

}  // namespace

TEST(DiffColourMap, LuminanceRisesStrictlyAndEndsMatchMagma) {
  double previous = -1.0;
  for (int i = 0; i <= 1000; ++i) {
    const double y = relativeLuminance(magma(float(i) / 1000.0f));
    ASSERT_GT(y, previous) << i;
    previous = y;
  }
  EXPECT_FLOAT_EQ(magma(0.0f)[2], 0.013866f);
  EXPECT_FLOAT_EQ(magma(1.0f)[1], 0.991438f);
  EXPECT_EQ(magma(-3.0f), magma(0.0f));
  EXPECT_EQ(magma(7.0f), magma(1.0f));
  EXPECT_EQ(magma(std::numeric_limits<float>::quiet_NaN()), taa::compare::kHeatmapNanColour);
}

TEST(DiffHeatmap, ScalesByMaxErrorAndMarksNan) {
  Image e(4, 1, 1);
  e.data = {0.0f, 0.05f, 0.2f, std::numeric_limits<float>::quiet_NaN()};
  const Image h = heatmap(e, 0.1f);
  ASSERT_EQ(h.channels, 3);
  EXPECT_EQ(h.at(0, 0, 0), magma(0.0f)[0]);
  EXPECT_EQ(h.at(1, 0, 1), magma(0.5f)[1]);
  EXPECT_EQ(h.at(2, 0, 2), magma(1.0f)[2]);  // clamped
  EXPECT_EQ(h.at(3, 0, 1), 1.0f);            // NaN -> green
  EXPECT_EQ(h.at(3, 0, 0), 0.0f);
  Image inf(1, 1, 1, std::numeric_limits<float>::infinity());
  EXPECT_EQ(heatmap(inf).at(0, 0, 1), magma(1.0f)[1]);
  EXPECT_THROW(heatmap(e, 0.0f), std::invalid_argument);
}

TEST(DiffCrop, CopiesTheRectangleAndRejectsOutside) {
  const Image img = indexed(5, 4, 2);
  const Image c = crop(img, 1, 2, 3, 2);
  ASSERT_EQ(c.width, 3);
  ASSERT_EQ(c.height, 2);
  ASSERT_EQ(c.channels, 2);
  for (int y = 0; y < 2; ++y)
    for (int x = 0; x < 3; ++x)
      for (int ch = 0; ch < 2; ++ch) EXPECT_EQ(c.at(x, y, ch), img.at(x + 1, y + 2, ch));
  EXPECT_EQ(crop(img, 0, 0, 5, 4).data, img.data);
  EXPECT_THROW(crop(img, 3, 0, 3, 1), std::out_of_range);
  EXPECT_THROW(crop(img, -1, 0, 1, 1), std::out_of_range);
  EXPECT_THROW(crop(img, 0, 0, 0, 1), std::out_of_range);
}

TEST(DiffUpscale, RepeatsPixels) {
  const Image img = indexed(2, 2, 1);
  const Image u = upscaleNearest(img, 3);
  ASSERT_EQ(u.width, 6);
  ASSERT_EQ(u.height, 6);
  EXPECT_EQ(u.at(2, 2), 0.0f);
  EXPECT_EQ(u.at(3, 0), 1.0f);
  EXPECT_EQ(u.at(0, 5), 2.0f);
  EXPECT_EQ(u.at(5, 5), 3.0f);
  EXPECT_EQ(upscaleNearest(img, 1).data, img.data);
  EXPECT_THROW(upscaleNearest(img, 0), std::invalid_argument);
}

TEST(DiffWorstRegion, FindsPlantedBlock) {
  Image e(64, 40, 1, 0.01f);
  for (int y = 23; y < 31; ++y)
    for (int x = 37; x < 45; ++x) e.at(x, y) = 0.9f;
  const auto r = worstRegion(e, 8, 8);
  EXPECT_EQ(r.x, 37);
  EXPECT_EQ(r.y, 23);
  EXPECT_NEAR(r.sum, 64 * 0.9, 1e-4);
  // A larger window still covers the block; ties go to the smallest y, then x.
  const auto big = worstRegion(e, 12, 12);
  EXPECT_EQ(big.x, 33);
  EXPECT_EQ(big.y, 19);
}

TEST(DiffWorstRegion, TiesBreakToSmallestYThenX) {
  Image e(10, 10, 1, 0.1f);  // every window has the same sum
  auto r = worstRegion(e, 3, 3);
  EXPECT_EQ(r.x, 0);
  EXPECT_EQ(r.y, 0);
  // Two equal blocks: the upper one wins even though it is further right.
  Image two(20, 20, 1, 0.0f);
  two.at(15, 2) = 1.0f;
  two.at(1, 9) = 1.0f;
  r = worstRegion(two, 1, 1);
  EXPECT_EQ(r.x, 15);
  EXPECT_EQ(r.y, 2);
  two.at(4, 2) = 1.0f;  // same row: smaller x wins
  r = worstRegion(two, 1, 1);
  EXPECT_EQ(r.x, 4);
  EXPECT_EQ(r.y, 2);
}

TEST(DiffWorstRegion, ClampsWindowAndHandlesNonFinite) {
  Image e(5, 3, 1, 0.0f);
  e.at(4, 2) = std::numeric_limits<float>::quiet_NaN();
  const auto r = worstRegion(e, 2, 2);
  EXPECT_EQ(r.x, 3);
  EXPECT_EQ(r.y, 1);
  const auto all = worstRegion(e, 50, 50);
  EXPECT_EQ(all.width, 5);
  EXPECT_EQ(all.height, 3);
  EXPECT_EQ(all.x, 0);
  EXPECT_THROW(worstRegion(e, 0, 2), std::invalid_argument);
  EXPECT_THROW(worstRegion(Image(), 1, 1), std::invalid_argument);
}

TEST(DiffReport, HeatmapAndZoomedCropWriteAsPng) {
  // End to end: error map -> worst region -> zoomed crops of both frames and the heatmap.
  Image ref(32, 24, 4, 0.2f);
  Image test = ref;
  for (int y = 10; y < 14; ++y)
    for (int x = 20; x < 24; ++x) test.at(x, y, 0) = 3.0f;
  const auto flip = taa::compare::flipLdrFromHdr(ref, test);
  const auto worst = worstRegion(flip.errorMap, 8, 8);
  EXPECT_GE(worst.x, 16);
  EXPECT_LE(worst.x, 20);
  EXPECT_GE(worst.y, 6);
  EXPECT_LE(worst.y, 10);
  const auto dir = std::filesystem::path(TAA_TEST_OUT) / "diff_report";
  std::filesystem::create_directories(dir);
  const Image zoomed = upscaleNearest(crop(heatmap(flip.errorMap), worst.x, worst.y, 8, 8), 4);
  taa::writePngLinear8(dir / "heat.png", zoomed);
  taa::writePng(dir / "test.png", upscaleNearest(crop(test, worst.x, worst.y, 8, 8), 4));
  const Image back = taa::readImage(dir / "heat.png");
  EXPECT_EQ(back.width, 32);
  EXPECT_EQ(back.height, 32);
}
