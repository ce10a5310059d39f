// The cascade fit of lighting.shadows without a GPU: the split scheme, the cascades'
// reach, and the properties that keep shadow edges still in the map while the camera
// moves (a radius that does not change as the camera turns, centres on whole texels).
#include "frame/shadow_cascades.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

namespace taa {
namespace {

script::CameraState cascadeTestCamera(glm::vec3 position, glm::vec3 target) {
  script::CameraState c;
  c.position = position;
  c.view = glm::lookAt(position, target, glm::vec3(0.0f, 1.0f, 0.0f));
  c.fovY = 1.0f;
  c.aspect = 16.0f / 9.0f;
  c.nearPlane = 0.1f;
  c.farPlane = 1000.0f;
  return c;
}

SceneBox cascadeTestBox() {
  SceneBox b;
  b.add(glm::vec3(-10.0f, 0.0f, -10.0f));
  b.add(glm::vec3(10.0f, 3.0f, 10.0f));
  return b;
}

spec::LightingSpec cascadeTestLighting(int cascades) {
  spec::LightingSpec l;
  l.shadows = true;
  l.cascades = cascades;
  return l;
}

TEST(ShadowCascades, SplitsAreTheMeanOfLogarithmicAndUniform) {
  const auto s = cascadeSplits(0.1f, 40.0f, 4);
  for (int i = 1; i <= 4; ++i) {
    const double t = i / 4.0;
    const double expected = 0.5 * 0.1 * std::pow(400.0, t) + 0.5 * (0.1 + 39.9 * t);
    EXPECT_NEAR(s[size_t(i - 1)], expected, 1e-4 * expected) << i;
  }
  EXPECT_EQ(s[3], 40.0f);
  EXPECT_EQ(cascadeSplits(0.1f, 40.0f, 1)[0], 40.0f);
  for (int i = 1; i < 4; ++i) EXPECT_LT(s[size_t(i - 1)], s[size_t(i)]);
}

TEST(ShadowCascades, ReachTheFarthestSceneCornerAtFrameZeroWithinTheFarPlane) {
  const auto cam = cascadeTestCamera(glm::vec3(0.0f, 2.0f, 12.0f), glm::vec3(0.0f));
  const float d = shadowDistance(cam, cascadeTestBox());
  EXPECT_NEAR(d, glm::length(glm::vec3(10.0f, -2.0f, -22.0f)), 1e-4f);
  auto nearFar = cam;
  nearFar.farPlane = 5.0f;
  EXPECT_EQ(shadowDistance(nearFar, cascadeTestBox()), 5.0f);
}

TEST(ShadowCascades, OffMeansNoCascadesAndNoUniforms) {
  spec::LightingSpec off;
  const auto c = shadowCascades(off, cascadeTestCamera(glm::vec3(0, 2, 12), glm::vec3(0)),
                                cascadeTestBox(), 30.0f);
  EXPECT_EQ(c.count, 0);
  gpu::FrameUniforms u{};
  setShadowUniforms(u, c);
  EXPECT_EQ(u.shadowForward.w, 0.0f);
  EXPECT_EQ(u.shadowMatrix[0], glm::mat4(0.0f));
}

TEST(ShadowCascades, TexelSizeDoesNotChangeAsTheCameraTurnsOrMoves) {
  const auto l = cascadeTestLighting(3);
  const auto a = shadowCascades(l, cascadeTestCamera(glm::vec3(0, 2, 12), glm::vec3(0)),
                                cascadeTestBox(), 30.0f);
  const auto b =
      shadowCascades(l, cascadeTestCamera(glm::vec3(1.3f, 2.5f, 9.0f), glm::vec3(-4, 0, 3)),
                     cascadeTestBox(), 30.0f);
  ASSERT_EQ(a.count, 3);
  for (int i = 0; i < 3; ++i) {
    EXPECT_NEAR(a.texelWorld[size_t(i)], b.texelWorld[size_t(i)], 1e-6f * a.texelWorld[size_t(i)])
        << i;
    if (i > 0) {
      EXPECT_GT(a.texelWorld[size_t(i)], a.texelWorld[size_t(i - 1)]);
    }
  }
}

TEST(ShadowCascades, ASmallCameraMoveShiftsTheMapByWholeTexels) {
  // A world point's texel coordinate in a cascade changes by an integer when the camera
  // moves: the map slides in texel steps, so edges do not crawl across texels.
  const auto l = cascadeTestLighting(2);
  const auto a = shadowCascades(l, cascadeTestCamera(glm::vec3(0, 2, 12), glm::vec3(0)),
                                cascadeTestBox(), 30.0f);
  bool moved = false;
  for (float dx = 0.01f; dx < 0.5f; dx += 0.037f) {
    const auto b = shadowCascades(l, cascadeTestCamera(glm::vec3(dx, 2, 12), glm::vec3(dx, 0, 0)),
                                  cascadeTestBox(), 30.0f);
    for (int i = 0; i < 2; ++i) {
      const glm::vec4 p(0.3f, 0.0f, -1.7f, 1.0f);
      const float half = 0.5f * float(kShadowMapSize);
      const glm::vec2 ta = glm::vec2(a.lightViewProj[size_t(i)] * p) * half;
      const glm::vec2 tb = glm::vec2(b.lightViewProj[size_t(i)] * p) * half;
      const glm::vec2 shift = tb - ta;
      EXPECT_NEAR(shift.x, std::round(shift.x), 2e-3f) << "cascade " << i << " dx " << dx;
      EXPECT_NEAR(shift.y, std::round(shift.y), 2e-3f) << "cascade " << i << " dx " << dx;
      moved = moved || std::round(shift.x) != 0.0f || std::round(shift.y) != 0.0f;
    }
  }
  EXPECT_TRUE(moved) << "the camera moves half a unit; the cascades should follow it";
}

TEST(ShadowCascades, EverySliceCornerLiesInsideItsCascadeAndTheSceneInsideTheDepthRange) {
  const auto l = cascadeTestLighting(4);
  const auto cam = cascadeTestCamera(glm::vec3(0, 2, 12), glm::vec3(0));
  const auto c = shadowCascades(l, cam, cascadeTestBox(), 30.0f);
  const glm::mat4 inv = glm::inverse(cam.view);
  const double tanY = std::tan(0.5);
  float a = cam.nearPlane;
  for (int i = 0; i < 4; ++i) {
    const float b = c.splits[size_t(i)];
    for (const float d : {a, b})
      for (const float sx : {-1.0f, 1.0f})
        for (const float sy : {-1.0f, 1.0f}) {
          const glm::vec4 view(sx * d * float(tanY) * cam.aspect, sy * d * float(tanY), -d, 1.0f);
          const glm::vec4 clip = c.lightViewProj[size_t(i)] * (inv * view);
          EXPECT_LE(std::abs(clip.x), 1.0f + 1e-4f) << "cascade " << i << " depth " << d;
          EXPECT_LE(std::abs(clip.y), 1.0f + 1e-4f) << "cascade " << i << " depth " << d;
        }
    a = b;
  }
  const SceneBox box = cascadeTestBox();
  for (int k = 0; k < 8; ++k) {
    const glm::vec4 corner((k & 1) ? box.hi.x : box.lo.x, (k & 2) ? box.hi.y : box.lo.y,
                           (k & 4) ? box.hi.z : box.lo.z, 1.0f);
    const float z = (c.lightViewProj[0] * corner).z;
    EXPECT_GT(z, 0.0f);
    EXPECT_LT(z, 1.0f);
  }
}

}  // namespace
}  // namespace taa
