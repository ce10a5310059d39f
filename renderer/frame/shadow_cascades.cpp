#include "frame/shadow_cascades.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

namespace taa {

namespace {

// Receivers move this many texels along their normal before the lookup, and their depth
// this many texels' worth towards the light: enough that a lit surface does not shadow
// itself at grazing angles (acne), little enough that contact shadows stay attached.
constexpr double kShadowNormalOffsetTexels = 1.5;
constexpr double kShadowDepthBiasTexels = 1.0;

// Light basis: z along the direction the light travels, x and y across it.
glm::dmat3 lightBasis(const glm::vec3& travel) {
  const glm::dvec3 z = glm::normalize(glm::dvec3(travel));
  const glm::dvec3 hint =
      std::abs(z.y) > 0.99 ? glm::dvec3(1.0, 0.0, 0.0) : glm::dvec3(0.0, 1.0, 0.0);
  const glm::dvec3 x = glm::normalize(glm::cross(hint, z));
  return glm::dmat3(x, glm::cross(z, x), z);
}

}  // namespace

void SceneBox::add(const glm::vec3& p) {
  lo = empty ? p : glm::min(lo, p);
  hi = empty ? p : glm::max(hi, p);
  empty = false;
}

std::array<float, SHADOW_MAX_CASCADES> cascadeSplits(float nearPlane, float farPlane, int count) {
  std::array<float, SHADOW_MAX_CASCADES> out{};
  const double n = nearPlane, f = farPlane;
  for (int i = 1; i <= count; ++i) {
    const double t = double(i) / count;
    out[size_t(i - 1)] = float(0.5 * n * std::pow(f / n, t) + 0.5 * (n + (f - n) * t));
  }
  out[size_t(count - 1)] = farPlane;
  return out;
}

float shadowDistance(const script::CameraState& camera0, const SceneBox& scene0) {
  if (scene0.empty) return camera0.farPlane;
  double far = 0.0;
  for (int i = 0; i < 8; ++i) {
    const glm::dvec3 corner((i & 1) ? scene0.hi.x : scene0.lo.x,
                            (i & 2) ? scene0.hi.y : scene0.lo.y,
                            (i & 4) ? scene0.hi.z : scene0.lo.z);
    far = std::max(far, glm::length(corner - glm::dvec3(camera0.position)));
  }
  return float(std::clamp(far, double(camera0.nearPlane) * 2.0, double(camera0.farPlane)));
}

ShadowCascades shadowCascades(const spec::LightingSpec& lighting, const script::CameraState& camera,
                              const SceneBox& scene, float distance) {
  ShadowCascades c;
  c.count = lighting.shadows ? lighting.cascades : 0;
  if (c.count == 0) return c;
  // The view's forward axis, from the view matrix (world -> view looks down -Z).
  const glm::dmat3 viewRot(glm::dmat4(camera.view));
  const glm::dvec3 forward = -glm::dvec3(viewRot[0][2], viewRot[1][2], viewRot[2][2]);
  c.forward = glm::vec3(glm::normalize(forward));
  c.origin = camera.position;
  c.splits = cascadeSplits(camera.nearPlane, std::max(distance, camera.nearPlane * 2.0f), c.count);

  const glm::dmat3 basis = lightBasis(lighting.direction);
  const glm::dmat3 toLight = glm::transpose(basis);
  // Depth range: the casters' bounds along the light, widened by a quarter of their diagonal
  // for deformed meshes, whose bounds at rest may not hold their posed vertices.
  double zLo = 0.0, zHi = 1.0;
  if (!scene.empty) {
    const double margin = 0.25 * glm::length(glm::dvec3(scene.hi - scene.lo)) + 1e-3;
    zLo = 1e300;
    zHi = -1e300;
    for (int i = 0; i < 8; ++i) {
      const glm::dvec3 corner((i & 1) ? scene.hi.x : scene.lo.x, (i & 2) ? scene.hi.y : scene.lo.y,
                              (i & 4) ? scene.hi.z : scene.lo.z);
      const double z = (toLight * corner).z;
      zLo = std::min(zLo, z - margin);
      zHi = std::max(zHi, z + margin);
    }
  }
  c.depthPerWorld = float(1.0 / (zHi - zLo));
  // Tangent of the half diagonal of the view: a slice's corners at depth d lie d * k off axis.
  const double tanY = std::tan(double(camera.fovY) * 0.5);
  const double k2 = tanY * tanY * (1.0 + double(camera.aspect) * double(camera.aspect));
  double a = camera.nearPlane;
  for (int i = 0; i < c.count; ++i) {
    const double b = c.splits[size_t(i)];
    // The smallest sphere around the slice [a, b] centred on the view axis: at equal distance
    // from the near and far corners, or on the far plane when that is closer.
    const double centreDepth = std::min(b, 0.5 * (a + b) * (1.0 + k2));
    const double radius = std::sqrt((b - centreDepth) * (b - centreDepth) + b * b * k2);
    const glm::dvec3 centre = toLight * (glm::dvec3(camera.position) + forward * centreDepth);
    const double texel = 2.0 * radius / kShadowMapSize;
    const double cx = std::floor(centre.x / texel) * texel,
                 cy = std::floor(centre.y / texel) * texel;
    // Columns of world -> clip: light basis rows scaled into [-1, 1] and depth into [0, 1].
    glm::dmat4 m(0.0);
    const double sz = c.depthPerWorld;
    for (int col = 0; col < 3; ++col) {
      m[col][0] = toLight[col][0] / radius;
      m[col][1] = toLight[col][1] / radius;
      m[col][2] = toLight[col][2] * sz;
    }
    m[3] = glm::dvec4(-cx / radius, -cy / radius, -zLo * sz, 1.0);
    c.lightViewProj[size_t(i)] = glm::mat4(m);
    c.texelWorld[size_t(i)] = float(texel);
    a = b;
  }
  return c;
}

void setShadowUniforms(gpu::FrameUniforms& u, const ShadowCascades& c) {
  if (c.count == 0) return;
  const double tile = 1.0 / c.count;
  for (int i = 0; i < c.count; ++i) {
    // Clip x, y in [-1, 1] -> the cascade's tile of the atlas; depth moved towards the light.
    glm::dmat4 toAtlas(1.0);
    toAtlas[0][0] = 0.5 * tile;
    toAtlas[1][1] = 0.5;
    toAtlas[3] = glm::dvec4((i + 0.5) * tile, 0.5, 0.0, 1.0);
    // Moving the depth towards the light: a receiver passes the test against its own surface.
    toAtlas[3][2] = -kShadowDepthBiasTexels * c.texelWorld[size_t(i)] * c.depthPerWorld;
    glm::dmat4 m = toAtlas * glm::dmat4(c.lightViewProj[size_t(i)]);
    u.shadowMatrix[i] = glm::mat4(m);
    u.shadowNormalOffset[i] = float(kShadowNormalOffsetTexels * c.texelWorld[size_t(i)]);
    u.shadowSplits[i] = c.splits[size_t(i)];
  }
  u.shadowForward = glm::vec4(c.forward, float(c.count));
  u.shadowOrigin = glm::vec4(c.origin, 0.0f);
  u.shadowAtlas = glm::vec4(1.0f / float(kShadowMapSize * c.count), 1.0f / float(kShadowMapSize),
                            float(tile), 0.0f);
}

}  // namespace taa
