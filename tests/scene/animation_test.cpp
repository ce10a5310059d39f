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

// Two clips on one node, as exporters write a rig's Walk and Run, and a third on another
// node: by default the first and the independent third play, not the second, which would
// overwrite the first (before issue 25 all three played and the second won).
Scene threeClips() {
  AnimChannel walk;
  walk.path = AnimPath::Translation;
  walk.times = {0.0f, 1.0f};
  walk.values = {{0, 0, 0, 0}, {1, 0, 0, 0}};
  Scene s = oneNode(walk);
  Model& m = s.models[0];
  m.animations[0].name = "Walk";
  Animation run = m.animations[0];
  run.name = "Run";
  run.channels[0].values = {{0, 0, 0, 0}, {4, 0, 0, 0}};
  m.animations.push_back(run);
  Node second = m.nodes[0];
  second.name = "second";
  m.nodes.push_back(second);
  Animation bob = m.animations[0];
  bob.name = "Bob";
  bob.channels[0].node = 1;
  bob.channels[0].values = {{0, 0, 0, 0}, {0, 2, 0, 0}};
  m.animations.push_back(bob);
  return s;
}

TEST(AnimationDefault, TheFirstOfClipsDrivingOneNodePlaysWithTheIndependentOnes) {
  Scene s = threeClips();
  EXPECT_EQ(defaultAnimations(s.models[0]), (std::vector<int>{0, 2}));
  const auto d = poseModel(s, 0, 0.5);
  expectNearAnimation(origin(d[0].transform), {0.5f, 0, 0});  // Walk, not Run's 2
  expectNearAnimation(origin(d[1].transform), {0, 1.0f, 0});  // Bob plays as well
  EXPECT_EQ(describeAnimations(s.models[0]),
            "m plays 0 'Walk', 2 'Bob'; not 1 'Run', which drive what an earlier one drives "
            "(pick with scene.animations or movers[].animations)");
  s.models[0].playing = {1};  // a case's pick
  expectNearAnimation(origin(poseModel(s, 0, 0.5)[0].transform), {2.0f, 0, 0});
  EXPECT_EQ(describeAnimations(s.models[0]),
            "m plays 1 'Run'; not 0 'Walk', 2 'Bob' (not picked by the case)");
}

TEST(AnimationDefault, KhronosBoxAnimatedPlaysBothOfItsAnimations) {
  // Its two animations drive different nodes (the inner box's translation, its rotation on
  // another node): both play, as its README shows.
  Scene s;
  s.models.push_back(loadGltf(testing::assetPath("khronos/BoxAnimated.gltf"), s));
  EXPECT_EQ(defaultAnimations(s.models[0]), (std::vector<int>{0, 1}));
}

TEST(PosedBounds, HoldEveryPoseAtTheGivenTimes) {
  // A box sliding 1 unit a second along +X for one second, then holding for one: at rest its
  // bounds end at x 1; posed over the first second they reach 2.
  AnimChannel slide;
  slide.path = AnimPath::Translation;
  slide.times = {0.0f, 1.0f, 2.0f};
  slide.values = {{0, 0, 0, 0}, {1, 0, 0, 0}, {1, 0, 0, 0}};
  const Scene s = oneNode(slide);
  glm::vec3 lo, hi;
  modelBounds(s, 0, lo, hi);
  EXPECT_NEAR(hi.x, 1.0f, 1e-6f);
  modelBounds(s, 0, {0.0, 0.5, 1.0}, lo, hi);
  EXPECT_NEAR(hi.x, 2.0f, 1e-6f);
  EXPECT_NEAR(lo.x, -1.0f, 1e-6f);
}

TEST(PosedBounds, SkinnedMeshesUseTheirDeformedVertices) {
  // skinned_quad.gltf: the right edge rises 0.8 units a second; the bind-pose bounds stop at
  // y 0.5, the pose at 5 s reaches 4.5.
  Scene s;
  s.models.push_back(loadGltf(testing::assetPath("skinned_quad.gltf"), s));
  glm::vec3 lo, hi;
  modelBounds(s, 0, {0.0, 5.0}, lo, hi);
  EXPECT_NEAR(hi.y, 4.5f, 1e-4f);
  EXPECT_NEAR(lo.y, -0.5f, 1e-4f);
}

}  // namespace
}  // namespace taa::scene
