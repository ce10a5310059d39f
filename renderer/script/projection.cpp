#include "script/projection.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/mat4x4.hpp>

namespace taa::script {

glm::mat4 reversedZPerspective(float fovYRadians, float aspect, float nearPlane, float farPlane) {
  // Swapping near and far in the [0,1] perspective is what reverses Z: float depth
  // then keeps its precision far away, where the 1/z mapping compresses it.
  glm::dmat4 p = glm::perspectiveRH_ZO<double>(fovYRadians, aspect, farPlane, nearPlane);
  p[1][1] = -p[1][1];  // Vulkan's framebuffer y points down
  return glm::mat4(p);
}

glm::dvec3 worldToPixel(const glm::mat4& viewProjection, const glm::dvec3& world, glm::ivec2 size) {
  const glm::dvec4 clip = glm::dmat4(viewProjection) * glm::dvec4(world, 1.0);
  const glm::dvec3 ndc = glm::dvec3(clip) / clip.w;
  return {(ndc.x * 0.5 + 0.5) * size.x, (ndc.y * 0.5 + 0.5) * size.y, ndc.z};
}

}  // namespace taa::script
