// Dynamic alpha: Lottes' luma weighting picks alpha per pixel within [alpha_min, alpha_max];
// velocity-driven alpha trusts the current frame where things move fast; Karis' reduce-blend
// leans on the history where it is about to be clamped, against flicker.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/effects.h"
#include "support/gpu_resolve.h"
#include "support/noise.h"

namespace taa {
namespace {

using test::renderOnce;
using test::report;

// The alpha each pixel used, inferred from a 2-frame synthetic resolve without rectification
// and without motion: out = h + alpha (c - h) per channel. Channels whose current and history
// differ by less than 0.05 say little and are skipped.
std::vector<float> inferredAlphas(const std::string& taa) {
  const auto spec =
      test::effectCase(R"({"render": {"width": 48, "height": 32}, "script": {"frames": 2},
      "jitter": {"pattern": "none"}})",
                       R"({"taa": )" + taa + "}");
  test::SyntheticResolve in;
  in.current = Image(48, 32, 4, 1.0f);
  in.history = Image(48, 32, 4, 1.0f);
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 48; ++x) {
      // Each row pair spans a different luma ratio, from equal to very different.
      const float level = 0.1f + 2.0f * test::hashUnit(3, x, y);
      for (int c = 0; c < 3; ++c) {
        in.current.at(x, y, c) = level * (0.8f + 0.4f * test::hashUnit(4, x, y, c));
        in.history.at(x, y, c) =
            level * (0.05f + 3.0f * float(y) / 32.0f) * (0.8f + 0.4f * test::hashUnit(5, x, y, c));
      }
    }
  const auto r = test::gpuResolve(spec, in);
  std::vector<float> alphas;
  for (int y = 0; y < 32; ++y)
    for (int x = 0; x < 48; ++x)
      for (int c = 0; c < 3; ++c) {
        const float h = r.history.at(x, y, c), cur = r.current.at(x, y, c),
                    out = r.output.at(x, y, c);
        if (std::fabs(cur - h) > 0.05f) alphas.push_back((out - h) / (cur - h));
      }
  return alphas;
}

TEST(EffectLumaWeight, AlphaStaysWithinItsBoundsAndSpansThem) {
  const auto alphas = inferredAlphas(
      R"({"rectify": "none", "luma_weight": true, "alpha_min": 0.05, "alpha_max": 0.6, "history_format": "rgba32f"})");
  ASSERT_GT(alphas.size(), 2000u);
  const auto [lo, hi] = std::minmax_element(alphas.begin(), alphas.end());
  report("smallest inferred alpha (alpha_min 0.05)", *lo);
  report("largest inferred alpha (alpha_max 0.6)", *hi);
  EXPECT_GE(*lo, 0.05f - 1e-3f);
  EXPECT_LE(*hi, 0.6f + 1e-3f);
  EXPECT_LT(*lo, 0.1f);  // similar lumas lean on the history
  EXPECT_GT(*hi, 0.5f);  // very different lumas trust the current frame
  // Without luma weighting the same inputs blend with the one alpha.
  const auto fixed =
      inferredAlphas(R"({"rectify": "none", "alpha": 0.1, "history_format": "rgba32f"})");
  const auto [flo, fhi] = std::minmax_element(fixed.begin(), fixed.end());
  EXPECT_NEAR(*flo, 0.1f, 1e-3f);
  EXPECT_NEAR(*fhi, 0.1f, 1e-3f);
}

// A cube crossing the checkerboard at ~1 px per frame, no rectification: behind it the history
// keeps its colour for many frames. The depth-closest 3x3 velocity gives the pixels it just left
// its speed, so velocity_alpha resets them at once.
const char* kDynamicAlphaMover = R"({
  "scene": {"builtin": "checkerboard"},
  "render": {"width": 160, "height": 90},
  "script": {"frames": 24},
  "reference": {"samples": 16},
  "movers": [{"shape": "cube", "start": [-3, 0.5, 2], "end": [3, 0.5, 2], "speed": 3, "repeat": "once"}],
  "taa": {"rectify": "none"}
})";

