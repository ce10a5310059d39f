// FXAA on synthetic images: an aliased (binary) shallow edge moves toward its
// analytic pixel coverage, flat regions, pixels away from edges and low-contrast
// steps are left bit-exact, and NaN/Inf do not reach the neighbours.
#include <gtest/gtest.h>

#include "passes/fxaa.h"
#include "renderer/post_test_util.h"

namespace taa {
namespace {

using namespace posttest;

constexpr int kPostFxaaW = 64, kPostFxaaH = 32;

// The half-plane below the line y = slope * x + offset (y down) is white.
float lineY(float x) {
  return 0.3f * x + 6.0f;
}

Image aliasedEdge() {
  return grey(kPostFxaaW, kPostFxaaH,
              [](int x, int y) { return float(y) + 0.5f > lineY(float(x) + 0.5f) ? 1.0f : 0.0f; });
}

// Fraction of pixel (x, y) below the line, by 32x32 supersampling.
float coverage(int x, int y) {
  int inside = 0;
  for (int j = 0; j < 32; ++j)
    for (int i = 0; i < 32; ++i)
      inside += float(y) + (float(j) + 0.5f) / 32 > lineY(float(x) + (float(i) + 0.5f) / 32);
  return float(inside) / 1024.0f;
}

float tonemap(float c) {
  return c / (1.0f + c);
}

// Mean distance to the coverage-weighted blend of black and white over the pixels
// the line crosses or touches, in the tonemapped space FXAA blends in.
float edgeError(const Image& img) {
  double sum = 0.0;
  int n = 0;
  for (int y = 0; y < kPostFxaaH; ++y)
    for (int x = 2; x < kPostFxaaW - 2; ++x) {
      const float dist = std::fabs(float(y) + 0.5f - lineY(float(x) + 0.5f));
      if (dist > 2.0f) continue;
      sum += std::fabs(tonemap(img.at(x, y)) - coverage(x, y) * tonemap(1.0f));
      ++n;
    }
  return float(sum / n);
}

TEST(Fxaa, MovesAnAliasedEdgeTowardItsCoverage) {
  const Image in = aliasedEdge();
  FxaaPass pass(test::gpu());
  const Image out = runFilter(pass, in);
  const float before = edgeError(in), after = edgeError(out);
  std::printf("edge error: before %.4f after %.4f\n", before, after);
  EXPECT_LT(after, 0.6f * before);
  // The staircase flattens: along a row, the step at the edge gets smaller.
  float stepBefore = 0.0f, stepAfter = 0.0f;
  for (int x = 4; x < kPostFxaaW - 4; ++x) {
    const int y = int(lineY(float(x) + 0.5f));
    for (int j = y - 1; j <= y + 1; ++j) {
      stepBefore = std::max(stepBefore, std::fabs(in.at(x + 1, j) - in.at(x, j)));
      stepAfter = std::max(stepAfter, std::fabs(out.at(x + 1, j) - out.at(x, j)));
    }
  }
  EXPECT_LT(stepAfter, 0.8f * stepBefore);
}

TEST(Fxaa, LeavesFlatImagesAndPixelsAwayFromEdgesBitExact) {
  const Image flat = grey(16, 16, [](int, int) { return 0.45f; });
  FxaaPass pass(test::gpu());
  EXPECT_TRUE(sameBits(runFilter(pass, flat), roundedToHalf(flat)));

  const Image in = roundedToHalf(aliasedEdge());
  const Image out = runFilter(pass, in);
  int checked = 0;
  for (int y = 1; y < kPostFxaaH - 1; ++y)
    for (int x = 1; x < kPostFxaaW - 1; ++x) {
      bool uniform = true;
      for (int j = -1; j <= 1; ++j)
        for (int i = -1; i <= 1; ++i) uniform &= in.at(x + i, y + j) == in.at(x, y);
      if (!uniform) continue;
      ++checked;
      for (int c = 0; c < 4; ++c)
        ASSERT_TRUE(sameBits(out.at(x, y, c), in.at(x, y, c))) << x << "," << y;
    }
  EXPECT_GT(checked, 1000);
}

TEST(Fxaa, LeavesStepsBelowTheContrastThresholdAlone) {
  const Image in =
      roundedToHalf(grey(32, 16, [](int x, int y) { return x + y / 2 < 20 ? 0.50f : 0.53f; }));
  FxaaPass pass(test::gpu());
  EXPECT_TRUE(sameBits(runFilter(pass, in), in));
}

// To its neighbours a NaN reads as black and an Inf as the largest half: they come
// out exactly as next to the repaired pixel. The broken pixels themselves may pass
// through unchanged (FXAA copies pixels it does not filter).
TEST(Fxaa, NonFiniteInputDoesNotReachTheNeighbours) {
  Image in = aliasedEdge();
  Image repaired = in;
  const int nx = 20, ny = int(lineY(20.5f));  // on the edge
  setPixel(in, nx, ny, kNaN);
  setPixel(repaired, nx, ny, 0.0f);
  setPixel(in, 40, 5, kInf);
  setPixel(repaired, 40, 5, 65504.0f);
  FxaaPass pass(test::gpu());
  const Image out = runFilter(pass, in);
  EXPECT_EQ(nonFiniteOutside(out, {{nx, ny}, {40, 5}}), 0);
  EXPECT_EQ(differingPixels(out, runFilter(pass, repaired), {{nx, ny}, {40, 5}}), 0);
}

TEST(Fxaa, SameInputTwiceGivesIdenticalBytes) {
  const Image in = aliasedEdge();
  FxaaPass pass(test::gpu());
  EXPECT_TRUE(sameBits(runFilter(pass, in), runFilter(pass, in)));
}

}  // namespace
}  // namespace taa
