// Projection conventions shared by every pass: Vulkan clip space with Y flipped
// (image row 0 is the top, NDC y grows downwards) and reversed Z with depth
// range [0,1] (near plane -> depth 1, far plane -> depth 0).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace taa::script {

// Right-handed view space looking down -Z. Built in double precision and rounded
// once, so near = 1e-4 with far = 1e6 still maps [near, far] onto [1, 0].
glm::mat4 reversedZPerspective(float fovYRadians, float aspect, float nearPlane, float farPlane);

// Where a world point lands on a width x height target: x, y in pixels (y down,
// pixel centres at +0.5) and z the depth-buffer value. Evaluated in double so tests
// measure the matrices, not this helper's rounding.
glm::dvec3 worldToPixel(const glm::mat4& viewProjection, const glm::dvec3& world, glm::ivec2 size);

}  // namespace taa::script
