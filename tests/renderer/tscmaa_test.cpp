// TSCMAA end to end: TAA touches only its share of the edge pixels, the knobs move the
// output the way they should, and the result does not depend on lavapipe's threads.
#include <gtest/gtest.h>

#include <regex>

#include "renderer/post_test_util.h"
#include "renderer/tscmaa_test_util.h"
#include "support/process.h"

namespace taa {
namespace {

using tscmaatest::aux;
using tscmaatest::counter;

// A strafing camera over the fence: history moves, many thin edges.
const char* kTscmaaMoving = R"("scene": {"builtin": "fence"}, "script": {"frames": 6},
  "camera": {"strafe": {"speed": 0.6, "distance": 0.4}})";

RenderOptions captures() {
  RenderOptions o;
  o.captures |= {Capture::Cmaa, Capture::EdgeMask};
  return o;
}

uint32_t bits(const Image& mask, int x, int y) {
  return uint32_t(mask.at(x, y));
}

TEST(TscmaaGpu, PixelsOutsideTheTaaShareEqualTheCmaaOutput) {
  const auto frames = tscmaatest::renderAll(tscmaatest::tscmaaCase("", kTscmaaMoving), captures());
  int taaChanged = 0;
  for (const auto& r : frames) {
    const Image &mask = aux(r, "tscmaa_mask"), &cmaa = aux(r, "cmaa");
    for (int y = 0; y < mask.height; ++y)
      for (int x = 0; x < mask.width; ++x) {
        if (bits(mask, x, y) & TSCMAA_TAA)
          taaChanged += !sameRgbBits(r.color, cmaa, x, y);
        else
          ASSERT_TRUE(sameRgbBits(r.color, cmaa, x, y))
              << "frame " << r.frame << " at " << x << "," << y;
      }
  }
  EXPECT_GT(taaChanged, 100);  // and TAA does act where it may
}

TEST(TscmaaGpu, TaaShareZeroGivesTheCmaaImage) {
  for (const auto& r :
       tscmaatest::renderAll(tscmaatest::tscmaaCase(R"("taa_share": 0)", kTscmaaMoving), captures())) {
    EXPECT_EQ(counter(r, "tscmaa_taa_pixels"), 0.0);
    EXPECT_TRUE(sameBits(r.color, aux(r, "cmaa"))) << r.frame;
  }
}

TEST(TscmaaGpu, HistoryWeightChangesOnlyTaaPixels) {
  const auto a = tscmaatest::renderAll(tscmaatest::tscmaaCase(R"("history_weight": 0.8)", kTscmaaMoving),
                                       captures());
  const auto b = tscmaatest::renderAll(tscmaatest::tscmaaCase(R"("history_weight": 0.3)", kTscmaaMoving),
                                       captures());
  int differing = 0;
  for (size_t f = 0; f < a.size(); ++f) {
    const Image& mask = aux(a[f], "tscmaa_mask");
    for (int y = 0; y < mask.height; ++y)
      for (int x = 0; x < mask.width; ++x) {
        if (sameRgbBits(a[f].color, b[f].color, x, y)) continue;
        ++differing;
        ASSERT_TRUE(bits(mask, x, y) & TSCMAA_TAA) << "frame " << f << " at " << x << "," << y;
      }
  }
  EXPECT_GT(differing, 100);
}

double edgesWith(const std::string& knobs) {
  const auto frames = tscmaatest::renderAll(tscmaatest::tscmaaCase(knobs, kTscmaaMoving));
  return counter(frames.back(), "tscmaa_edges");
}

TEST(TscmaaGpu, HigherThresholdFindsFewerEdges) {
  const double low = edgesWith(R"("edge_threshold": 0.03)"),
               mid = edgesWith(R"("edge_threshold": 0.1)"),
               high = edgesWith(R"("edge_threshold": 0.3)");
  EXPECT_GT(low, mid);
  EXPECT_GT(mid, high);
}

TEST(TscmaaGpu, StrongerNonDominantRemovalFindsFewerEdges) {
  const double none = edgesWith(R"("non_dominant_edge_removal": 0)"),
               some = edgesWith(R"("non_dominant_edge_removal": 0.5)"),
               most = edgesWith(R"("non_dominant_edge_removal": 3)");
  EXPECT_GT(none, some);
  EXPECT_GT(some, most);
}

std::vector<std::string> tscmaaHashes(const std::string& env) {
  const std::string out =
      std::string(TAA_TEST_OUT) + "/tscmaa-determinism-" + env.substr(env.find('=') + 1);
  const auto r = test::runHarness(
      std::string("render ") + TAA_SOURCE_DIR + "/cases/tscmaa_fence.json --out " + out, env);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  // Each list holds one index per pixel of the 320x180 frame after its 16-byte header:
  // 230,416 bytes, no more (the log reports what the case allocates).
  EXPECT_NE(r.output.find("buffer tscmaa lists 2x1 (225 KiB each)"), std::string::npos) << r.output;
  std::vector<std::string> found;
  const std::regex line("frame \\d+ sha256 ([0-9a-f]{64})");
  for (std::sregex_iterator it(r.output.begin(), r.output.end(), line), end; it != end; ++it)
    found.push_back((*it)[1]);
  return found;
}

// The edge lists fill in thread-scheduling order; nothing may depend on that order.
TEST(TscmaaGpu, OneAndTwoLavapipeThreadsGiveIdenticalFrames) {
  const auto one = tscmaaHashes("LP_NUM_THREADS=1");
  const auto two = tscmaaHashes("LP_NUM_THREADS=2");
  ASSERT_FALSE(one.empty());
  EXPECT_EQ(one, two);
}

}  // namespace
}  // namespace taa
