// The 5-tap gradient sharpener: the exact formula, the identity on flat input,
// more contrast on a soft edge, a non-negative finite result, NaN confined.
#include <gtest/gtest.h>

#include "passes/sharpen.h"
#include "renderer/post_test_util.h"

namespace taa {
namespace {

using namespace posttest;

// A soft vertical edge from 0.2 to 0.8 over five pixels.
Image softEdge(int w, int h) {
  return grey(w, h, [](int x, int) {
    return 0.2f + 0.6f * std::clamp((float(x) - 14.0f) / 5.0f, 0.0f, 1.0f);
  });
}

TEST(Sharpen, MatchesTheFiveTapFormula) {
  Image in = grey(16, 16, [](int x, int y) { return float((x * 5 + y * 3) % 7) * 0.25f; });
  SharpenPass pass(test::gpu(), 0.6f);
  const Image out = runFilter(pass, in);
  const Image h = roundedToHalf(in);
  for (int y = 1; y < 15; ++y)
    for (int x = 1; x < 15; ++x) {
      const float c = h.at(x, y);
      const float lap = 4 * c - h.at(x, y - 1) - h.at(x, y + 1) - h.at(x - 1, y) - h.at(x + 1, y);
      EXPECT_NEAR(out.at(x, y), halfRound(std::max(0.0f, c + 0.6f * lap / 4)), 2e-3f)
          << x << "," << y;
    }
}

TEST(Sharpen, IsTheIdentityOnAFlatImage) {
  const Image in = grey(24, 12, [](int, int) { return 0.7f; });
  SharpenPass pass(test::gpu(), 1.0f);
  EXPECT_TRUE(sameBits(runFilter(pass, in), roundedToHalf(in)));
}

TEST(Sharpen, RaisesTheContrastOfASoftEdge) {
  const Image in = softEdge(32, 8);
  SharpenPass pass(test::gpu(), 1.0f);
  const Image out = runFilter(pass, in);
  const Image h = roundedToHalf(in);
  EXPECT_GT(maxStepInRow(out, 4), 1.2f * maxStepInRow(h, 4));
  // The edge's feet are pushed apart (the usual over/undershoot of unsharp masking).
  EXPECT_LT(out.at(14, 4), h.at(14, 4));
  EXPECT_GT(out.at(19, 4), h.at(19, 4));
  // Far from the edge nothing moves.
  EXPECT_EQ(out.at(3, 4), h.at(3, 4));
  EXPECT_EQ(out.at(28, 4), h.at(28, 4));
}

TEST(Sharpen, ResultIsNonNegativeAndFinite) {
  Image in = grey(16, 16, [](int, int) { return 0.05f; });
  setPixel(in, 4, 4, 60000.0f);  // a highlight next to dark pixels would undershoot
  SharpenPass pass(test::gpu(), 1.0f);
  const Image out = runFilter(pass, in);
  for (int y = 0; y < 16; ++y)
    for (int x = 0; x < 16; ++x) ASSERT_GE(out.at(x, y), 0.0f) << x << "," << y;
  EXPECT_EQ(out.at(4, 5), 0.0f);
  EXPECT_EQ(nonFiniteOutside(out, {}), 0);
}

// A NaN reads as black and an Inf as the largest half to every tap, the broken
// pixel's own included: the output equals that of the repaired input, bit for bit.
TEST(Sharpen, NaNAndInfCountAsBlackAndHalfMax) {
  Image in = grey(16, 16, [](int x, int y) { return 0.1f + 0.05f * float((x + 2 * y) % 5); });
  Image repaired = in;
  setPixel(in, 10, 10, kNaN);
  setPixel(repaired, 10, 10, 0.0f);
  setPixel(in, 12, 3, kInf);
  setPixel(repaired, 12, 3, 65504.0f);
  SharpenPass pass(test::gpu(), 1.0f);
  const Image out = runFilter(pass, in);
  EXPECT_EQ(nonFiniteOutside(out, {}), 0);
  EXPECT_EQ(differingPixels(out, runFilter(pass, repaired)), 0);
}

TEST(Sharpen, SameInputTwiceGivesIdenticalBytes) {
  const Image in = grey(40, 20, [](int x, int y) { return float((x * 7 + y * 11) % 13) / 4.0f; });
  SharpenPass pass(test::gpu(), 0.35f);
  EXPECT_TRUE(sameBits(runFilter(pass, in), runFilter(pass, in)));
}

}  // namespace
}  // namespace taa
