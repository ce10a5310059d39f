// Emission (glTF emissiveFactor times KHR_materials_emissive_strength) on both shading
// paths: cases/scenes/emissive.gltf's panels are black and the light has no specular
// term, so each panel shows exactly its emission, and a panel without any shows 0.
#include <gtest/gtest.h>

#include <cmath>

#include "support/gpu.h"

namespace taa {
namespace {

Image renderEmissivePanels(const std::string& path) {
  const auto spec = test::caseFromJson(R"({
    "scene": {"gltf": "scenes/emissive.gltf"},
    "render": {"path": ")" + path + R"("},
    "lighting": {"specular": 0},
    "jitter": {"pattern": "none"},
    "taa": {"mode": "off"},
    "script": {"frames": 1},
    "camera": {"position": [0, 0.6, 3], "target": [0, 0.6, 0]},
    "output": {"frames": [0]}
  })",
                                       "emissive_" + path);
  return test::renderCase(spec)[0].color;
}

TEST(Emission, PanelsShowFactorTimesStrengthOnForwardAndDeferredPaths) {
  // Panel centres at x = -0.8, 0, 0.8 and depth 3: 0.8 * 155.9 / 3 = 41.6 pixels apart.
  struct Panel {
    int x;
    float rgb[3];
  } const panels[] = {{118, {4.0f, 2.0f, 0.5f}}, {160, {0.25f, 0.5f, 1.0f}}, {202, {0, 0, 0}}};
  const Image forward = renderEmissivePanels("forward");
  const Image deferred = renderEmissivePanels("deferred");
  for (const Panel& p : panels)
    for (int c = 0; c < 3; ++c) {
      // RGBA16F targets: half precision, 2^-11 relative.
      const float tolerance = p.rgb[c] * 1e-3f;
      EXPECT_NEAR(forward.at(p.x, 90, c), p.rgb[c], tolerance) << "forward x " << p.x << " c " << c;
      EXPECT_NEAR(deferred.at(p.x, 90, c), p.rgb[c], tolerance)
          << "deferred x " << p.x << " c " << c;
    }
}

}  // namespace
}  // namespace taa
