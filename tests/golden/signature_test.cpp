// Frame signatures: blind to low bits and HDR outliers, not to a visible local change.
#include "golden/signature.h"

#include <gtest/gtest.h>

namespace taa::golden {
namespace {

Image gradient(int w, int h) {
  Image img(w, h, 4);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c)
        img.at(x, y, c) = 0.1f + 0.8f * float(x + c * y) / float(w + 3 * h);
  return img;
}

TEST(FrameSignature, IdenticalFramesAreAtDistanceZero) {
  const auto s = frameSignature(gradient(160, 90));
  EXPECT_EQ(s.size(), 140u);
  const auto d = signatureDistance(s, frameSignature(gradient(160, 90)));
  EXPECT_TRUE(d.valid);
  EXPECT_EQ(d.cell, 0);
  EXPECT_EQ(d.mean, 0.0);
}

TEST(FrameSignature, LowBitNoiseAndAnHdrOutlierStayWithinTolerance) {
  Image other = gradient(160, 90);
  // What another CPU feature level does: the last bits of every value, and a highlight pixel
  // that keeps another jittered sample (1000 against 30000).
  for (size_t i = 0; i < other.data.size(); ++i) other.data[i] *= i % 2 ? 1.0005f : 0.9995f;
  Image golden = gradient(160, 90);
  golden.at(40, 40, 0) = 30000.0f;
  other.at(40, 40, 0) = 1000.0f;
  const auto d = signatureDistance(frameSignature(golden), frameSignature(other));
  EXPECT_TRUE(d.valid);
  EXPECT_LE(d.cell, 1);
  EXPECT_LE(d.mean, 1.0 / 255);
}

TEST(FrameSignature, AGhostInOneCellIsOutOfToleranceAndLocated) {
  const Image golden = gradient(160, 90);
  Image ghost = golden;
  // A 12 x 8 pixel smear in the cell at row 2, column 5 (cells are 20 x 11.25 pixels).
  for (int y = 24; y < 32; ++y)
    for (int x = 104; x < 116; ++x)
      for (int c = 0; c < 3; ++c) ghost.at(x, y, c) = 1.0f;
  const auto d = signatureDistance(frameSignature(golden), frameSignature(ghost));
  EXPECT_GT(d.cell, kSignatureCellTolerance);
  EXPECT_EQ(d.cellIndex, 2 * kSignatureGrid + 5);
}

TEST(FrameSignature, AColourShiftMovesTheChannelMeans) {
  const Image golden = gradient(160, 90);
  Image shifted = golden;
  for (int y = 0; y < 90; ++y)
    for (int x = 0; x < 160; ++x) shifted.at(x, y, 2) *= 1.05f;  // 5% more blue everywhere
  const auto d = signatureDistance(frameSignature(golden), frameSignature(shifted));
  EXPECT_GT(d.mean, kSignatureMeanTolerance);
}

TEST(FrameSignature, FramesSmallerThanTheGridAndMalformedStrings) {
  const auto tiny = frameSignature(Image(3, 1, 4, 0.5f));
  EXPECT_EQ(tiny.size(), 140u);
  EXPECT_TRUE(signatureDistance(tiny, tiny).valid);
  EXPECT_FALSE(signatureDistance(tiny, "00").valid);
  std::string bad = tiny;
  bad[7] = 'x';
  EXPECT_FALSE(signatureDistance(tiny, bad).valid);
}

}  // namespace
}  // namespace taa::golden
