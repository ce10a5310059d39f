// Numerical robustness: values at and above the half-float maximum, zero-variance neighbourhoods
// and motion far beyond the screen never put a NaN, an Inf or more than 65504 into the output or
// the history, whatever techniques run.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "support/effects.h"

namespace taa {
namespace {

using test::renderOnce;
using test::report;

constexpr float kHalfMax = 65504.0f;

// Technique combinations, each a taa patch, covering every blend, box and alpha formula.
const std::vector<std::string> kCombos = {
    R"({})",
    R"({"rectify": "none"})",
    R"({"rectify": "clamp", "color_space": "rgb"})",
    R"({"tonemap_weighting": "karis", "variance_clip": true, "shrink_chroma": true})",
    R"({"tonemap_weighting": "inverse_luma", "shaped_neighborhood": true, "reduce_blend_near_clamp": true})",
    R"({"tonemap_weighting": "log", "luma_weight": true, "velocity_alpha": true})",
    R"({"tonemap_weighting": "inverse_luma", "rectify": "none", "history_filter": "catmull_rom_16"})",
    R"({"history_filter": "bspline", "depth_culling": true, "anti_ghosting": true, "variance_clip": true})",
    R"({"consistency": true, "rejection_alpha": 0.5, "tonemap_weighting": "karis"})",
    R"({"mode": "basic", "tonemap_weighting": "inverse_luma"})",
};

void expectBounded(const test::EffectRun& run, const std::string& what) {
  for (const auto& r : run.frames)
    if (r.hasImages) {
      EXPECT_TRUE(test::allFiniteAtMost(r.color, kHalfMax)) << what << ", frame " << r.frame;
    }
}

TEST(EffectRobustness, HdrValuesAtTheHalfMaximumStayFiniteAndBounded) {
  // Intensity 1e5 lights surfaces far beyond 65504 (the raster target stores them as +Inf).
  const char* base = R"({
    "scene": {"builtin": "checkerboard"},
    "lighting": {"intensity": 1e5, "specular": 4},
    "camera": {"strafe": {"speed": 1.0}},
    "movers": [{"shape": "sphere", "start": [-2, 0.6, 2], "end": [2, 0.6, 2], "speed": 4}],
    "render": {"width": 96, "height": 54},
    "script": {"frames": 6}
  })";
  RenderOptions o;
  o.captures |= {Capture::Current};
  const auto& probe = renderOnce(base, "{}", {5}, o);
  int atMax = 0;
  for (float v : test::capturedImage(probe[5], Capture::Current).data) atMax += !(v < kHalfMax);
  report("input channels at or above the half maximum", atMax);
  ASSERT_GT(atMax, 1000);
  for (const auto& combo : kCombos)
    expectBounded(renderOnce(base, R"({"taa": )" + combo + "}", {1, 3, 5}), combo);
}

// A huge, unlit-by-specular cube face fills the view: every 3x3 box is flat (zero variance).
const char* kFlat = R"({
  "scene": {"builtin": "quad"},
  "camera": {"position": [0, 0.5, 6], "target": [0, 0.5, 0]},
  "lighting": {"specular": 0},
  "movers": [{"shape": "cube", "size": 30, "start": [0, 0.5, -14], "end": [0, 0.5, -14], "speed": 0}],
  "render": {"width": 64, "height": 36},
  "script": {"frames": 12}
})";

TEST(EffectRobustness, FlatScenesStayFiniteAndConverge) {
  RenderOptions o;
  o.captures |= {Capture::Current};
  for (const char* combo :
       {R"({"rectify": "clip"})", R"({"rectify": "clip", "variance_clip": true})",
        R"({"rectify": "clip", "color_space": "rgb", "variance_clip": true, "variance_gamma": 0})",
        R"({"luma_weight": true})", R"({"reduce_blend_near_clamp": true})",
        R"({"tonemap_weighting": "inverse_luma", "luma_weight": true})"}) {
    const auto& run = renderOnce(kFlat, R"({"taa": )" + std::string(combo) + "}", {11}, o);
    const Image& cur = test::capturedImage(run[11], Capture::Current);
    EXPECT_TRUE(test::allFiniteAtMost(run[11].color, kHalfMax)) << combo;
    // Flat input: the output is that colour (converged), up to half-float rounding.
    EXPECT_LT(test::maxAbs(run[11].color, cur), 1e-3) << combo;
  }
  // The scene really is flat.
  const auto& run = renderOnce(kFlat, R"({"taa": {"rectify": "clip"}})", {11}, o);
  const Image& cur = test::capturedImage(run[11], Capture::Current);
  double spread = 0.0;
  for (int y = 0; y < cur.height; ++y)
    for (int x = 0; x < cur.width; ++x)
      for (int c = 0; c < 3; ++c)
        spread = std::max(spread, double(std::fabs(cur.at(x, y, c) - cur.at(0, 0, c))));
  report("largest difference between input pixels (flat scene)", spread);
  EXPECT_EQ(spread, 0.0);
}

TEST(EffectRobustness, MotionOfHundredsOfPixelsPerFrameStaysFinite) {
  // Strafing ~33 units per frame back and forth: the nearby ground moves hundreds of pixels
  // per frame and every reprojection lands far off screen.
  const char* fast = R"({
    "scene": {"builtin": "checkerboard"},
    "camera": {"strafe": {"speed": 2000, "distance": 15}},
    "movers": [{"shape": "cube", "start": [-200, 0.5, 2], "end": [200, 0.5, 2], "speed": 20000}],
    "render": {"width": 96, "height": 54},
    "script": {"frames": 6}
  })";
  RenderOptions o;
  o.captures |= {Capture::Velocity};
  const auto& probe = renderOnce(fast, "{}", {5}, o);
  double largest = 0.0;
  for (float v : test::capturedImage(probe[5], Capture::Velocity).data)
    largest = std::max(largest, double(std::fabs(v)));
  report("largest velocity component (px per frame)", largest);
  EXPECT_GT(largest, 500.0);
  for (const auto& combo : kCombos)
    expectBounded(renderOnce(fast, R"({"taa": )" + combo + "}", {1, 3, 5}), combo);
}

}  // namespace
}  // namespace taa
