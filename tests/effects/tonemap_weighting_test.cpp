// Luminance-weighted blending (Karis 1/(1+luma), inverse-luma and log domains) on an HDR scene
// with a sub-pixel specular highlight: the weighting changes the output, and the highlight's
// linear value jumps less from frame to frame as the jitter moves it in and out of pixels.
#include <gtest/gtest.h>

#include <cmath>

#include "support/effects.h"

namespace taa {
namespace {

using test::renderOnce;
using test::report;

// A glossy sphere seen close up: shininess 3000 makes its highlight smaller than a pixel and
// ~500 times brighter than the rest of the frame, so it lands in a pixel on some jitter steps
// only.
const char* kHighlight = R"({
  "scene": {"builtin": "checkerboard"},
  "lighting": {"intensity": 3, "specular": 400, "shininess": 3000, "direction": [0.3, -0.5, -1]},
  "camera": {"position": [0, 1.2, 3.2], "target": [0, 0.8, 0]},
  "movers": [{"shape": "sphere", "start": [0, 0.8, 1.5], "end": [0, 0.8, 1.5], "speed": 0, "size": 1.2}],
  "render": {"width": 128, "height": 72},
  "script": {"frames": 32},
  "reference": {"samples": 64}
})";

std::vector<int> window() {
  std::vector<int> f;
  for (int i = 16; i < 32; ++i) f.push_back(i);
  return f;
}

const test::EffectRun& run(const char* weighting) {
  return renderOnce(
      kHighlight, std::string(R"({"taa": {"tonemap_weighting": ")") + weighting + "\"}}", window());
}

// Pixels within one of where the reference is brighter than 2 (the highlight).
test::Mask highlight() {
  RenderOptions o;
  o.captures |= {Capture::Reference};
  const Image& ref = renderOnce(kHighlight, "{}", {31}, o)[31].reference;
  return test::dilate(test::maskWhere(ref.width, ref.height,
                                      [&](int x, int y) { return luminance(ref, x, y) > 2.0f; }),
                      ref.width, ref.height, 1);
}

// Mean frame-to-frame change of the tonemapped (Reinhard) output over the mask.
double displayFlicker(const test::EffectRun& r, const test::Mask& mask) {
  double sum = 0.0;
  for (int f = 17; f < 32; ++f) {
    Image a = r[f].color, b = r[f - 1].color;
    for (float& v : a.data) v = v / (1.0f + v);
    for (float& v : b.data) v = v / (1.0f + v);
    sum += test::meanAbs(a, b, mask) / 15.0;
  }
  return sum;
}

void check(const char* weighting, double maxRatio) {
  const test::Mask bright = highlight();
  ASSERT_GT(test::count(bright), 10);
  const auto& none = run("none");
  const auto& weighted = run(weighting);
  EXPECT_GT(test::differing(weighted[31].color, none[31].color, 1e-3), 300) << "output unchanged";
  const double fNone = test::meanFlicker(none, 16, 31, bright),
               fWeighted = test::meanFlicker(weighted, 16, 31, bright);
  report("highlight pixels", test::count(bright));
  report("linear highlight flicker, none", fNone);
  report(std::string("linear highlight flicker, ") + weighting, fWeighted);
  // What a display shows after a tonemap does not calm down: the weighted average tracks the
  // tonemapped samples, whose changes are as large (reported for the record).
  report("tonemapped highlight flicker, none", displayFlicker(none, bright));
  report(std::string("tonemapped highlight flicker, ") + weighting,
         displayFlicker(weighted, bright));
  EXPECT_LT(fWeighted, maxRatio * fNone);
}

TEST(EffectToneWeighting, KarisReducesHighlightFlicker) {
  check("karis", 0.6);
}

TEST(EffectToneWeighting, InverseLumaReducesHighlightFlicker) {
  check("inverse_luma", 0.6);
}

TEST(EffectToneWeighting, LogReducesHighlightFlicker) {
  check("log", 0.85);
}

}  // namespace
}  // namespace taa
