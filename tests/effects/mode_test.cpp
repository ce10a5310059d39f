// taa.mode: pass_through shows the resolve's input unchanged; basic blends with the same pixel
// of the last output, without reprojection, and so ghosts under camera motion where full does
// not.
#include <gtest/gtest.h>

#include "support/effects.h"

namespace taa {
namespace {

using test::renderOnce;
using test::report;

TEST(EffectPassThrough, OutputIsTheInputBitForBit) {
  const char* moving = R"({
    "scene": {"builtin": "foliage"},
    "camera": {"rotate": {"yaw_deg_per_s": 40}},
    "lighting": {"intensity": 40},
    "render": {"width": 96, "height": 54},
    "script": {"frames": 4},
    "taa": {"mode": "pass_through"}
  })";
  RenderOptions o;
  o.captures |= {Capture::Current};
  const auto& run = renderOnce(moving, "{}", {0, 1, 2, 3}, o);
  for (int f = 0; f < 4; ++f)
    EXPECT_TRUE(sameBits(run[f].color, test::capturedImage(run[f], Capture::Current)))
        << "frame " << f;
}

// A camera panning at ~1 px per frame over the checkerboard.
const char* kModePan = R"({
  "scene": {"builtin": "checkerboard"},
  "camera": {"rotate": {"yaw_deg_per_s": 30}},
  "render": {"width": 160, "height": 90},
  "script": {"frames": 24},
  "reference": {"samples": 16}
})";

TEST(EffectBasic, GhostsUnderCameraMotionFarMoreThanFull) {
  RenderOptions o;
  o.captures |= {Capture::Reference};
  const auto& full = renderOnce(kModePan, "{}", {23}, o);
  const auto& basic = renderOnce(kModePan, R"({"taa": {"mode": "basic"}})", {23});
  const Image& ref = full[23].reference;
  const double eFull = test::rmse(full[23].color, ref), eBasic = test::rmse(basic[23].color, ref);
  report("rmse vs reference under a pan, full", eFull);
  report("rmse vs reference under a pan, basic", eBasic);
  EXPECT_GT(eBasic, 2.5 * eFull);
}

}  // namespace
}  // namespace taa
