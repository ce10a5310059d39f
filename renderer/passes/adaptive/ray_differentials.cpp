#include "passes/adaptive/ray_differentials.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec4.hpp>

namespace taa {

namespace {

glm::vec3 unproject(const glm::mat4& invViewProj, glm::vec2 pixel, glm::vec2 size, float depth) {
  const glm::vec2 ndc = pixel / size * 2.0f - 1.0f;
  const glm::vec4 w = invViewProj * glm::vec4(ndc, depth, 1.0f);
  return glm::vec3(w) / w.w;
}

glm::vec2 interpolate(const glm::vec2 uv[3], glm::vec2 b) {
  return uv[0] * (1.0f - b.x - b.y) + uv[1] * b.x + uv[2] * b.y;
}

}  // namespace

scene::Ray cameraRay(const glm::mat4& invViewProj, glm::vec2 pixel, glm::vec2 size) {
  scene::Ray r;
  r.origin = unproject(invViewProj, pixel, size, 1.0f);
  r.dir = unproject(invViewProj, pixel, size, 0.0f) - r.origin;
  r.tMax = 1.0f;
  return r;
}

glm::vec2 planeBarycentrics(const scene::Triangle& tri, const scene::Ray& ray) {
  const glm::vec3 e1 = tri.v1 - tri.v0, e2 = tri.v2 - tri.v0;
  const glm::vec3 ng = glm::cross(e1, e2);
  const float t = glm::dot(tri.v0 - ray.origin, ng) / glm::dot(ray.dir, ng);
  const glm::vec3 p = ray.origin + t * ray.dir - tri.v0;
  const float d00 = glm::dot(e1, e1), d01 = glm::dot(e1, e2), d11 = glm::dot(e2, e2);
  const float d20 = glm::dot(p, e1), d21 = glm::dot(p, e2);
  const float denom = d00 * d11 - d01 * d01;
  return glm::vec2(d11 * d20 - d01 * d21, d00 * d21 - d01 * d20) / denom;
}

UvDifferentials uvDifferentials(const scene::Triangle& tri, const glm::vec2 uv[3],
                                const scene::Hit& hit, const scene::Ray& right,
                                const scene::Ray& down) {
  UvDifferentials d;
  d.uv = interpolate(uv, {hit.u, hit.v});
  d.dUvDx = interpolate(uv, planeBarycentrics(tri, right)) - d.uv;
  d.dUvDy = interpolate(uv, planeBarycentrics(tri, down)) - d.uv;
  return d;
}

float textureLod(glm::vec2 dUvDx, glm::vec2 dUvDy, glm::vec2 size) {
  return std::log2(std::max(glm::length(dUvDx * size), glm::length(dUvDy * size)));
}

void anisotropicGradients(glm::vec2& dUvDx, glm::vec2& dUvDy, glm::vec2 size, float aniso) {
  const float lx = glm::length(dUvDx * size), ly = glm::length(dUvDy * size);
  // At least 1: a zero footprint (a triangle of one UV) has nothing to shorten (0 / 0 was NaN).
  const float ratio =
      std::max(std::min(std::max(lx, ly) / std::max(std::min(lx, ly), 1e-30f), aniso), 1.0f);
  if (lx >= ly)
    dUvDx /= ratio;
  else
    dUvDy /= ratio;
}

}  // namespace taa
