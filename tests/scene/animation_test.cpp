#include <gtest/gtest.h>

#include <glm/gtc/quaternion.hpp>

#include "scene/geometry.h"
#include "scene/gltf_loader.h"
#include "scene_test_util.h"

namespace taa::scene {
namespace {

glm::vec3 origin(const glm::mat4& m) {
  return glm::vec3(m[3]);
}

void expectNearAnimation(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

// Rotation angle of a transform about +Y, from where it sends +X.
float yawDegrees(const glm::mat4& m) {
  const glm::vec3 x = glm::normalize(glm::vec3(m[0]));
  return glm::degrees(std::atan2(-x.z, x.x));
}

struct AnimatedFixture : ::testing::Test {
  void SetUp() override {
    scene.models.push_back(loadGltf(testing::assetPath("animated.gltf"), scene));
  }
  std::vector<MeshDraw> at(double t) const { return poseModel(scene, 0, t); }
  Scene scene;
};

TEST_F(AnimatedFixture, LinearTranslationAndSlerpRotation) {
  const auto d = at(0.5);
  ASSERT_EQ(d.size(), 2u);
  expectNearAnimation(origin(d[0].transform), {1, 0, 0});
  EXPECT_NEAR(yawDegrees(d[0].transform), 22.5f, 1e-3f);  // a quarter of the way to 90
  const auto e = at(1.5);
  expectNearAnimation(origin(e[0].transform), {2, 1, 0});
  EXPECT_NEAR(yawDegrees(e[0].transform), 67.5f, 1e-3f);
}

TEST_F(AnimatedFixture, StepHoldsUntilTheNextKey) {
  EXPECT_NEAR(glm::length(glm::vec3(at(0.99)[0].transform[0])), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::length(glm::vec3(at(1.0)[0].transform[0])), 2.0f, 1e-5f);
  EXPECT_NEAR(glm::length(glm::vec3(at(1.9)[0].transform[0])), 2.0f, 1e-5f);  // past the last key
}

TEST_F(AnimatedFixture, CubicSplineFollowsHermiteWithScaledTangents) {
  // Keys at 0 and 2: p0 = 0, out-tangent (0,1,0); p1 = (0,2,0), in-tangent 0. At s = 0.5:
  // h10 * 2 * 1 + h01 * 2 = 0.125 * 2 + 0.5 * 2 = 1.25.
  const Scene& s = scene;
  const auto d = poseModel(s, 0, 1.0);
  const glm::mat4 parent = d[0].transform;
  const glm::vec3 local = glm::vec3(glm::inverse(parent) * glm::vec4(origin(d[1].transform), 1.0f));
  expectNearAnimation(local, {0, 1.25f, 0});
  EXPECT_NEAR(glm::length(glm::vec3(d[1].transform[0])), 0.25f * 2.0f, 1e-5f)
      << "child scale times parent's";
}

TEST_F(AnimatedFixture, LoopsModuloDuration) {
  for (double t : {2.5, 4.5, -1.5}) {
    const auto a = at(0.5), b = at(t);
    for (int c = 0; c < 4; ++c)
      for (int k = 0; k < 4; ++k)
        EXPECT_NEAR(a[1].transform[c][k], b[1].transform[c][k], 1e-4f) << t;
  }
}

TEST_F(AnimatedFixture, BoundsAtRest) {
  glm::vec3 lo, hi;
  modelBounds(scene, 0, lo, hi);
  expectNearAnimation(lo, glm::vec3(-0.5f));
  expectNearAnimation(hi, glm::vec3(0.5f));
}

// A hand-built model to test sampling rules in isolation.
Scene oneNode(AnimChannel ch) {
  Scene s;
  MeshBuilder b(s, "m");
  b.setMaterial(addMaterial(s, glm::vec4(1.0f)));
  b.box(glm::vec3(-1.0f), glm::vec3(1.0f));
  Model m = flatModel(s, "m", {b.finish()});
  Animation a;
  a.duration = ch.times.back();
  a.channels.push_back(std::move(ch));
  m.animations.push_back(a);
  s.models.push_back(m);
  return s;
}

TEST(AnimationSampling, SlerpTakesTheShortArc) {
  AnimChannel ch;
  ch.path = AnimPath::Rotation;
  ch.times = {0.0f, 1.0f};
  const glm::quat q = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
  ch.values = {{0, 0, 0, 1}, {-q.x, -q.y, -q.z, -q.w}};  // the same rotation, negated
  ch.times.push_back(4.0f);                              // hold, so t = 0.5 does not wrap
  ch.values.push_back(ch.values.back());
  const Scene s = oneNode(ch);
  EXPECT_NEAR(yawDegrees(poseModel(s, 0, 0.5)[0].transform), 45.0f, 1e-3f);
}

TEST(AnimationSampling, ClampsBeforeFirstKey) {
  AnimChannel ch;
  ch.times = {1.0f, 2.0f};
  ch.values = {{5, 0, 0, 0}, {7, 0, 0, 0}};
  const Scene s = oneNode(ch);
  expectNearAnimation(origin(poseModel(s, 0, 0.5)[0].transform), {5, 0, 0});
  expectNearAnimation(origin(poseModel(s, 0, 1.5)[0].transform), {6, 0, 0});
}

TEST(AnimationSampling, CubicRotationIsNormalised) {
  AnimChannel ch;
  ch.path = AnimPath::Rotation;
  ch.interpolation = Interpolation::CubicSpline;
  ch.times = {0.0f, 1.0f, 2.0f};
  const glm::quat q = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
  const glm::vec4 zero(0.0f), id(0, 0, 0, 1), r(q.x, q.y, q.z, q.w);
  ch.values = {zero, id, zero, zero, r, zero, zero, r, zero};
  const Scene s = oneNode(ch);
  const glm::mat4 m = poseModel(s, 0, 0.5)[0].transform;
  EXPECT_NEAR(glm::length(glm::vec3(m[0])), 1.0f, 1e-5f);
  EXPECT_NEAR(yawDegrees(m), 45.0f, 1.0f) << "smoothstep halfway between the two keys";
}

TEST(AnimationSampling, NoAnimationIsRest) {
  Scene s;
  MeshBuilder b(s, "m");
  b.setMaterial(addMaterial(s, glm::vec4(1.0f)));
  b.box(glm::vec3(0.0f), glm::vec3(1.0f));
  Model m = flatModel(s, "m", {b.finish()});
  m.nodes[0].translation = {1, 2, 3};
  s.models.push_back(m);
  expectNearAnimation(origin(poseModel(s, 0, 123.0)[0].transform), {1, 2, 3});
}

}  // namespace
}  // namespace taa::scene
