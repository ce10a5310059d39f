// Karis' reduce-blend (blend_weight.glsl) treats a neighbourhood box whose luma half-extent
// is at most 1e-7 as flat (the history counts as on its edge: alpha halves) rather than
// dividing by it. No case puts a box near that bound (the mutation sample found none), so
// synthetic ones sit on each side of it: the current frame's green alternates by one
// half-float step (half-extent 8.5e-8, then 1.7e-7 a binade up), and the history's luma lies
// near the box's middle, a few steps of a smaller red above its low corner. A third box has a
// half-extent of exactly 1e-7 (float), where the test is `>` and not `>=`.
#include <gtest/gtest.h>

#include <cmath>

#include "support/cpu_resolve.h"
#include "support/effects.h"
#include "support/gpu_resolve.h"

namespace taa {
namespace {

constexpr int kFlatBoxSize = 8;
constexpr float kFlatBoxAlpha = 0.5f;

float flatBoxLuma(float r, float g, float b) { return 0.2126f * r + 0.7152f * g + 0.0722f * b; }

struct FlatBoxBlend {
  float alpha;     // the alpha the GPU blended with, from the green channel
  float expected;  // test::cpu::reduceBlendNearClamp on the same lumas
  float halfExtent;
};

// green: the current frame's base green, a power of two (its half-float step is green / 1024);
// steps: how many half-float steps of red (2^-24 at this red) the history's red sits above.
FlatBoxBlend blendWithLumaBox(float green, int steps) {
  const auto spec = test::effectCase(
      R"({"render": {"width": 8, "height": 8}, "script": {"frames": 2}, "jitter": {"pattern": "none"}})",
      R"({"taa": {"alpha": 0.5, "rectify": "clamp", "color_space": "rgb", "history_filter": "bilinear",
                  "reduce_blend_near_clamp": true, "history_format": "rgba32f"}})");
  const float red = std::ldexp(1.5f, -14), step = std::ldexp(1.0f, -24), gStep = green / 1024.0f;
  test::SyntheticResolve in;
  in.current = Image(kFlatBoxSize, kFlatBoxSize, 4, 1.0f);
  in.history = Image(kFlatBoxSize, kFlatBoxSize, 4, 1.0f);
  for (int y = 0; y < kFlatBoxSize; ++y)
    for (int x = 0; x < kFlatBoxSize; ++x) {
      in.current.at(x, y, 0) = red;
      in.current.at(x, y, 1) = green + ((x + y) % 2 ? gStep : 0.0f);
      in.current.at(x, y, 2) = green;
      in.history.at(x, y, 0) = red + float(steps) * step;
      in.history.at(x, y, 1) = green;
      in.history.at(x, y, 2) = green;
    }
  const auto r = test::gpuResolve(spec, in);
  const float lo = flatBoxLuma(red, green, green), hi = flatBoxLuma(red, green + gStep, green);
  const float h = flatBoxLuma(red + float(steps) * step, green, green);
  FlatBoxBlend m{0.0f, test::cpu::reduceBlendNearClamp(kFlatBoxAlpha, h, lo, hi), 0.5f * (hi - lo)};
  // Clamping moves the history's red onto the box, where the current red is; its green
  // stays, one step below the current green of every other pixel: those tell the alpha.
  float sum = 0.0f;
  int n = 0;
  for (int y = 0; y < kFlatBoxSize; ++y)
    for (int x = (y + 1) % 2; x < kFlatBoxSize; x += 2, ++n) {
      const float hg = r.history.at(x, y, 1), cg = r.current.at(x, y, 1);
      sum += (r.output.at(x, y, 1) - hg) / (cg - hg);
    }
  m.alpha = sum / float(n);
  return m;
}

TEST(TaaReduceBlendFlatBox, AHalfExtentAtMost1e7CountsAsFlat) {
  const FlatBoxBlend m = blendWithLumaBox(std::ldexp(1.0f, -12), 7);
  test::report("luma half-extent", m.halfExtent);
  test::report("inferred alpha", m.alpha);
  ASSERT_GT(m.halfExtent, 1e-8f);
  ASSERT_LE(m.halfExtent, 1e-7f);
  EXPECT_FLOAT_EQ(m.expected, 0.5f * kFlatBoxAlpha);
  EXPECT_NEAR(m.alpha, 0.5f * kFlatBoxAlpha, 2e-3f);  // the history inside the box does not count
}

