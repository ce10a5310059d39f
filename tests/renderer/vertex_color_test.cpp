// glTF COLOR_0 reaches the image: the morphed quad (cases/scenes/morphed_quad.gltf) is
// white in its material, red on its left column of vertices and blue on its right.
#include <gtest/gtest.h>

#include "support/gpu.h"

namespace taa {
namespace {

TEST(VertexColor, MorphedQuadIsRedOnTheLeftAndBlueOnTheRight) {
  const auto spec = test::caseFromJson(R"({
    "scene": {"builtin": "checkerboard"},
    "jitter": {"pattern": "none"},
    "taa": {"mode": "off"},
    "script": {"frames": 1},
    "camera": {"position": [0, 0.8, 3], "target": [0, 0.8, 0]},
    "movers": [{"shape": "gltf", "gltf": "scenes/morphed_quad.gltf", "size": 3,
                "start": [0, 0.8, 0], "end": [0, 0.8, 0], "speed": 0, "animation_speed": 0}],
    "output": {"frames": [0]}
  })",
                                       "vertex_color");
  const auto frames = test::renderCase(spec);
  const Image& c = frames[0].color;
  // The quad spans about +-0.24 of the width around the centre; sample near its edges
  // (local x = -+0.4), where the colours are nearly pure.
  const int y = c.height / 2, left = c.width / 2 - c.width / 5, right = c.width / 2 + c.width / 5;
  EXPECT_GT(c.at(left, y, 0), 3.0f * c.at(left, y, 2)) << "red dominates on the left";
  EXPECT_GT(c.at(right, y, 2), 3.0f * c.at(right, y, 0)) << "blue dominates on the right";
  EXPECT_LT(c.at(left, y, 1), 0.25f * c.at(left, y, 0)) << "the white material is tinted";
}

}  // namespace
}  // namespace taa
