// debug.channels' pass (debug_channels.comp) on a synthetic input whose alpha is not 1: shown
// channels pass through, hidden colour channels read 0 and a hidden alpha reads 1. Every debug
// view the renderer draws today is opaque (alpha 1), so no case can tell a shown alpha from a
// hidden one (still_image_test.cpp's DebugChannels test checks the colour channels on a real
// view); this one can.
#include <gtest/gtest.h>

#include "renderer/post_test_util.h"

namespace taa {
namespace {

using namespace posttest;

constexpr int kDebugChannelsW = 8, kDebugChannelsH = 8;

// RGB and alpha that differ per pixel, alpha in [0.25, 1).
Image translucent() {
  Image in(kDebugChannelsW, kDebugChannelsH, 4, 1.0f);
  for (int y = 0; y < kDebugChannelsH; ++y)
    for (int x = 0; x < kDebugChannelsW; ++x) {
      in.at(x, y, 0) = 0.125f * float(x + 1);
      in.at(x, y, 1) = 0.125f * float(y + 1);
      in.at(x, y, 2) = 0.5f;
      in.at(x, y, 3) = 0.25f + 0.0625f * float((x + 3 * y) % 12);
    }
  return in;
}

Image shownChannels(glm::vec4 shown, const Image& in) {
  PostFilter pass(test::gpu(), "debug_channels.comp", shown);
  return runFilter(pass, in);
}

TEST(DebugChannels, AlphaShownReadsTheInputsAlphaAndHiddenReadsOne) {
  const Image in = roundedToHalf(translucent());
  const Image colour = shownChannels({1.0f, 1.0f, 1.0f, 0.0f}, in);
  const Image alpha = shownChannels({0.0f, 0.0f, 0.0f, 1.0f}, in);
  const Image all = shownChannels({1.0f, 1.0f, 1.0f, 1.0f}, in);
  for (int y = 0; y < kDebugChannelsH; ++y)
    for (int x = 0; x < kDebugChannelsW; ++x) {
      ASSERT_LT(in.at(x, y, 3), 1.0f);
      for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(colour.at(x, y, c), in.at(x, y, c)) << x << "," << y << " channel " << c;
        EXPECT_EQ(alpha.at(x, y, c), 0.0f) << x << "," << y << " channel " << c;
        EXPECT_EQ(all.at(x, y, c), in.at(x, y, c)) << x << "," << y << " channel " << c;
      }
      EXPECT_EQ(colour.at(x, y, 3), 1.0f) << x << "," << y << ": alpha hidden";
      EXPECT_EQ(alpha.at(x, y, 3), in.at(x, y, 3)) << x << "," << y << ": alpha shown";
      EXPECT_EQ(all.at(x, y, 3), in.at(x, y, 3)) << x << "," << y << ": alpha shown";
    }
}

}  // namespace
}  // namespace taa
