// The blend factor alpha: the current sample's weight. 1 keeps no history; lower values average
// more jittered samples and land closer to the supersampled reference on a static scene.
#include <gtest/gtest.h>

#include "support/effects.h"

namespace taa {
namespace {

using test::renderOnce;
using test::report;

// A strafing camera, so a history that leaked into the output would show.
const char* kMoving = R"({
  "scene": {"builtin": "checkerboard"},
  "camera": {"strafe": {"speed": 1.5}},
  "render": {"width": 96, "height": 54},
  "script": {"frames": 8}
})";

TEST(EffectAlpha, AlphaOneReproducesTheCurrentFrameExactly) {
  const std::vector<int> all = {0, 1, 2, 3, 4, 5, 6, 7};
  const auto& full = renderOnce(kMoving, R"({"taa": {"alpha": 1.0}})", all);
  const auto& pass = renderOnce(kMoving, R"({"taa": {"mode": "pass_through"}})", all);
  for (int f = 0; f < 8; ++f)
    EXPECT_TRUE(test::rgbIdentical(full[f].color, pass[f].color)) << "frame " << f;
  // alpha 0.5 must not: the comparison sees history when there is some.
  const auto& half = renderOnce(kMoving, R"({"taa": {"alpha": 0.5}})", all);
  EXPECT_GT(test::differing(half[7].color, pass[7].color, 1e-3), 500);
}

// Rectification off, so what the output holds is the plain exponential average of the jittered
// frames (a clip would pull it back toward the current frame).
const char* kAlphaStatic = R"({
  "scene": {"builtin": "checkerboard"},
  "render": {"width": 128, "height": 72},
  "script": {"frames": 48},
  "reference": {"samples": 16},
  "taa": {"rectify": "none"}
})";

TEST(EffectAlpha, LowerAlphaConvergesCloserToTheReferenceOnAStaticScene) {
  // The last 8 frames are one whole Halton cycle; their mean error does not favour a step.
  const std::vector<int> last = {40, 41, 42, 43, 44, 45, 46, 47};
  RenderOptions o;
  o.captures |= {Capture::Reference};
  const auto& a005 = renderOnce(kAlphaStatic, R"({"taa": {"alpha": 0.05}})", last, o);
  const auto& a03 = renderOnce(kAlphaStatic, R"({"taa": {"alpha": 0.3}})", last);
  const auto& a1 = renderOnce(kAlphaStatic, R"({"taa": {"alpha": 1.0}})", last);
  auto meanError = [&](const test::EffectRun& run) {
    double sum = 0.0;
    for (int f : last) sum += test::rmse(run[f].color, a005[f].reference);
    return sum / double(last.size());
  };
  const double e005 = meanError(a005), e03 = meanError(a03), e1 = meanError(a1);
  report("mean rmse vs reference, frames 40-47, alpha 0.05", e005);
  report("mean rmse vs reference, frames 40-47, alpha 0.3", e03);
  report("mean rmse vs reference, frames 40-47, alpha 1", e1);
  EXPECT_LT(e005, 0.8 * e03);
  EXPECT_LT(e03, 0.5 * e1);
}

}  // namespace
}  // namespace taa
