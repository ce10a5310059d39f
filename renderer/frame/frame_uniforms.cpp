#include "frame/frame_uniforms.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

namespace taa {

namespace {
// Projection times the view's rotation alone: the sky lies at infinity, so only
// the camera's orientation moves it.
glm::mat4 rotationOnly(const script::CameraState& c) { return c.projection * glm::mat4(glm::mat3(c.view)); }
}  // namespace

gpu::FrameUniforms makeFrameUniforms(const script::FrameState& s, const spec::LightingSpec& lighting) {
  gpu::FrameUniforms u{};
  u.viewProj = s.jitteredProjection * s.camera.view;
  u.viewProjNoJitter = s.camera.viewProjection;
  u.prevViewProjNoJitter = s.prevCamera.viewProjection;
  u.invViewProjNoJitter = glm::inverse(s.camera.viewProjection);
  u.skyViewProj = rotationOnly(s.camera);
  u.skyInvViewProj = glm::inverse(u.skyViewProj);
  u.skyPrevViewProj = rotationOnly(s.prevCamera);
  u.cameraPos = glm::vec4(s.camera.position, 1.0f);
  u.lightDir = glm::vec4(-glm::normalize(lighting.direction), lighting.intensity);
  u.lightColor = glm::vec4(lighting.color, lighting.specular);
  u.ambient = glm::vec4(lighting.ambient, lighting.shininess);
  const glm::vec2 size(s.renderSize);
  u.renderSize = glm::vec4(size, 1.0f / size.x, 1.0f / size.y);
  u.jitter = glm::vec4(s.jitter, 0.0f, 0.0f);
  return u;
}

}  // namespace taa
