// The tracer's camera rays and texture LOD from ray differentials, on the CPU: the
// same arithmetic as shaders/adaptive_trace.comp and shaders/trace/surface.glsl, so
// tests can hold it against the analytic LOD of a plane without a GPU.
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>

#include "scene/bvh.h"

namespace taa {

// The ray through `pixel` (pixels, y down) from the near plane (reversed Z depth 1)
// to the far plane (depth 0): t in [0, 1] spans the raster's depth range.
scene::Ray cameraRay(const glm::mat4& invViewProj, glm::vec2 pixel, glm::vec2 size);

// Barycentrics (of v1, v2) where the line of `ray` meets the triangle's plane.
glm::vec2 planeBarycentrics(const scene::Triangle& tri, const scene::Ray& ray);

struct UvDifferentials {
  glm::vec2 uv;            // at the hit
  glm::vec2 dUvDx, dUvDy;  // to where the rays one pixel right and one pixel down meet the plane
};

UvDifferentials uvDifferentials(const scene::Triangle& tri, const glm::vec2 uv[3],
                                const scene::Hit& hit, const scene::Ray& right,
                                const scene::Ray& down);

// Vulkan's isotropic LOD for those gradients on a texture of `size` texels:
// log2 of the longer gradient in texels (before bias and clamping).
float textureLod(glm::vec2 dUvDx, glm::vec2 dUvDy, glm::vec2 size);

// adaptive.aniso as the tracer applies it: the longer gradient (in texels) shortened by
// min(longer / shorter, aniso), so textureLod of the result is log2 of the footprint's
// longer axis over that ratio (never below its shorter axis).
void anisotropicGradients(glm::vec2& dUvDx, glm::vec2& dUvDy, glm::vec2 size, float aniso);

}  // namespace taa
