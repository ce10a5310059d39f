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

// The linear grey whose edge luma is `l`: l^2 = y / (1 + y).
float greyForLuma(float l) {
  return l * l / (1.0f - l * l);
}

uint32_t bitsAt(const std::vector<uint32_t>& mask, int w, int x, int y) {
  return mask[size_t(y * w + x)];
}

TEST(TscmaaEdgeCpu, ThresholdDecidesWhetherAStepIsAnEdge) {
  const float t = 1.0f / 22.0f;
  for (const float step : {t * 0.8f, t * 1.2f}) {
    const Image img =
        grey(16, 8, [&](int x, int) { return greyForLuma(x < 8 ? 0.4f : 0.4f + step); });
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

// A weak horizontal step (left half) meets a strong vertical edge: with removal the
// weak edge's last piece, which touches the strong edge, drops out; its other pieces,
// which touch only equals, stay.
TEST(TscmaaEdgeCpu, NonDominantRemovalDropsWeakEdgesTouchingStrongOnes) {
  const Image img = grey(16, 16, [](int x, int y) {
    return x >= 8 ? greyForLuma(0.95f) : greyForLuma(y < 8 ? 0.30f : 0.37f);
  });
  const auto kept = test::tscmaaEdgeMask(img, knobs(1.0f / 22.0f, 0.0f, 0.0f));
  const auto removed = test::tscmaaEdgeMask(img, knobs(1.0f / 22.0f, 0.5f, 0.0f));
  EXPECT_TRUE(bitsAt(kept, 16, 7, 7) & TSCMAA_EDGE_BOTTOM);
  EXPECT_FALSE(bitsAt(removed, 16, 7, 7) & TSCMAA_EDGE_BOTTOM);
  EXPECT_FALSE(bitsAt(removed, 16, 7, 8) & TSCMAA_EDGE_TOP);
  for (int x = 0; x < 7; ++x) {
    EXPECT_TRUE(bitsAt(removed, 16, x, 7) & TSCMAA_EDGE_BOTTOM) << x;
    EXPECT_TRUE(bitsAt(removed, 16, x, 8) & TSCMAA_EDGE_TOP) << x;
  }
  // The strong edge dominates and stays whole.
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
       {std::pair{1.0f / 22.0f, 0.5f}, std::pair{1.0f / 32.0f, 0.0f}, std::pair{0.1f, 2.0f}}) {
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
