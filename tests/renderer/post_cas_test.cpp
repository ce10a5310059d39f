// Contrast Adaptive Sharpening: more local contrast on a blurred edge, never past a
// pixel's 3x3 min/max, the identity on flat input, stronger with sharpness, NaN
// and Inf confined.
#include <gtest/gtest.h>

#include "passes/cas.h"
#include "renderer/post_test_util.h"

namespace taa {
namespace {

using namespace posttest;

// A blurred HDR edge (0.1 to 3.0 over six pixels) with some texture along y, so
// the neighbourhoods are not all alike.
Image blurredEdge() {
  return grey(40, 12, [](int x, int y) {
    const float t = std::clamp((float(x) - 17.0f) / 6.0f, 0.0f, 1.0f);
    return (0.1f + 2.9f * t) * (1.0f + 0.05f * float(y % 3));
  });
}

// The largest relative step between horizontal neighbours in the tonemapped space
// CAS works in.
float maxTonemappedStep(const Image& img, int y) {
  float m = 0.0f;
  for (int x = 0; x + 1 < img.width; ++x) {
    const float a = img.at(x, y) / (1 + img.at(x, y)),
                b = img.at(x + 1, y) / (1 + img.at(x + 1, y));
    m = std::max(m, std::fabs(b - a));
  }
  return m;
}

TEST(Cas, RaisesLocalContrastOnABlurredEdge) {
  const Image in = roundedToHalf(blurredEdge());
  CasPass pass(test::gpu(), 1.0f);
  const Image out = runFilter(pass, in);
  // CAS is deliberately gentle (the lobe is at most -1/5, scaled by the headroom).
  for (int y = 1; y < 11; ++y)
    EXPECT_GT(maxTonemappedStep(out, y), 1.02f * maxTonemappedStep(in, y)) << y;
}

TEST(Cas, StaysWithinEveryPixelsNeighbourhood) {
  // A busy image: ramps, a blurred edge and high-frequency detail.
  const Image in = roundedToHalf(grey(32, 32, [](int x, int y) {
    return 0.02f * float(x) +
           ((x / 3 + y / 2) % 2 ? 4.0f : 0.3f) * (1.0f + 0.1f * float((x * y) % 5));
  }));
  for (float sharpness : {0.0f, 0.5f, 1.0f}) {
    CasPass pass(test::gpu(), sharpness);
    const Image out = runFilter(pass, in);
    int changed = 0;
    for (int y = 0; y < 32; ++y)
      for (int x = 0; x < 32; ++x)
        for (int c = 0; c < 3; ++c) {
          float lo = 1e30f, hi = -1e30f;
          for (int j = -1; j <= 1; ++j)
            for (int i = -1; i <= 1; ++i) {
              const float v = in.at(std::clamp(x + i, 0, 31), std::clamp(y + j, 0, 31), c);
              lo = std::min(lo, v);
              hi = std::max(hi, v);
            }
          ASSERT_GE(out.at(x, y, c), lo) << x << "," << y << " sharpness " << sharpness;
          ASSERT_LE(out.at(x, y, c), hi) << x << "," << y << " sharpness " << sharpness;
          changed += out.at(x, y, c) != in.at(x, y, c);
        }
    EXPECT_GT(changed, 500) << "sharpness " << sharpness;
  }
}

TEST(Cas, IsTheIdentityOnAFlatImage) {
  for (float v : {0.0f, 0.35f, 12.5f}) {
    const Image in = grey(20, 10, [v](int, int) { return v; });
    CasPass pass(test::gpu(), 1.0f);
    EXPECT_TRUE(sameBits(runFilter(pass, in), roundedToHalf(in))) << v;
  }
}

TEST(Cas, SharpnessMovesTheLobeFromAnEighthToAFifth) {
  EXPECT_FLOAT_EQ(casPeak(0.0f), -1.0f / 8.0f);
  EXPECT_FLOAT_EQ(casPeak(1.0f), -1.0f / 5.0f);
  const Image in = roundedToHalf(blurredEdge());
  CasPass soft(test::gpu(), 0.0f), sharp(test::gpu(), 1.0f);
  EXPECT_GT(maxTonemappedStep(runFilter(sharp, in), 5), maxTonemappedStep(runFilter(soft, in), 5));
}

// NaN reads as black and Inf as the largest half, to the neighbours and the pixel
// itself: the output equals that of the repaired input, bit for bit.
TEST(Cas, NonFiniteInputStaysInItsPixel) {
  Image in = blurredEdge();
  Image repaired = in;
  setPixel(in, 19, 5, kNaN);
  setPixel(repaired, 19, 5, 0.0f);
  setPixel(in, 8, 2, kInf);
  setPixel(repaired, 8, 2, 65504.0f);
  CasPass pass(test::gpu(), 1.0f);
  const Image out = runFilter(pass, in);
  EXPECT_EQ(nonFiniteOutside(out, {}), 0);
  EXPECT_EQ(differingPixels(out, runFilter(pass, repaired)), 0);
}

TEST(Cas, SameInputTwiceGivesIdenticalBytes) {
  const Image in = blurredEdge();
  CasPass pass(test::gpu(), 0.4f);
  EXPECT_TRUE(sameBits(runFilter(pass, in), runFilter(pass, in)));
}

}  // namespace
}  // namespace taa
