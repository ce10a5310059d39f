#include "passes/taa_moving.h"

#include <algorithm>
#include <glm/matrix.hpp>

#include "spec/taa_modes.h"

namespace taa {

float cameraSpeedPx(const script::FrameState& s, float depth) {
  // Unjittered matrices: the jitter is not camera motion, and would make a still camera move.
  const glm::mat4 toWorld = glm::inverse(s.camera.view);
  const glm::mat4 proj = s.camera.projection, prevViewProj = s.prevCamera.viewProjection;
  const glm::vec2 halfSize = glm::vec2(s.renderSize) * 0.5f;
  constexpr glm::vec2 kMovingProbes[] = {
      {0.0f, 0.0f}, {-0.5f, -0.5f}, {0.5f, -0.5f}, {-0.5f, 0.5f}, {0.5f, 0.5f}};
  float speed = 0.0f;
  for (const glm::vec2 ndc : kMovingProbes) {
    // The view-space point at distance `depth` (the camera looks down -z) under this NDC.
    const glm::vec2 slope(ndc.x / proj[0][0], ndc.y / proj[1][1]);
    const glm::vec4 world = toWorld * glm::vec4(slope * depth, -depth, 1.0f);
    const glm::vec4 prev = prevViewProj * world;
    if (prev.w <= 0.0f) return 1e6f;  // behind the previous camera: as fast as it gets
    const glm::vec2 moved = (glm::vec2(prev) / prev.w - ndc) * halfSize;
    speed = std::max(speed, glm::length(moved));
  }
  return speed;
}

float movingWeight(const spec::TaaMovingSpec& moving, const script::FrameState& s) {
  if (!moving.active) return 0.0f;
  const float speed = cameraSpeedPx(s, moving.depth);
  if (speed <= moving.from_px) return 0.0f;
  if (speed >= moving.to_px) return 1.0f;
  const float x = (speed - moving.from_px) / (moving.to_px - moving.from_px);
  return x * x * (3.0f - 2.0f * x);
}

spec::TaaSpec blendMoving(const spec::TaaSpec& user, float w) {
  spec::TaaSpec still = spec::effectiveTaa(user);
  if (w <= 0.0f) return still;
  spec::TaaSpec movingUser = user;
#define TAA_MOVING_NONE_E(key, type, values, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_MOVING_NONE_B(key, def, id, name, modes, reads, rule, text, doc, impl)
#define TAA_MOVING_TAKE_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  movingUser.key = user.moving.key;
#define TAA_MOVING_BLEND_F(key, def, lo, hi, slot, name, modes, rule, text, doc, impl) \
  still.key += (moving.key - still.key) * w;
  TAA_SETTINGS(TAA_MOVING_NONE_E, TAA_MOVING_NONE_B, TAA_MOVING_TAKE_F)
  const spec::TaaSpec moving = spec::effectiveTaa(movingUser);
  TAA_SETTINGS(TAA_MOVING_NONE_E, TAA_MOVING_NONE_B, TAA_MOVING_BLEND_F)
#undef TAA_MOVING_NONE_E
#undef TAA_MOVING_NONE_B
#undef TAA_MOVING_TAKE_F
#undef TAA_MOVING_BLEND_F
  return still;
}

}  // namespace taa
