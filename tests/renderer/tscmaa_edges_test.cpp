// TSCMAA edge detection: the CPU reference's rules on crafted patterns, and the GPU
// mask and list headers against the reference.
#include <gtest/gtest.h>

#include <cmath>

#include "renderer/post_test_util.h"
#include "renderer/tscmaa_test_util.h"
#include "support/cpu_tscmaa.h"

namespace taa {
namespace {

using posttest::grey;
using posttest::roundedToHalf;

spec::TscmaaSpec knobs(float threshold, float removal, float share = 0.5f) {
  spec::TscmaaSpec t;
  t.edge_threshold = threshold;
  t.non_dominant_edge_removal = removal;
  t.taa_share = share;
  return t;
}

// The linear grey displayed as `l`: edge detection encodes sqrt(c / (1 + c)), so c = l^2 / (1 -
// l^2); the luma weights sum to 1, so a grey step's difference is the step itself.
float greyShownAs(float l) {
  return l * l / (1.0f - l * l);
}

uint32_t bitsAt(const std::vector<uint32_t>& mask, int w, int x, int y) {
  return mask[size_t(y * w + x)];
}

TEST(TscmaaEdgeCpu, ThresholdDecidesWhetherAStepIsAnEdge) {
  const float t = 1.0f / 22.0f;
  for (const float step : {t * 0.8f, t * 1.2f}) {
    const Image img =
        grey(16, 8, [&](int x, int) { return greyShownAs(x < 8 ? 0.4f : 0.4f + step); });
    const auto mask = test::tscmaaEdgeMask(img, knobs(t, 0.5f, 0.0f));
    const bool edge = step > t;
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 16; ++x) {
        const uint32_t expected = !edge    ? 0u
                                  : x == 7 ? TSCMAA_EDGE_RIGHT
                                  : x == 8 ? TSCMAA_EDGE_LEFT
                                           : 0u;
        ASSERT_EQ(bitsAt(mask, 16, x, y), expected) << "step " << step << " at " << x << "," << y;
      }
  }
}

// CMAA's edge value: the excess of the luma-weighted difference of display-encoded
// colours over the threshold, in fifteenths rounded up (by its +0.99), at most 15.
TEST(TscmaaEdgeCpu, EdgeValueIsTheExcessOverTheThresholdInFifteenths) {
  const float t = 1.0f / 22.0f;
  auto value = [&](float a, float b) {  // two greys, given as displayed
    const float ca[3] = {std::sqrt(a * a), std::sqrt(a * a), std::sqrt(a * a)};
    const float cb[3] = {std::sqrt(b * b), std::sqrt(b * b), std::sqrt(b * b)};
    return test::tscmaaEdgeValue(ca, cb, t);
  };
  EXPECT_EQ(value(0.5f, 0.5f + 0.9f * t), 0);
  EXPECT_EQ(value(0.2f, 0.2f + t + 0.003f), 1);
  EXPECT_EQ(value(0.2f, 0.2f + t + 1.5f / 15.0f), 2);
  EXPECT_EQ(value(0.0f, 1.0f), 15);
  // Colour as displayed (Reinhard, as the PNGs): HDR highlights keep the difference the display
  // shows between them, which a clip to 1 would lose; NaN is black, +Inf the brightest value.
  const float hdrA[3] = {test::tscmaaEdgeChannel(2.0f), test::tscmaaEdgeChannel(2.0f),
                         test::tscmaaEdgeChannel(2.0f)};
  const float hdrB[3] = {test::tscmaaEdgeChannel(50.0f), test::tscmaaEdgeChannel(50.0f),
                         test::tscmaaEdgeChannel(50.0f)};
  EXPECT_EQ(test::tscmaaEdgeValue(hdrA, hdrB, t), 2);  // 0.816 against 0.990
  EXPECT_EQ(test::tscmaaEdgeChannel(std::nanf("")), 0.0f);
  EXPECT_GT(test::tscmaaEdgeChannel(INFINITY), 0.9999f);
  // Per-channel differences with Rec. 709 weights: a pure blue step is weak, green strong.
  const float black[3] = {0.0f, 0.0f, 0.0f}, blue[3] = {0.0f, 0.0f, 0.5f},
              green[3] = {0.0f, 0.5f, 0.0f};
  EXPECT_EQ(test::tscmaaEdgeValue(black, blue, t), 0);
  EXPECT_GT(test::tscmaaEdgeValue(black, green, t), 4);
}

// CMAA's rule on the twelve values of an owner pixel (the judged edge first): the edge
// must reach mean + removal x (max - mean).
TEST(TscmaaEdgeCpu, RemovalMixesTheNeighbourhoodsMeanAndMaximum) {
  const int weakBesideStrong[12] = {1, 10, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  EXPECT_TRUE(test::tscmaaEdgeKept(weakBesideStrong, 0.0f));  // 1 >= mean 11/12
  EXPECT_FALSE(test::tscmaaEdgeKept(weakBesideStrong, 0.5f));
  const int even[12] = {5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5, 5};
  for (const float removal : {0.0f, 0.5f, 1.0f}) EXPECT_TRUE(test::tscmaaEdgeKept(even, removal));
  const int belowMean[12] = {1, 8, 8, 8, 0, 0, 0, 0, 0, 0, 0, 0};
  EXPECT_FALSE(test::tscmaaEdgeKept(belowMean, 0.0f));  // 1 < mean 25/12
  const int secondStrongest[12] = {9, 10, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  EXPECT_TRUE(test::tscmaaEdgeKept(secondStrongest, 0.8f));
  EXPECT_FALSE(test::tscmaaEdgeKept(secondStrongest, 1.0f));  // at 1 only the strongest stay
  const int none[12] = {0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
  EXPECT_FALSE(test::tscmaaEdgeKept(none, 0.0f));
}

// A weak horizontal step (left half) meets a strong vertical edge: with removal the
// weak edge's pieces within reach of the strong edge drop out; its other pieces, which
// touch only equals, stay, and the strong edge stays whole.
TEST(TscmaaEdgeCpu, NonDominantRemovalDropsWeakEdgesTouchingStrongOnes) {
  const Image img = grey(16, 16, [](int x, int y) {
    return x >= 8 ? greyShownAs(0.95f) : greyShownAs(y < 8 ? 0.30f : 0.37f);
  });
  const auto removed = test::tscmaaEdgeMask(img, knobs(1.0f / 22.0f, 0.5f, 0.0f));
  for (int x = 6; x < 8; ++x) {
    EXPECT_FALSE(bitsAt(removed, 16, x, 7) & TSCMAA_EDGE_BOTTOM) << x;
    EXPECT_FALSE(bitsAt(removed, 16, x, 8) & TSCMAA_EDGE_TOP) << x;
  }
  for (int x = 0; x < 6; ++x) {
    EXPECT_TRUE(bitsAt(removed, 16, x, 7) & TSCMAA_EDGE_BOTTOM) << x;
    EXPECT_TRUE(bitsAt(removed, 16, x, 8) & TSCMAA_EDGE_TOP) << x;
  }
  for (int y = 0; y < 16; ++y) EXPECT_TRUE(bitsAt(removed, 16, 7, y) & TSCMAA_EDGE_RIGHT) << y;
}

TEST(TscmaaEdgeCpu, EveryEdgeIsSeenAlikeFromBothSides) {
  const Image img = roundedToHalf(tscmaatest::blockNoise(40, 30, 7));
  const auto mask = test::tscmaaEdgeMask(img, knobs(1.0f / 22.0f, 0.5f));
  int edges = 0;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      const uint32_t m = bitsAt(mask, 40, x, y);
      edges += (m & TSCMAA_EDGES) != 0u;
      const uint32_t right = x + 1 < 40 ? bitsAt(mask, 40, x + 1, y) : 0u;
      const uint32_t below = y + 1 < 30 ? bitsAt(mask, 40, x, y + 1) : 0u;
      EXPECT_EQ(bool(m & TSCMAA_EDGE_RIGHT), bool(right & TSCMAA_EDGE_LEFT)) << x << "," << y;
      EXPECT_EQ(bool(m & TSCMAA_EDGE_BOTTOM), bool(below & TSCMAA_EDGE_TOP)) << x << "," << y;
    }
  EXPECT_GT(edges, 100);
}

TEST(TscmaaEdgeCpu, TaaShareSelectsThatShareOfEdgePixels) {
  const Image img = roundedToHalf(tscmaatest::blockNoise(64, 64, 3));
  for (const float share : {0.0f, 0.25f, 0.5f, 1.0f}) {
    const auto mask = test::tscmaaEdgeMask(img, knobs(0.01f, 0.0f, share));
    int edges = 0, taa = 0;
    for (const uint32_t m : mask) {
      edges += (m & TSCMAA_EDGES) != 0u;
      taa += (m & TSCMAA_TAA) != 0u;
      ASSERT_FALSE((m & TSCMAA_TAA) && !(m & TSCMAA_EDGES));
    }
    ASSERT_GT(edges, 1000);
    EXPECT_NEAR(double(taa) / edges, share, 0.03) << share;
  }
}

TEST(TscmaaEdgeGpu, MaskMatchesCpuReferenceBitForBit) {
  Image img =
      roundedToHalf(tscmaatest::blockNoise(67, 45, 11));  // not a multiple of the 8x8 groups
  posttest::setPixel(img, 10, 10, posttest::kNaN);
  posttest::setPixel(img, 30, 20, posttest::kInf);
  for (const auto& [threshold, removal] :
       {std::pair{1.0f / 22.0f, 0.5f}, std::pair{1.0f / 32.0f, 0.0f}, std::pair{0.1f, 1.0f}}) {
    const auto spec =
        tscmaatest::tscmaaCase("\"edge_threshold\": " + std::to_string(threshold) +
                                   ", \"non_dominant_edge_removal\": " + std::to_string(removal),
                               "", 67, 45);
    const auto gpu = tscmaatest::runSynthetic(spec, img);
    const auto cpu = test::tscmaaEdgeMask(img, spec.tscmaa);
    ASSERT_EQ(gpu.mask.size(), cpu.size());
    int mismatches = 0;
    uint32_t edges = 0, taa = 0;
    for (size_t i = 0; i < cpu.size(); ++i) {
      mismatches += gpu.mask[i] != cpu[i];
      edges += (cpu[i] & TSCMAA_EDGES) != 0u;
      taa += (cpu[i] & TSCMAA_TAA) != 0u;
    }
    EXPECT_EQ(mismatches, 0) << "threshold " << threshold << " removal " << removal;
    EXPECT_EQ(gpu.counts.edges.count, edges);
    EXPECT_EQ(gpu.counts.taa.count, taa);
    EXPECT_GT(edges, 50u);
  }
}

// The indirect arguments the edge pass leaves are the group counts of its lists.
TEST(TscmaaEdgeGpu, DispatchedGroupsFollowTheEdgeCount) {
  const Image img = roundedToHalf(tscmaatest::blockNoise(96, 64, 5));
  uint32_t previous = ~0u;
  for (const float threshold : {0.01f, 0.05f, 0.2f, 0.5f}) {
    const auto spec =
        tscmaatest::tscmaaCase("\"edge_threshold\": " + std::to_string(threshold), "", 96, 64);
    const auto r = tscmaatest::runSynthetic(spec, img);
    for (const auto& h : {r.counts.edges, r.counts.taa}) {
      EXPECT_EQ(h.groupsX, tscmaatest::groupsFor(h.count)) << threshold;
      EXPECT_EQ(h.groupsY, 1u);
      EXPECT_EQ(h.groupsZ, 1u);
    }
    EXPECT_LT(r.counts.edges.count, previous) << "threshold " << threshold;
    EXPECT_LE(r.counts.taa.count, r.counts.edges.count);
    previous = r.counts.edges.count;
  }
}

}  // namespace
}  // namespace taa
