// Cascaded shadow maps for the directional light: where each cascade's slice of the
// view lies and how it projects into the shadow atlas. Pure functions of the case, the
// frame's camera and the scene's bounds, so the frame and its reference see one map.
#pragma once

#include <array>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include "common/shared.h"
#include "script/frame_state.h"
#include "spec/scene_spec.h"

namespace taa {

constexpr int kShadowMapSize = 1024;  // texels per side of each cascade's tile in the atlas

struct SceneBox {
  glm::vec3 lo{0.0f};
  glm::vec3 hi{0.0f};
  bool empty = true;
  void add(const glm::vec3& p);
};

struct ShadowCascades {
  int count = 0;
  // Far end of each cascade as view depth (distance along the camera's forward axis).
  std::array<float, SHADOW_MAX_CASCADES> splits{};
  // World -> the cascade's clip space: x, y in [-1, 1] over its tile, z in [0, 1] from the
  // light's side of the scene to the far side. The caster pass renders with it.
  std::array<glm::mat4, SHADOW_MAX_CASCADES> lightViewProj{};
  // World size of one shadow-map texel in each cascade.
  std::array<float, SHADOW_MAX_CASCADES> texelWorld{};
  float depthPerWorld = 1.0f;  // clip depth per world unit along the light
  glm::vec3 forward{0.0f, 0.0f, -1.0f};
  glm::vec3 origin{0.0f};
};

// Split distances between `nearPlane` and `farPlane` for `count` cascades: the mean of the
// logarithmic and the uniform split (the "practical" scheme, lambda 0.5). splits[count - 1]
// is farPlane.
std::array<float, SHADOW_MAX_CASCADES> cascadeSplits(float nearPlane, float farPlane, int count);

// How far the cascades reach: from the camera at frame 0 to the farthest corner of the
// scene's bounds then, at most the camera's far plane. A constant of the run, so the
// cascades keep their size (and their texels their world position) as the camera moves.
float shadowDistance(const script::CameraState& camera0, const SceneBox& scene0);

// Each cascade is the bounding sphere of its slice of the view frustum (its radius does not
// change as the camera turns), seen along the light, its centre snapped to whole texels so
// that a shadow edge stays put in the map while the camera moves. `scene` (this frame's
// caster bounds) sets the depth range.
ShadowCascades shadowCascades(const spec::LightingSpec& lighting, const script::CameraState& camera,
                              const SceneBox& scene, float distance);

// The FrameUniforms fields shading reads (all zero when `c.count` is 0).
void setShadowUniforms(gpu::FrameUniforms& u, const ShadowCascades& c);

}  // namespace taa
