#include <gtest/gtest.h>

#include <cmath>

#include "scene/textures.h"

namespace taa::scene {
namespace {

std::vector<uint8_t> grey(int w, int h, uint8_t v, uint8_t a = 255) {
  std::vector<uint8_t> px(size_t(w) * size_t(h) * 4, v);
  for (size_t i = 3; i < px.size(); i += 4) px[i] = a;
  return px;
}

uint8_t at(const Texture::Level& l, int x, int y, int c) {
  return l.rgba[(size_t(y) * size_t(l.width) + size_t(x)) * 4 + size_t(c)];
}

uint64_t fnv1a(const std::vector<uint8_t>& bytes) {
  uint64_t h = 1469598103934665603ull;
  for (uint8_t b : bytes) h = (h ^ b) * 1099511628211ull;
  return h;
}

TEST(TextureMips, ChainSizesHalveDownToOne) {
  const Texture t = makeTexture(7, 3, grey(7, 3, 0));
  ASSERT_EQ(t.levels.size(), 3u);
  EXPECT_EQ(t.levels[1].width, 3);
  EXPECT_EQ(t.levels[1].height, 1);
  EXPECT_EQ(t.levels[2].width, 1);
  EXPECT_EQ(t.levels[2].height, 1);
  EXPECT_EQ(makeTexture(256, 256, grey(256, 256, 0)).levels.size(), 9u);
  EXPECT_EQ(makeTexture(1, 1, grey(1, 1, 0)).levels.size(), 1u);
  const Texture tall = makeTexture(1, 5, grey(1, 5, 0));
  ASSERT_EQ(tall.levels.size(), 3u);
  EXPECT_EQ(tall.levels[1].height, 2);
  for (const auto& l : t.levels) EXPECT_EQ(l.rgba.size(), size_t(l.width) * size_t(l.height) * 4);
}

TEST(TextureMips, EvenBoxAveragesColourInLinearLight) {
  // Black and white checker: the mean is 0.5 linear, which is sRGB 188, not 128.
  std::vector<uint8_t> px = {0, 0, 0, 0, 255, 255, 255, 255, 255, 255, 255, 255, 0, 0, 0, 255};
  const Texture t = makeTexture(2, 2, px);
  ASSERT_EQ(t.levels.size(), 2u);
  EXPECT_EQ(at(t.levels[1], 0, 0, 0), 188);
  EXPECT_EQ(at(t.levels[1], 0, 0, 0), linearToSrgb8(0.5));
  EXPECT_EQ(at(t.levels[1], 0, 0, 3), 191);  // alpha stays linear: (0 + 3 * 255) / 4 = 191.25
}

TEST(TextureMips, OddWidthUsesAreaWeights) {
  // 5 -> 2: texel 0 covers source 0, 1 and half of 2; texel 1 the other half of 2, 3, 4.
  std::vector<uint8_t> px = grey(5, 1, 0);
  const uint8_t alpha[] = {0, 100, 200, 50, 255};
  const uint8_t red[] = {0, 255, 255, 0, 255};
  for (int i = 0; i < 5; ++i) {
    px[size_t(i) * 4 + 3] = alpha[i];
    px[size_t(i) * 4] = red[i];
  }
  const Texture t = makeTexture(5, 1, px);
  ASSERT_EQ(t.levels[1].width, 2);
  EXPECT_EQ(at(t.levels[1], 0, 0, 3), 80);   // (0 + 100 + 0.5 * 200) / 2.5
  EXPECT_EQ(at(t.levels[1], 1, 0, 3), 162);  // (0.5 * 200 + 50 + 255) / 2.5
  EXPECT_EQ(at(t.levels[1], 0, 0, 0), linearToSrgb8(1.5 / 2.5));
  EXPECT_EQ(at(t.levels[1], 1, 0, 0), linearToSrgb8(1.5 / 2.5));
  // The last level averages everything: (0+100+200+50+255) / 5 = 121.
  EXPECT_EQ(at(t.levels.back(), 0, 0, 3), 121);
}

TEST(TextureMips, ThreeByThreeIsTheMeanOfNine) {
  std::vector<uint8_t> px = grey(3, 3, 0);
  double sum = 0.0;
  for (int i = 0; i < 9; ++i) {
    const uint8_t v = uint8_t(i * 30);
    px[size_t(i) * 4 + 1] = v;
    px[size_t(i) * 4 + 3] = v;
    sum += srgb8ToLinear(v);
  }
  const Texture t = makeTexture(3, 3, px);
  ASSERT_EQ(t.levels.size(), 2u);
  EXPECT_EQ(at(t.levels[1], 0, 0, 1), linearToSrgb8(sum / 9.0));
  EXPECT_EQ(at(t.levels[1], 0, 0, 3), 120);  // 30 * (0 + ... + 8) / 9
}

TEST(TextureMips, ConstantTextureStaysConstant) {
  const Texture t = makeTexture(13, 7, grey(13, 7, 77, 201));
  for (const auto& l : t.levels)
    for (size_t i = 0; i < l.rgba.size(); ++i)
      ASSERT_EQ(l.rgba[i], i % 4 == 3 ? 201 : 77) << l.width;
}

TEST(TextureSrgb, EightBitCodesRoundTrip) {
  for (int c = 0; c < 256; ++c) EXPECT_EQ(linearToSrgb8(srgb8ToLinear(uint8_t(c))), c);
  EXPECT_NEAR(srgbToLinear(linearToSrgb(0.25)), 0.25, 1e-12);
}

TEST(TextureProcedural, DeterministicAcrossCalls) {
  const Texture a = leafTexture(64, 3), b = leafTexture(64, 3);
  ASSERT_EQ(a.levels.size(), b.levels.size());
  for (size_t i = 0; i < a.levels.size(); ++i) EXPECT_EQ(a.levels[i].rgba, b.levels[i].rgba);
  EXPECT_EQ(roughNoiseTexture(64, 9).levels[0].rgba, roughNoiseTexture(64, 9).levels[0].rgba);
  EXPECT_NE(roughNoiseTexture(64, 9).levels[0].rgba, roughNoiseTexture(64, 10).levels[0].rgba);
}

TEST(TextureProcedural, LevelZeroFingerprintsAreStable) {
  // Level 0 uses only IEEE +-*/ and sqrt, so these hold on every platform; a change here
  // changes every golden image of the scenes that use the texture.
  EXPECT_EQ(hash32(0u), 0u);
  EXPECT_EQ(hash32(1u), 1753845952u);
  EXPECT_EQ(fnv1a(leafTexture(128, 1).levels[0].rgba), 13225270515458747229ull);
  EXPECT_EQ(fnv1a(roughNoiseTexture(128, 1).levels[0].rgba), 15432722317858618180ull);
  EXPECT_EQ(fnv1a(groundTexture(64, 1, {40, 70, 30, 255}, {100, 130, 60, 255}).levels[0].rgba),
            15569952261428903685ull);
  EXPECT_EQ(fnv1a(woodTexture(64, 1).levels[0].rgba), 9488667545536139887ull);
}

TEST(TextureProcedural, LeafIsACutOut) {
  const Texture t = leafTexture(128, 1);
  EXPECT_TRUE(hasTranslucentTexels(t));
  size_t opaque = 0, total = 0;
  const auto& px = t.levels[0].rgba;
  for (size_t i = 3; i < px.size(); i += 4, ++total) {
    ASSERT_TRUE(px[i] == 0 || px[i] == 255) << "alpha must be binary at level 0";
    opaque += px[i] == 255;
  }
  const double coverage = double(opaque) / double(total);
  EXPECT_GT(coverage, 0.15);
  EXPECT_LT(coverage, 0.7);
  // Transparent texels carry leaf colour, so mips do not fringe towards black.
  EXPECT_GT(px[1], 80);
}

double lumaStdDev(const Texture& t) {
  const auto& px = t.levels[0].rgba;
  double sum = 0.0, sum2 = 0.0;
  const double n = double(px.size() / 4);
  for (size_t i = 0; i < px.size(); i += 4) {
    const double y = 0.2126 * px[i] + 0.7152 * px[i + 1] + 0.0722 * px[i + 2];
    sum += y;
    sum2 += y * y;
  }
  return std::sqrt(sum2 / n - (sum / n) * (sum / n));
}

TEST(TextureProcedural, RoughNoiseHasHighVariance) {
  const double rough = lumaStdDev(roughNoiseTexture(128, 5));
  const double ground = lumaStdDev(groundTexture(128, 5, {40, 70, 30, 255}, {100, 130, 60, 255}));
  EXPECT_GT(rough, 50.0);
  EXPECT_LT(ground, 20.0);
  EXPECT_FALSE(hasTranslucentTexels(roughNoiseTexture(32, 5)));
}

}  // namespace
}  // namespace taa::scene