// The red cube's ghost on the neutral checkerboard: mean red excess (R - G) over the reference.
double redness(const Image& img, const Image& ref, const test::Mask& mask) {
  double sum = 0.0;
  int n = 0;
  for (int y = 0; y < img.height; ++y)
    for (int x = 0; x < img.width; ++x)
      if (mask[size_t(y) * img.width + x]) {
        sum += std::max(0.0f,
                        (img.at(x, y, 0) - img.at(x, y, 1)) - (ref.at(x, y, 0) - ref.at(x, y, 1)));
        ++n;
      }
  return n ? sum / n : 0.0;
}

TEST(EffectVelocityAlpha, FastMoverLeavesAShorterTrail) {
  const std::vector<int> frames = {8, 9, 10, 11, 12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23};
  RenderOptions o;
  o.captures |= {Capture::Reference};
  o.captures |= {Capture::Ids};
  const auto& plain = renderOnce(kDynamicAlphaMover, "{}", frames, o);
  const auto& fast =
      renderOnce(kDynamicAlphaMover, R"({"taa": {"velocity_alpha": true, "velocity_alpha_px": 0.5}})",
                 {16, 17, 18, 19, 20, 21, 22, 23});
  double ePlain = 0.0, eFast = 0.0, rPlain = 0.0, rFast = 0.0;
  int trailPlain = 0, trailFast = 0;
  for (int f = 16; f <= 23; ++f) {
    const test::Mask vacated = test::vacatedMask(plain, f - 8, f);
    ePlain += test::rmse(plain[f].color, plain[f].reference, vacated) / 8.0;
    eFast += test::rmse(fast[f].color, plain[f].reference, vacated) / 8.0;
    // Trail length: vacated pixels still visibly off the reference.
    trailPlain += test::differing(plain[f].color, plain[f].reference, 0.1, vacated);
    trailFast += test::differing(fast[f].color, plain[f].reference, 0.1, vacated);
    rPlain += redness(plain[f].color, plain[f].reference, vacated) / 8.0;
    rFast += redness(fast[f].color, plain[f].reference, vacated) / 8.0;
  }
  report("red tint of the trail, velocity_alpha off", rPlain);
  report("red tint of the trail, velocity_alpha on", rFast);
  report("trail rmse, velocity_alpha off", ePlain);
  report("trail rmse, velocity_alpha on", eFast);
  report("trail pixels off by > 0.1 (8 frames), velocity_alpha off", trailPlain);
  report("trail pixels off by > 0.1 (8 frames), velocity_alpha on", trailFast);
  EXPECT_LT(rFast, 0.6 * rPlain);
  EXPECT_LT(eFast, 0.85 * ePlain);
  EXPECT_LT(trailFast, 0.8 * trailPlain);
}

// The fence under Halton jitter with a static camera: thin slats flicker as jitter moves them in
// and out of pixels; near the box edge the history is what keeps them steady.
const char* kFence = R"({
  "scene": {"builtin": "fence"},
  "render": {"width": 160, "height": 90},
  "script": {"frames": 32}
})";

TEST(EffectReduceBlend, LessFlickerOnTheFence) {
  const std::vector<int> frames = {16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27, 28, 29, 30, 31};
  const auto& plain = renderOnce(kFence, "{}", frames);
  const auto& reduced = renderOnce(kFence, R"({"taa": {"reduce_blend_near_clamp": true}})", frames);
  const double fPlain = test::meanFlicker(plain, 16, 31),
               fReduced = test::meanFlicker(reduced, 16, 31);
  report("mean |frame-to-frame change|, frames 16-31, plain", fPlain);
  report("mean |frame-to-frame change|, frames 16-31, reduce_blend_near_clamp", fReduced);
  EXPECT_LT(fReduced, 0.9 * fPlain);
}

}  // namespace
}  // namespace taa
