// A masked caster's shadow is cut by the same alpha as its surface: base colour times COLOR_0's
// alpha. cases/scenes/alpha_cutoff_zero.gltf's right quad has an opaque material and a COLOR_0
// alpha from -1 on its left edge to 1 on its right (cutoff 0), so only its right half stands,
// and only that half may shade the floor; the left quad, drawn whole, casts its whole square.
#include <gtest/gtest.h>

#include <string>

#include "support/gpu.h"

namespace taa::shadow_alpha_test {

Image renderQuads(bool shadows) {
  const std::string lighting = std::string(R"("direction": [0, -0.6, 0.8], "specular": 0)") +
                               (shadows ? R"(, "shadows": true, "cascades": 1)" : "");
  const auto spec = test::caseFromJson(R"({
    "scene": {"gltf": "scenes/alpha_cutoff_zero.gltf"},
    "lighting": {)" + lighting + R"(},
    "camera": {"position": [0, 3.0, 3.2], "target": [0, 0, 1.0]},
    "render": {"width": 192, "height": 108},
    "jitter": {"pattern": "none"},
    "taa": {"mode": "off"},
    "script": {"frames": 1},
    "output": {"frames": [0]}
  })",
                                       shadows ? "shadow_alpha_on" : "shadow_alpha_off");
  return test::renderCase(spec)[0].color;
}

float luma(const Image& im, int x, int y) {
  return 0.2126f * im.at(x, y, 0) + 0.7152f * im.at(x, y, 1) + 0.0722f * im.at(x, y, 2);
}

TEST(ShadowAlpha, ACasterCutByItsVertexAlphaCastsOnlyWhatStands) {
  const Image on = renderQuads(true), off = renderQuads(false);
  int left = 0, right = 0;  // darkened pixels under each quad's half of the view
  for (int y = 0; y < on.height; ++y)
    for (int x = 0; x < on.width; ++x)
      if (luma(on, x, y) < 0.7f * luma(off, x, y)) ++(x < on.width / 2 ? left : right);
  ASSERT_GT(left, 300) << "the whole quad's shadow must be on the floor";
  // Half the quad stands: about half the shadow (its edge is a diagonal's worth off in
  // perspective), far from the whole square's.
  EXPECT_GT(right, left / 4);
  EXPECT_LT(right, left * 3 / 4) << "left " << left << ", right " << right;
}

}  // namespace taa::shadow_alpha_test
