// The fast float FLIP (flip.cpp) against the previous double implementation (flip_double.cpp),
// its independence from the thread count, and its math helpers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "compare/flip.h"
#include "compare/flip_double.h"
#include "compare/flip_math.h"
#include "support/noise.h"

using taa::Image;
using taa::compare::flipLdr;
using taa::compare::flipLdrDouble;
using taa::compare::FlipOptions;
using taa::test::hashUnit;

namespace {

// A frame-like picture: smooth colour gradients, hard-edged blocks and thin lines, so colour,
// edge and point terms all matter.
Image scene(int w, int h, uint32_t seed) {
  Image img(w, h, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const bool block = ((x / 13) + (y / 9)) % 3 == 0;
      const bool line = x % 17 == int(seed % 17) || y % 23 == 5;
      for (int c = 0; c < 3; ++c) {
        float v = 0.15f + 0.6f * float(x + c * 7) / float(w) * float(y + 3) / float(h);
        if (block) v = 0.2f + 0.6f * hashUnit(seed, x / 13, y / 9, c);
        if (line) v = c == 1 ? 0.95f : 0.05f;
        img.at(x, y, c) = v;
      }
    }
  return img;
}

// The test side: a shifted, re-noised, partly recoloured version of the reference.
Image altered(const Image& ref, uint32_t seed, float noise) {
  Image out = ref;
  for (int y = 0; y < ref.height; ++y)
    for (int x = 0; x < ref.width; ++x)
      for (int c = 0; c < 3; ++c) {
        const int sx = std::min(x + (y > ref.height / 2 ? 1 : 0), ref.width - 1);
        float v = ref.at(sx, y, c) + noise * (hashUnit(seed, x, y, c) - 0.5f);
        if (x > ref.width * 2 / 3 && y < ref.height / 3 && c == 0) v *= 0.7f;
        out.at(x, y, c) = std::clamp(v, 0.0f, 1.0f);
      }
  return out;
}

void expectCloseToDouble(const Image& a, const Image& b, const FlipOptions& options = {}) {
  const auto fast = flipLdr(a, b, options);
  const auto slow = flipLdrDouble(a, b, options);
  EXPECT_NEAR(fast.mean, slow.mean, 1e-4);
  float worst = 0.0f;
  for (size_t i = 0; i < fast.errorMap.data.size(); ++i)
    worst = std::max(worst, std::fabs(fast.errorMap.data[i] - slow.errorMap.data[i]));
  EXPECT_LE(worst, 1e-3f);
  EXPECT_NEAR(fast.p99, slow.p99, 1e-3);
  EXPECT_NEAR(fast.max, slow.max, 1e-3);
}

}  // namespace

TEST(FlipFast, MatchesDoubleImplementationOnFrameSizedPairs) {
  for (uint32_t seed : {1u, 2u, 3u}) {
    const Image ref = scene(320, 180, seed);
    expectCloseToDouble(ref, altered(ref, seed, 0.02f * float(seed)));
  }
}

TEST(FlipFast, MatchesDoubleImplementationOnOddShapesAndViewingDistances) {
  const Image ref = scene(97, 61, 5);
  const Image test = altered(ref, 5, 0.1f);
  FlipOptions near;
  near.pixelsPerDegree = 12.0;  // small kernels
  FlipOptions far;
  far.pixelsPerDegree = 140.0;  // kernels wider than the image is tall
  expectCloseToDouble(ref, test);
  expectCloseToDouble(ref, test, near);
  expectCloseToDouble(ref, test, far);
  expectCloseToDouble(scene(3, 40, 7), altered(scene(3, 40, 7), 7, 0.2f));
  expectCloseToDouble(scene(40, 2, 8), altered(scene(40, 2, 8), 8, 0.2f));
}

TEST(FlipFast, BitIdenticalForEveryThreadCount) {
  // Tall enough for many strips at every count, so strip borders land on different rows.
  const Image ref = scene(150, 333, 11);
  const Image test = altered(ref, 11, 0.08f);
  FlipOptions one;
  one.threads = 1;
  const auto base = flipLdr(ref, test, one);
  ASSERT_GT(base.mean, 0.0);
  for (int threads : {2, 3, 4, 7, 16}) {
    FlipOptions o;
    o.threads = threads;
    const auto r = flipLdr(ref, test, o);
    EXPECT_EQ(r.errorMap.data, base.errorMap.data) << threads << " threads";
    EXPECT_EQ(r.mean, base.mean) << threads << " threads";
    EXPECT_EQ(r.p99, base.p99) << threads << " threads";
  }
}

TEST(FlipMath, HelpersMatchLibm) {
  using namespace taa::compare::flipmath;
  for (float x = 0.008f; x < 1.2f; x *= 1.013f) {
    EXPECT_NEAR(cbrtPositive(x), std::cbrt(double(x)), 3e-7 * std::cbrt(double(x))) << x;
  }
  // pow goes through y = e * log2(x) in float, so its relative error grows with |y| (one float
  // rounding of y is |y| * 6e-8); FLIP's powers have |y| below 12.
  for (float x = 1e-30f; x < 1e6f; x *= 1.7f) {
    const double l2 = std::log2(double(x));
    EXPECT_NEAR(log2Positive(x), l2, 2e-7 + 1e-7 * std::fabs(l2)) << x;
    for (float e : {0.0f, 0.013f, 0.5f, 0.7f, 1.0f, 2.4f}) {
      const double y = l2 * double(e);
      const double want = std::pow(double(x), double(e));
      if (std::fabs(y) < 120.0) {
        EXPECT_NEAR(powPositive(x, e), want, (5e-7 + 1e-7 * std::fabs(y)) * want) << x << "^" << e;
      }
    }
  }
  for (float y = -120.0f; y < 120.0f; y += 0.37f) {
    EXPECT_NEAR(exp2Bounded(y), std::exp2(double(y)), 5e-7 * std::exp2(double(y))) << y;
  }
  EXPECT_EQ(exp2Bounded(0.0f), 1.0f);
}
