// Motion blur on synthetic inputs: static pixels are copied bit for bit, a moving
// step edge becomes the box-filtered ramp of the motion's length, the speed lands
// in alpha when asked, nearer surfaces do not bleed into slower background, and
// NaN/Inf stay in their own pixel.
#include <gtest/gtest.h>

#include "passes/motion_blur.h"
#include "renderer/post_test_util.h"

namespace taa {
namespace {

using namespace posttest;

constexpr int kPostMotionBlurW = 64, kPostMotionBlurH = 16, kPostMotionBlurEdge = 32;

struct Inputs {
  Image color = grey(kPostMotionBlurW, kPostMotionBlurH, [](int x, int) { return x < kPostMotionBlurEdge ? 0.0f : 1.0f; });
  Image velocity = Image(kPostMotionBlurW, kPostMotionBlurH, 2, 0.0f);
  Image depth = Image(kPostMotionBlurW, kPostMotionBlurH, 1, 0.5f);
};

// Rows [0, kPostMotionBlurH/2) move by `v` (render pixels); the rest is static.
Inputs movingTopHalf(glm::vec2 v) {
  Inputs in;
  for (int y = 0; y < kPostMotionBlurH / 2; ++y)
    for (int x = 0; x < kPostMotionBlurW; ++x) {
      in.velocity.at(x, y, 0) = v.x;
      in.velocity.at(x, y, 1) = v.y;
    }
  return in;
}

Image blur(const MotionBlurSettings& s, const Inputs& in) {
  MotionBlurPass pass(test::gpu(), s);
  auto color = test::uploadFloatImage(in.color, VK_FORMAT_R16G16B16A16_SFLOAT, "color");
  auto velocity = test::uploadFloatImage(in.velocity, VK_FORMAT_R16G16_SFLOAT, "velocity");
  auto depth = test::uploadFloatImage(in.depth, VK_FORMAT_R32_SFLOAT, "depth");
  auto out = makePostImage(test::gpu(), "blurred", {kPostMotionBlurW, kPostMotionBlurH});
  VkCommandBuffer cmd = test::gpu().beginCommands();
  pass.record(cmd, color, velocity, depth, out, {kPostMotionBlurW, kPostMotionBlurH});
  test::gpu().submitAndWait(cmd);
  return test::downloadImage(out);
}

TEST(MotionBlur, StaticPixelsAreCopiedBitForBit) {
  Inputs in = movingTopHalf({8.0f, 0.0f});
  // Values that need every mantissa bit of a half: any averaging would show.
  for (int y = kPostMotionBlurH / 2; y < kPostMotionBlurH; ++y)
    for (int x = 0; x < kPostMotionBlurW; ++x) setPixel(in.color, x, y, halfRound(0.1f + 0.37f * float(x ^ y)));
  const Image out = blur({16, 1.0f, false}, in);
  const Image expected = roundedToHalf(in.color);
  for (int y = kPostMotionBlurH / 2; y < kPostMotionBlurH; ++y)
    for (int x = 0; x < kPostMotionBlurW; ++x)
      for (int c = 0; c < 4; ++c)
        ASSERT_TRUE(sameBits(out.at(x, y, c), expected.at(x, y, c))) << x << "," << y;
}

TEST(MotionBlur, MovingStepEdgeBecomesARampOfTheMotionLength) {
  const float length = 8.0f;
  const Image out = blur({16, 1.0f, false}, movingTopHalf({length, 0.0f}));
  for (int y = 0; y < kPostMotionBlurH / 2; ++y) {
    int ramp = 0;
    for (int x = 0; x < kPostMotionBlurW; ++x) {
      // A centred box of `length` pixels over the step: the fraction of it past the edge.
      const float analytic =
          std::clamp((float(x) + 0.5f - float(kPostMotionBlurEdge) + length / 2) / length, 0.0f, 1.0f);
      EXPECT_NEAR(out.at(x, y, 0), analytic, 1.0f / 16 + 1e-3f) << x;
      if (x > 0) {
        EXPECT_GE(out.at(x, y, 0), out.at(x - 1, y, 0));
      }
      ramp += out.at(x, y, 0) > 0.0f && out.at(x, y, 0) < 1.0f;
      EXPECT_EQ(out.at(x, y, 3), 1.0f);
    }
    EXPECT_EQ(ramp, int(length)) << "row " << y;
  }
  // The static half keeps its hard step.
  EXPECT_EQ(out.at(kPostMotionBlurEdge - 1, kPostMotionBlurH - 1, 0), 0.0f);
  EXPECT_EQ(out.at(kPostMotionBlurEdge, kPostMotionBlurH - 1, 0), 1.0f);
}

TEST(MotionBlur, ScaleShortensTheRampAndVerticalMotionLeavesAVerticalEdgeAlone) {
  const Image half = blur({16, 0.5f, false}, movingTopHalf({8.0f, 0.0f}));
  int ramp = 0;
  for (int x = 0; x < kPostMotionBlurW; ++x) ramp += half.at(x, 0, 0) > 0.0f && half.at(x, 0, 0) < 1.0f;
  EXPECT_EQ(ramp, 4);
  // Motion along the edge samples the same column: nothing changes.
  const Image along = blur({16, 1.0f, false}, movingTopHalf({0.0f, 6.0f}));
  EXPECT_EQ(along.at(kPostMotionBlurEdge - 1, 2, 0), 0.0f);
  EXPECT_EQ(along.at(kPostMotionBlurEdge, 2, 0), 1.0f);
}

TEST(MotionBlur, VelocityInAlphaHoldsTheUnscaledSpeedInRenderPixels) {
  const Image out = blur({8, 0.5f, true}, movingTopHalf({3.0f, -4.0f}));
  for (int x = 0; x < kPostMotionBlurW; x += 7) {
    EXPECT_FLOAT_EQ(out.at(x, 0, 3), 5.0f) << x;
    EXPECT_EQ(out.at(x, kPostMotionBlurH - 1, 3), 0.0f) << x;
  }
}

TEST(MotionBlur, NearerSurfacesDoNotBleedIntoTheBlurOfFartherOnes) {
  // Right of the edge a near (reversed Z 0.9) white surface, left a far black one;
  // everything moves by 8 px.
  Inputs in = movingTopHalf({8.0f, 0.0f});
  for (int y = 0; y < kPostMotionBlurH; ++y)
    for (int x = kPostMotionBlurEdge; x < kPostMotionBlurW; ++x) in.depth.at(x, y) = 0.9f;
  const Image out = blur({16, 1.0f, false}, in);
  // The far side stays black; the near side's blur still takes in the far side.
  for (int x = 0; x < kPostMotionBlurEdge; ++x) EXPECT_EQ(out.at(x, 0, 0), 0.0f) << x;
  EXPECT_LT(out.at(kPostMotionBlurEdge, 0, 0), 1.0f);
  EXPECT_GT(out.at(kPostMotionBlurEdge, 0, 0), 0.0f);
}

// The near limit's epsilon (1e-7 past centreDepth * (1 + tolerance)) keeps a tap of the centre's
// own depth when the tolerance is 0, and a tap of the far plane (reversed Z 0) at any tolerance:
// without it every tap of a surface of one depth would drop out, the centre included, and the
// pixel would keep its unblurred colour. (Cases run the default tolerance over the depth of real
// surfaces, where the epsilon is lost in the product; the sky has no velocity.)
TEST(MotionBlur, TapsOfTheCentresOwnDepthCountAtZeroToleranceAndOnTheFarPlane) {
  for (const float depth : {0.5f, 0.0f}) {
    Inputs in = movingTopHalf({8.0f, 0.0f});
    in.depth = Image(kPostMotionBlurW, kPostMotionBlurH, 1, depth);
    const Image out = blur({16, 1.0f, false, depth == 0.0f ? 0.05f : 0.0f}, in);
    int ramp = 0;
    for (int x = 0; x < kPostMotionBlurW; ++x) ramp += out.at(x, 0, 0) > 0.0f && out.at(x, 0, 0) < 1.0f;
    EXPECT_EQ(ramp, 8) << "depth " << depth << ": the step edge blurs into a ramp";
  }
}

TEST(MotionBlur, NonFiniteColourOrVelocityStaysInItsPixel) {
  Inputs in = movingTopHalf({6.0f, 0.0f});
  setPixel(in.color, 10, 2, kNaN);
  setPixel(in.color, 40, 4, kInf);
  in.velocity.at(20, 3, 0) = kNaN;
  in.velocity.at(50, 5, 1) = kInf;
  const Image out = blur({8, 1.0f, true}, in);
  EXPECT_EQ(nonFiniteOutside(out, {}), 0);
  // The pixels next to the broken ones average only finite taps.
  EXPECT_EQ(out.at(11, 2, 0), 0.0f);
  EXPECT_EQ(out.at(39, 4, 0), 1.0f);
  // A broken motion vector counts as no motion.
  EXPECT_EQ(out.at(20, 3, 3), 0.0f);
  EXPECT_EQ(out.at(20, 3, 0), 0.0f);
}

TEST(MotionBlur, SameInputTwiceGivesIdenticalBytes) {
  Inputs in = movingTopHalf({5.3f, 1.7f});
  for (int y = 0; y < kPostMotionBlurH; ++y)
    for (int x = 0; x < kPostMotionBlurW; ++x) in.color.at(x, y, 1) = float((x * 7 + y * 13) % 11) / 7.0f;
  EXPECT_TRUE(sameBits(blur({12, 0.8f, true}, in), blur({12, 0.8f, true}, in)));
}

}  // namespace
}  // namespace taa
