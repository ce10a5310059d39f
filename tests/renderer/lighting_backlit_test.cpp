// lighting.glsl's Blinn-Phong gives a surface that faces away from the sun no specular: n.l is
// clamped to 0 there, and the highlight needs n.l > 0. Seen from the front with the sun grazing
// it from behind, such a surface still has n.h > 0, so a highlight computed anyway would show.
// cases/scenes/uv1_emissive.gltf's quads face +z; the sun travels up-to-down and towards +z
// (from behind them), the camera looks at their fronts. Its occlusion quad's lower half runs
// the occluded variant, the other pixels the plain one (forward) or the shadowed one
// (deferred, shadows on): each quad must look the same with and without specular. No case
// lights an occlusion-textured surface from behind (the mutation sample's `n.l >= 0` changed
// no frame).
#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include "support/content.h"
#include "support/gpu.h"

namespace taa {
namespace {

// The case's lighting.direction (where the light travels) and camera position, below.
const glm::vec3 kBacklitSun{0.0f, -1.0f, 0.3f};
const glm::vec3 kBacklitCamera{0.0f, 1.1f, 3.2f};

spec::CaseSpec backlitCase(const std::string& path, bool shadows, float specular) {
  const std::string members =
      R"("scene": {"gltf": "scenes/uv1_emissive.gltf"},
      "camera": {"position": [0, 1.1, 3.2], "target": [0, 0.85, 0]},
      "render": {"width": 96, "height": 54, "path": ")" +
      path + R"("},
      "lighting": {"direction": [0, -1, 0.3], "shininess": 1, "specular": )" +
      std::to_string(specular) + (shadows ? R"(, "shadows": true, "cascades": 1)" : "") + "}";
  return test::stillCase(members, "backlit_" + path);
}

TEST(LightingBacklit, ASurfaceFacingAwayFromTheSunHasNoHighlight) {
  // The occlusion quad's lower quarter (0, 0.65, 0): behind the sun's side, yet n.h is large.
  const glm::vec3 n(0.0f, 0.0f, 1.0f), l = -glm::normalize(kBacklitSun);
  const glm::vec3 v = glm::normalize(kBacklitCamera - glm::vec3(0.0f, 0.65f, 0.0f));
  ASSERT_LT(glm::dot(n, l), 0.0f);
  ASSERT_GT(glm::dot(n, glm::normalize(l + v)), 0.5f);
  for (const auto& [path, shadows] :
       {std::pair<std::string, bool>{"forward", false}, {"deferred", true}}) {
    const spec::CaseSpec spec = backlitCase(path, shadows, 1.0f);
    const Image with = test::renderStill(spec),
                without = test::renderStill(backlitCase(path, shadows, 0.0f));
    int compared = 0;
    for (const float quadX : {-1.2f, 0.0f, 1.2f}) {
      // The quad's pixels, 0.05 in from its edges (the floor below faces the sun: it shines).
      const test::Pixel lo = test::pixelOf(spec, {quadX - 0.45f, 1.35f, 0.0f});
      const test::Pixel hi = test::pixelOf(spec, {quadX + 0.45f, 0.45f, 0.0f});
      for (int y = lo.y; y <= hi.y; ++y)
        for (int x = lo.x; x <= hi.x; ++x, ++compared)
          for (int c = 0; c < 3; ++c)
            EXPECT_EQ(with.at(x, y, c), without.at(x, y, c)) << path << " at " << x << "," << y;
    }
    EXPECT_GT(compared, 3 * 100) << path;
  }
}

}  // namespace
}  // namespace taa
