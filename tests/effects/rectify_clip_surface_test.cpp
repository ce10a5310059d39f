// Clipping (rectify.glsl's clipToBox) leaves a history that lies on the widened box's surface,
// m exactly 1, as it is: `m > 1` clips, `m >= 1` would return center + offset / 1, which need
// not be h in float arithmetic. Here the history's red is exactly one widened half-extent right
// of the centre (m = 1 from red alone), and its green, 2^-24 beside a centre of 2, does not
// survive the round trip: 2^-24 - 2 rounds to -2, and 2 + -2 is 0. No case puts a history on
// the surface (the mutation sample's `m >= 1` changed no frame), so synthetic inputs do.
#include <gtest/gtest.h>

#include <cmath>

#include "support/effects.h"
#include "support/gpu_resolve.h"

namespace taa {
namespace {

constexpr int kClipSurfaceSize = 8;

TEST(TaaClipSurface, AHistoryOnTheWidenedBoxIsKeptBitForBit) {
  const auto spec = test::effectCase(
      R"({"render": {"width": 8, "height": 8}, "script": {"frames": 2}, "jitter": {"pattern": "none"}})",
      R"({"taa": {"alpha": 0.5, "rectify": "clip", "color_space": "rgb", "history_filter": "bilinear",
                  "history_format": "rgba32f"}})");
  // Every 3x3 window of the checkerboard holds both colours: box lo (0, 0, 0), hi (1, 4, 0),
  // centre (0.5, 2, 0). Its largest bound is 4, so each half-extent widens by 4 / 1024 = 2^-8:
  // red 0.5 + 2^-8, green 2 + 2^-8, blue 2^-8, all exact.
  const float tiny = std::ldexp(1.0f, -24);       // the smallest half float
  const float red = 1.0f + std::ldexp(1.0f, -8);  // centre 0.5 plus the widened half-extent
  test::SyntheticResolve in;
  in.current = Image(kClipSurfaceSize, kClipSurfaceSize, 4, 1.0f);
  in.history = Image(kClipSurfaceSize, kClipSurfaceSize, 4, 1.0f);
  for (int y = 0; y < kClipSurfaceSize; ++y)
    for (int x = 0; x < kClipSurfaceSize; ++x) {
      const bool bright = (x + y) % 2 != 0;
      in.current.at(x, y, 0) = bright ? 1.0f : 0.0f;
      in.current.at(x, y, 1) = bright ? 4.0f : 0.0f;
      in.current.at(x, y, 2) = 0.0f;
      in.history.at(x, y, 0) = red;
      in.history.at(x, y, 1) = tiny;
      in.history.at(x, y, 2) = 0.0f;
    }
  const auto r = test::gpuResolve(spec, in);
  int checked = 0;
  for (int y = 0; y < kClipSurfaceSize; ++y)
    for (int x = 0; x < kClipSurfaceSize; ++x) {
      ASSERT_EQ(r.history.at(x, y, 0), red);
      ASSERT_EQ(r.history.at(x, y, 1), tiny);
      if ((x + y) % 2 != 0) continue;  // 2 + 2^-25 is 2 in float: the dark pixels tell
      // The history kept (not clipped) and blended half-half with a current of 0.
      EXPECT_EQ(r.output.at(x, y, 0), 0.5f * red) << x << "," << y;
      EXPECT_EQ(r.output.at(x, y, 1), 0.5f * tiny) << x << "," << y << ": the history's green";
      ++checked;
    }
  EXPECT_EQ(checked, kClipSurfaceSize * kClipSurfaceSize / 2);
}

}  // namespace
}  // namespace taa
