// lighting.shadows on the GPU: a cube hovering over the checkerboard casts a shadow on it
// (the floor there falls to its ambient light), shadows only ever darken, the forward and
// deferred paths shade the same shadow, and the supersampled reference sees it too.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "support/gpu.h"

namespace taa {
namespace {

spec::CaseSpec shadowCase(bool shadows, const std::string& path, int cascades = 3) {
  std::string lighting = R"("direction": [0.6, -1.0, 0.5], "specular": 0)";
  if (shadows) lighting += R"(, "shadows": true, "cascades": )" + std::to_string(cascades);
  return test::caseFromJson(R"({
    "scene": {"builtin": "checkerboard"},
    "lighting": {)" + lighting + R"(},
    "render": {"path": ")" + path +
                                R"("},
    "movers": [{"shape": "cube", "size": 1.0, "start": [0, 1.0, 0], "end": [0, 1.0, 0], "color": [0.8, 0.8, 0.8]}],
    "jitter": {"pattern": "none"},
    "taa": {"mode": "off"},
    "script": {"frames": 1},
    "reference": {"samples": 4},
    "output": {"frames": [0]}
  })",
                            "shadow_" + path + (shadows ? "_on" : "_off"));
}

struct ShadowFrames {
  Image color;
  Image reference;
};

ShadowFrames renderShadowCase(const spec::CaseSpec& spec) {
  RenderOptions o;
  o.captures |= {Capture::Reference};
  auto records = test::renderCaseWith(spec, o);
  return {records[0].color, test::capturedImage(records[0], Capture::Reference)};
}

float shadowLuma(const Image& im, int x, int y) {
  return 0.2126f * im.at(x, y, 0) + 0.7152f * im.at(x, y, 1) + 0.0722f * im.at(x, y, 2);
}

// Pixels at most `ratio` as bright with shadows as without.
int darkenedPixels(const Image& on, const Image& off, float ratio) {
  int n = 0;
  for (int y = 0; y < on.height; ++y)
    for (int x = 0; x < on.width; ++x)
      if (shadowLuma(on, x, y) < ratio * shadowLuma(off, x, y)) ++n;
  return n;
}

TEST(Shadows, ACubeShadowsTheFloorAndNothingGetsBrighter) {
  const ShadowFrames off = renderShadowCase(shadowCase(false, "forward"));
  const ShadowFrames on = renderShadowCase(shadowCase(true, "forward"));
  // The cube's shadow: a 1x1 unit square cast about 0.5 units along the light, a few hundred
  // pixels at 320x180 from 6 units away.
  const int shadowed = darkenedPixels(on.color, off.color, 0.5f);
  EXPECT_GT(shadowed, 300);
  EXPECT_LT(shadowed, 4000);
  float maxGain = 0.0f;
  for (int y = 0; y < on.color.height; ++y)
    for (int x = 0; x < on.color.width; ++x)
      for (int c = 0; c < 3; ++c)
        maxGain = std::max(maxGain, on.color.at(x, y, c) - off.color.at(x, y, c));
  EXPECT_LE(maxGain, 0.0f) << "a shadow may only take light away";
}

TEST(Shadows, ForwardAndDeferredShadeTheSameShadow) {
  const ShadowFrames forward = renderShadowCase(shadowCase(true, "forward", 2));
  const ShadowFrames deferred = renderShadowCase(shadowCase(true, "deferred", 2));
  const ShadowFrames off = renderShadowCase(shadowCase(false, "deferred"));
  EXPECT_GT(darkenedPixels(deferred.color, off.color, 0.5f), 300);
  float worst = 0.0f;
  for (int y = 0; y < forward.color.height; ++y)
    for (int x = 0; x < forward.color.width; ++x)
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(forward.color.at(x, y, c) - deferred.color.at(x, y, c)));
  // Deferred reconstructs the position from depth and reads a half-float normal; both move
  // the lookup by far less than a shadow-map texel, so the shadows match to a few 1e-3.
  EXPECT_LT(worst, 0.02f);
}

TEST(Shadows, TheReferenceSeesTheSameShadow) {
  const ShadowFrames off = renderShadowCase(shadowCase(false, "forward"));
  const ShadowFrames on = renderShadowCase(shadowCase(true, "forward"));
  const int inFrame = darkenedPixels(on.color, off.color, 0.5f);
  const int inReference = darkenedPixels(on.reference, off.reference, 0.5f);
  EXPECT_GT(inReference, 300);
  EXPECT_NEAR(double(inReference), double(inFrame), 0.1 * inFrame);
}

TEST(Shadows, MoreCascadesSharpenTheNearShadow) {
  // The first cascade covers less of the view with more cascades: its texels are smaller,
  // so the PCF penumbra (partly lit pixels) narrows.
  const auto penumbra = [](const Image& on, const Image& off) {
    int n = 0;
    for (int y = 0; y < on.height; ++y)
      for (int x = 0; x < on.width; ++x) {
        const float r = shadowLuma(on, x, y) / std::max(shadowLuma(off, x, y), 1e-6f);
        if (r > 0.3f && r < 0.9f) ++n;
      }
    return n;
  };
  const ShadowFrames off = renderShadowCase(shadowCase(false, "forward"));
  const ShadowFrames one = renderShadowCase(shadowCase(true, "forward", 1));
  const ShadowFrames four = renderShadowCase(shadowCase(true, "forward", 4));
  EXPECT_LT(penumbra(four.color, off.color), penumbra(one.color, off.color));
}

}  // namespace
}  // namespace taa
