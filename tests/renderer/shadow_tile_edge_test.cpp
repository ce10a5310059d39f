// shadow.glsl keeps its 3x3 PCF kernel inside the cascade's own tile of the atlas: the lookup is
// clamped two texels in from the tile's edges, so no tap's bilinear footprint reaches the next
// cascade's tile. Only a receiver whose lookup lands within two texels of a tile's edge tests
// that clamp, and a cascade's tile is the square around the sphere that bounds its slice of the
// view, so that means a receiver at the slice's far corner with the light's x axis pointing at
// it. No case has one (the mutation sample widened the clamp past the right edge: no frame
// changed), so this test builds one:
// - a wall (a huge cube's face) across the view at a view depth just short of the first split,
//   so the left screen edge shows the first slice's far corner, in a view 64 times wider than
//   high (512 x 8 pixels: the corner is on the sphere's horizontal diameter, and the left column's
//   centres half a pixel from it, about one texel);
// - the sun travelling forward and down, in the camera's vertical plane, so that its x axis is
//   the world's -x: the wall's left edge lies at the right edge of the first cascade's tile;
// - the second cascade's tile, right of that edge, holds the wall's upper part (nearer the sun)
//   on the same rows: a tap reaching it would shadow the wall.
// With the clamp the wall is evenly lit up to its edge.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

#include "frame/shadow_cascades.h"
#include "script/frame_state.h"
#include "support/effects.h"
#include "support/gpu.h"

namespace taa {
namespace {

constexpr int kTileEdgeW = 512, kTileEdgeH = 8;
constexpr float kTileEdgeNear = 0.1f, kTileEdgeFar = 100.0f, kTileEdgeCameraZ = -10.0f;
constexpr float kTileEdgeCubeSize = 1000.0f;

// The wall's view depth: the first of two splits (the cascades reach the far plane: the cube's
// corners lie beyond it), less 1e-4 of it.
float tileEdgeWallDepth() {
  return cascadeSplits(kTileEdgeNear, kTileEdgeFar, 2)[0] * (1.0f - 1e-4f);
}

spec::CaseSpec tileEdgeCase() {
  const float cubeZ = kTileEdgeCameraZ - tileEdgeWallDepth() - 0.5f * kTileEdgeCubeSize;
  char json[1024];
  std::snprintf(json, sizeof(json), R"({
    "scene": {"builtin": "quad"},
    "camera": {"position": [0, 0, %.9g], "target": [0, 0, %.9g], "fov_y_deg": 2.15,
               "near": %.9g, "far": %.9g},
    "render": {"width": %d, "height": %d},
    "lighting": {"direction": [0, -0.6, -0.8], "specular": 0, "shadows": true, "cascades": 2},
    "movers": [{"shape": "cube", "size": %.9g, "start": [0, 0, %.9g], "end": [0, 0, %.9g],
                "color": [0.8, 0.8, 0.8]}],
    "jitter": {"pattern": "none"}, "taa": {"mode": "off"},
    "script": {"frames": 1}, "output": {"frames": [0]}
  })",
                double(kTileEdgeCameraZ), double(kTileEdgeCameraZ - 1.0f), double(kTileEdgeNear),
                double(kTileEdgeFar), kTileEdgeW, kTileEdgeH, double(kTileEdgeCubeSize),
                double(cubeZ), double(cubeZ));
  return test::caseFromJson(json, "shadow_tile_edge");
}

TEST(ShadowTileEdge, AWallIsEvenlyLitUpToTheFirstCascadesTileEdge) {
  const spec::CaseSpec spec = tileEdgeCase();
  // Where the left column's lookup lands, as shadow.glsl computes it (the quad at the origin,
  // behind the camera, and the cube are the casters).
  const script::FrameState state = script::frameState(spec, 0);
  SceneBox box;
  const float h = 0.5f * kTileEdgeCubeSize, cubeZ = kTileEdgeCameraZ - tileEdgeWallDepth() - h;
  for (const glm::vec3 corner : {glm::vec3(-h, -h, cubeZ - h), glm::vec3(h, h, cubeZ + h),
                                 glm::vec3(-0.5f, -0.5f, 0.0f), glm::vec3(0.5f, 0.5f, 0.0f)})
    box.add(corner);
  const ShadowCascades cascades =
      shadowCascades(spec.lighting, state.camera, box, shadowDistance(state.camera, box));
  gpu::FrameUniforms u{};
  setShadowUniforms(u, cascades);
  const float depth = tileEdgeWallDepth();
  ASSERT_LT(depth, u.shadowSplits[0]);  // the first cascade's slice
  const float tanY = std::tan(0.5f * state.camera.fovY);
  const float x = (1.0f / kTileEdgeW - 1.0f) * depth * tanY * state.camera.aspect;
  const glm::vec3 wall(x, 0.0f, kTileEdgeCameraZ - depth), normal(0.0f, 0.0f, 1.0f);
  const glm::vec4 s = u.shadowMatrix[0] * glm::vec4(wall + normal * u.shadowNormalOffset[0], 1.0f);
  const float texel = u.shadowAtlas.x, tileEdge = u.shadowAtlas.z;
  const float pastClamp = (s.x - (tileEdge - 2.0f * texel)) / texel;
  test::report("left column's lookup past the clamp (texels)", pastClamp);
  ASSERT_GT(pastClamp, 0.5f);  // the clamp moves it, so the kernel's right taps...
  ASSERT_LT(pastClamp, 2.0f);  // ...would otherwise reach past the tile's edge

  const Image im = test::renderCase(spec)[0].color;
  const auto luma = [&](int px, int py) {
    return 0.2126f * im.at(px, py, 0) + 0.7152f * im.at(px, py, 1) + 0.0722f * im.at(px, py, 2);
  };
  const float centre = luma(kTileEdgeW / 2, kTileEdgeH / 2);
  ASSERT_GT(centre, 0.5f);  // the wall, lit
  for (int py = 0; py < kTileEdgeH; ++py)
    for (int px = 0; px < kTileEdgeW; ++px)
      EXPECT_NEAR(luma(px, py), centre, 1e-3f * centre) << px << "," << py;
}

}  // namespace
}  // namespace taa
