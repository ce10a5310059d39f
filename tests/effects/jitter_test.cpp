// Sample acquisition: the jitter sequence moves the rasterised image by its offset, gathers
// sub-pixel coverage the reference also averages, and its lock / slowdown switches pin or hold
// the step.
#include <gtest/gtest.h>

#include <cmath>

#include "support/effects.h"

namespace taa {
namespace {

using test::renderOnce;
using test::report;

// A static checkerboard with boxes: many edges that only sub-pixel samples resolve.
const char* kJitterStatic = R"({
  "scene": {"builtin": "checkerboard"},
  "render": {"width": 128, "height": 72},
  "script": {"frames": 24},
  "reference": {"samples": 16}
})";

TEST(EffectJitter, HaltonConvergesCloserToTheReferenceThanNoJitter) {
  RenderOptions o;
  o.captures |= {Capture::Reference};
  const auto& halton = renderOnce(kJitterStatic, R"({"jitter": {"pattern": "halton"}})", {23}, o);
  const auto& none = renderOnce(kJitterStatic, R"({"jitter": {"pattern": "none"}})", {23});
  const Image& ref = halton[23].reference;  // static scene: the same truth for both runs
  const double eHalton = test::rmse(halton[23].color, ref), eNone = test::rmse(none[23].color, ref);
  report("rmse vs reference, halton x8, frame 23", eHalton);
  report("rmse vs reference, no jitter, frame 23", eNone);
  EXPECT_LT(eHalton, 0.6 * eNone);
}

// The quad's left edge against the sky, seen head-on: a vertical edge at a fractional pixel
// position, where +-0.5 px of jitter moves coverage by exactly one column.
const char* kQuad = R"({
  "scene": {"builtin": "quad"},
  "camera": {"position": [0, 0, 1.5], "target": [0, 0, 0]},
  "render": {"width": 96, "height": 54},
  "script": {"frames": 1},
  "taa": {"mode": "pass_through"}
})";

// First column showing the quad in row y, or -1.
int edgeColumn(const Image& ids, int y) {
  for (int x = 0; x < ids.width; ++x)
    if (ids.at(x, y, 0) >= 0.0f) return x;
  return -1;
}

TEST(EffectJitter, ManualHalfPixelOffsetsShiftAVerticalEdgeByOnePixel) {
  RenderOptions o;
  o.captures |= {Capture::Ids};
  const auto& right =
      renderOnce(kQuad, R"({"jitter": {"pattern": "manual", "points": [[0.5, 0]]}})", {0}, o);
  const auto& left =
      renderOnce(kQuad, R"({"jitter": {"pattern": "manual", "points": [[-0.5, 0]]}})", {0}, o);
  const Image& idsR = test::capturedImage(right[0], Capture::Ids);
  const Image& idsL = test::capturedImage(left[0], Capture::Ids);
  int rows = 0;
  for (int y = 0; y < idsR.height; ++y) {
    const int r = edgeColumn(idsR, y), l = edgeColumn(idsL, y);
    if (r < 0 && l < 0) continue;
    ++rows;
    // The image moves by the jitter (shaders/common/shared.h): +x moves it right.
    EXPECT_EQ(r, l + 1) << "row " << y;
  }
  EXPECT_GT(rows, 20);
  // The whole output moved, not just the ids: the right-jittered image one column to the
  // left is the left-jittered one (up to interpolation rounding).
  const Image& a = right[0].color;
  const Image& b = left[0].color;
  double shifted = 0.0, unshifted = 0.0;
  for (int y = 0; y < a.height; ++y)
    for (int x = 0; x + 1 < a.width; ++x)
      for (int c = 0; c < 3; ++c) {
        shifted += std::fabs(a.at(x + 1, y, c) - b.at(x, y, c));
        unshifted += std::fabs(a.at(x, y, c) - b.at(x, y, c));
      }
  report("sum |right(x+1) - left(x)|", shifted);
  report("sum |right(x) - left(x)|", unshifted);
  EXPECT_LT(shifted, 0.01 * unshifted);
}

const char* kRaw = R"({
  "scene": {"builtin": "checkerboard"},
  "render": {"width": 96, "height": 54},
  "script": {"frames": 9},
  "taa": {"mode": "pass_through"},
  "jitter": {"pattern": "halton", "length": 8}
})";

const std::vector<int> kJitterAll = {0, 1, 2, 3, 4, 5, 6, 7, 8};

RenderOptions currentJitter() {
  RenderOptions o;
  o.captures |= {Capture::Current};
  return o;
}

const Image& raw(const test::EffectRun& run, int f) {
  return test::capturedImage(run[f], Capture::Current);
}

TEST(EffectJitter, LockPinsOneStepOfTheSequence) {
  const auto& free = renderOnce(kRaw, "{}", kJitterAll, currentJitter());
  const auto& locked = renderOnce(kRaw, R"({"jitter": {"lock": 3}})", kJitterAll, currentJitter());
  for (int f = 0; f < 9; ++f) {
    EXPECT_TRUE(sameBits(raw(locked, f), raw(free, 3))) << "frame " << f;
    if (f > 0) {
      EXPECT_FALSE(sameBits(raw(free, f), raw(free, f - 1))) << "frame " << f;
    }
  }
}

TEST(EffectJitter, SlowdownHoldsEachStepForKFrames) {
  const auto& free = renderOnce(kRaw, "{}", kJitterAll, currentJitter());
  const auto& slow = renderOnce(kRaw, R"({"jitter": {"slowdown": 3}})", kJitterAll, currentJitter());
  for (int f = 0; f < 9; ++f)
    EXPECT_TRUE(sameBits(raw(slow, f), raw(free, f / 3))) << "frame " << f;
  EXPECT_FALSE(sameBits(raw(slow, 2), raw(slow, 3)));
}

}  // namespace
}  // namespace taa
