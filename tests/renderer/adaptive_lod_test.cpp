// Texture LOD from ray differentials (the tracer's arithmetic, mirrored on the CPU in
// passes/adaptive/ray_differentials) against the analytic LOD of a textured plane
// seen at known angles: at the image centre one pixel spans d * a / cos(theta) of the
// plane along its tilt and d * a across it, a = 2 tan(fov / 2) / height.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/trigonometric.hpp>

#include "passes/adaptive/ray_differentials.h"
#include "script/projection.h"

namespace taa {
namespace {

struct Plane {
  scene::Triangle tri;
  glm::vec2 uv[3];
};

// A large triangle in the plane through (0, 0, -d) whose normal is tilted by theta
// from +Z about the x axis; uv = k * (x along e1, y along e2) in world units.
Plane tiltedPlane(float d, float thetaRad, float k) {
  const glm::vec3 centre(0.0f, 0.0f, -d);
  const glm::vec3 e1(1.0f, 0.0f, 0.0f);
  const glm::vec3 e2(0.0f, std::cos(thetaRad), -std::sin(thetaRad));
  const glm::vec2 corners[3] = {{-50.0f, -50.0f}, {50.0f, -50.0f}, {0.0f, 50.0f}};
  Plane p;
  glm::vec3* v[3] = {&p.tri.v0, &p.tri.v1, &p.tri.v2};
  for (int i = 0; i < 3; ++i) {
    *v[i] = centre + e1 * corners[i].x + e2 * corners[i].y;
    p.uv[i] = corners[i] * k;
  }
  return p;
}

TEST(AdaptiveRayLod, MatchesTheAnalyticLodOfATiltedPlane) {
  const float fov = glm::radians(60.0f);
  const glm::vec2 size(321.0f, 181.0f);  // odd: a pixel centre lies on the optical axis
  const glm::mat4 proj = script::reversedZPerspective(fov, size.x / size.y, 0.1f, 1000.0f);
  const glm::mat4 inv = glm::inverse(proj);  // the camera sits at the origin looking down -Z
  const glm::vec2 centre = size * 0.5f;
  const float pixelAngle = 2.0f * std::tan(fov * 0.5f) / size.y;
  const glm::vec2 texture(256.0f);
  for (float d : {2.0f, 10.0f, 40.0f})
    for (float deg : {0.0f, 30.0f, 60.0f, 75.0f}) {
      const float theta = glm::radians(deg);
      const float k = 0.5f;
      const Plane plane = tiltedPlane(d, theta, k);
      const scene::Ray ray = cameraRay(inv, centre, size);
      scene::Hit hit;
      ASSERT_TRUE(scene::intersectTriangle(ray, plane.tri, hit.t, hit.u, hit.v));
      hit.triangle = 0;
      const auto diff =
          uvDifferentials(plane.tri, plane.uv, hit, cameraRay(inv, centre + glm::vec2(1, 0), size),
                          cameraRay(inv, centre + glm::vec2(0, 1), size));
      const float analytic = std::log2(texture.x * k * d * pixelAngle / std::cos(theta));
      const float lod = textureLod(diff.dUvDx, diff.dUvDy, texture);
      // A one-pixel difference is not a derivative: the plane's perspective makes it
      // longer by about pixelAngle * tan(theta) relatively (2.4% at 75 degrees).
      const float tolerance = 0.005f + 1.5f * pixelAngle * std::tan(theta) / std::log(2.0f);
      EXPECT_NEAR(lod, analytic, tolerance) << "d " << d << " theta " << deg;
      // Across the tilt the footprint does not stretch.
      EXPECT_NEAR(std::log2(glm::length(diff.dUvDx * texture)),
                  std::log2(texture.x * k * d * pixelAngle), 0.005f)
          << "d " << d << " theta " << deg;
    }
}

TEST(AdaptiveRayLod, PlaneBarycentricsExtendPastTheTriangle) {
  const scene::Triangle tri{{0, 0, -1}, {1, 0, -1}, {0, 1, -1}};
  scene::Ray r;
  r.origin = {2.0f, 3.0f, 0.0f};
  r.dir = {0.0f, 0.0f, -2.0f};
  const glm::vec2 b = planeBarycentrics(tri, r);
  EXPECT_FLOAT_EQ(b.x, 2.0f);
  EXPECT_FLOAT_EQ(b.y, 3.0f);
}

}  // namespace
}  // namespace taa