TEST(TaaReduceBlendFlatBox, AWiderBoxWeighsWhereTheHistoryLies) {
  const FlatBoxBlend m = blendWithLumaBox(std::ldexp(1.0f, -11), 13);
  test::report("luma half-extent", m.halfExtent);
  test::report("inferred alpha", m.alpha);
  ASSERT_GT(m.halfExtent, 1e-7f);
  EXPECT_GT(m.expected, 0.9f * kFlatBoxAlpha);  // near the box's middle: close to the full alpha
  EXPECT_NEAR(m.alpha, m.expected, 2e-3f);
}

// A half-extent of exactly 1e-7 (float): a search over min/max boxes of half-float colours found
// none (their lumas lie on grids that step over it), so a variance-clipped box gives it. Red only,
// in the checkerboard 0 / 2^-20 with one tap of each 3x3 window NaN (left out: 8 taps, 4 of each):
// mean and sigma are both 2^-21 exactly, so the box's red is [2^-21 (1 - gamma), 2^-21 fl(1 +
// gamma)] with nothing rounded but 1 + gamma, and its lumas are single products 0.2126 * red,
// exact however the GPU orders the dot product. This gamma makes their half difference 1e-7.
constexpr float kExactFlatGamma = 0.9864309430122375f;

struct ExactFlatBox {
  float halfExtent;  // the box's luma half-extent, computed as blend_weight.glsl does
  float alpha[4];    // the alpha each measured pixel blended with, from the red channel
};

ExactFlatBox blendWithExactFlatBox() {
  const auto spec = test::effectCase(
      R"({"render": {"width": 8, "height": 8}, "script": {"frames": 2}, "jitter": {"pattern": "none"}})",
      R"({"taa": {"alpha": 0.5, "rectify": "clamp", "color_space": "rgb", "history_filter": "bilinear",
                  "variance_clip": true, "variance_gamma": 0.9864309430122375,
                  "reduce_blend_near_clamp": true, "history_format": "rgba32f"}})");
  const float v = std::ldexp(1.0f, -20), mean = 0.5f * v;  // both half floats (subnormal)
  test::SyntheticResolve in;
  in.current = Image(kFlatBoxSize, kFlatBoxSize, 4, 1.0f);
  in.history = Image(kFlatBoxSize, kFlatBoxSize, 4, 1.0f);
  for (int y = 0; y < kFlatBoxSize; ++y)
    for (int x = 0; x < kFlatBoxSize; ++x) {
      // NaN at (3, 3), (7, 3), (3, 7), (7, 7): the windows of (2, 2), (6, 2), (2, 6), (6, 6)
      // each hold one, and those pixels are v with 3 more v and 4 zeros around them.
      const bool nan = x % 4 == 3 && y % 4 == 3;
      in.current.at(x, y, 0) = nan ? std::nanf("") : ((x + y) % 2 ? 0.0f : v);
      in.current.at(x, y, 1) = in.current.at(x, y, 2) = 0.0f;
      in.history.at(x, y, 0) = mean;  // the box's middle: t would be 1
      in.history.at(x, y, 1) = in.history.at(x, y, 2) = 0.0f;
    }
  const auto r = test::gpuResolve(spec, in);
  const float gamma = kExactFlatGamma, sigma = mean;
  const float lo = mean - gamma * sigma, hi = mean + gamma * sigma;
  ExactFlatBox m{0.5f * (0.2126f * hi - 0.2126f * lo), {}};
  const int pixels[4][2] = {{2, 2}, {6, 2}, {2, 6}, {6, 6}};
  for (int i = 0; i < 4; ++i) {
    const int x = pixels[i][0], y = pixels[i][1];
    const float h = r.history.at(x, y, 0), c = r.current.at(x, y, 0);
    m.alpha[i] = (r.output.at(x, y, 0) - h) / (c - h);
  }
  return m;
}

TEST(TaaReduceBlendFlatBox, AHalfExtentOfExactly1e7CountsAsFlat) {
  const ExactFlatBox m = blendWithExactFlatBox();
  test::report("luma half-extent - 1e-7", double(m.halfExtent) - double(1e-7f));
  ASSERT_EQ(m.halfExtent, 1e-7f);  // the arrangement reaches the bound itself
  for (float a : m.alpha) {
    test::report("inferred alpha", a);
    EXPECT_NEAR(a, 0.5f * kFlatBoxAlpha, 1e-3f);  // halved: on the edge of a flat box
  }
}

}  // namespace
}  // namespace taa
