#include "script/camera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "script/projection.h"

using taa::script::activeCut;
using taa::script::cameraPose;
using taa::script::CameraPose;
using taa::script::cutStartsAt;
using taa::script::lookOrientation;
using taa::script::pitchDegrees;
using taa::script::reversedZPerspective;
using taa::script::worldToPixel;
using taa::spec::CameraSpec;
using taa::spec::LookMode;
using taa::spec::TimingSpec;

namespace {

// At the origin facing -Z: yaw, pitch and strafe directions read off directly.
CameraSpec straightCamera() {
  CameraSpec c;
  c.position = {0.0f, 0.0f, 0.0f};
  c.target = {0.0f, 0.0f, -1.0f};
  return c;
}

const TimingSpec kTiming{60, 16, {}};

CameraPose poseAt(const CameraSpec& c, int frame) {
  return cameraPose(c, kTiming, frame);
}

void expectVec(const glm::dvec3& a, const glm::dvec3& b, double tol = 1e-9) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

void expectOrthonormal(const glm::dmat3& m) {
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) EXPECT_NEAR(glm::dot(m[i], m[j]), i == j ? 1.0 : 0.0, 1e-12);
  EXPECT_NEAR(glm::determinant(m), 1.0, 1e-12);  // a rotation, not a mirror
}

}  // namespace

TEST(CameraBase, ViewMatchesGlmLookAtWithYUp) {
  CameraSpec c;  // default pose (0,1.6,6) -> (0,0.5,0)
  const glm::mat4 expected = glm::lookAt(c.position, c.target, glm::vec3(0, 1, 0));
  const glm::mat4 view = poseAt(c, 0).view();
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) EXPECT_NEAR(view[i][j], expected[i][j], 1e-6f) << i << "," << j;
}

TEST(CameraBase, LookingStraightDownOrUpHasADefinedUpVector) {
  const glm::dmat3 down = lookOrientation({0, -5, 0});
  expectOrthonormal(down);
  expectVec(down[0], {1, 0, 0});   // right stays +X, as when tilting down from facing -Z
  expectVec(down[1], {0, 0, -1});  // screen top points along -Z
  expectVec(-down[2], {0, -1, 0});
  const glm::dmat3 up = lookOrientation({0, 2, 0});
  expectOrthonormal(up);
  expectVec(up[0], {1, 0, 0});
  expectVec(up[1], {0, 0, 1});
  const glm::dmat3 none = lookOrientation({0, 0, 0});
  expectVec(-none[2], {0, 0, -1});
}

TEST(CameraCut, FlagsOnlyTheCutFrameAndSwitchesPoseFromThenOn) {
  CameraSpec c = straightCamera();
  c.cuts = {{5, {10, 0, 0}, {10, 0, 10}}, {9, {0, 3, 0}, {1, 3, 0}}};
  for (int f = 0; f < 12; ++f) EXPECT_EQ(cutStartsAt(c, f), f == 5 || f == 9) << f;
  EXPECT_EQ(activeCut(c, 4), -1);
  EXPECT_EQ(activeCut(c, 5), 0);
  EXPECT_EQ(activeCut(c, 8), 0);
  EXPECT_EQ(activeCut(c, 100), 1);
  expectVec(poseAt(c, 4).position, {0, 0, 0});
  expectVec(poseAt(c, 5).position, {10, 0, 0});
  expectVec(poseAt(c, 5).forward(), {0, 0, 1});
  expectVec(poseAt(c, 8).position, {10, 0, 0});
  expectVec(poseAt(c, 9).forward(), {1, 0, 0});
}

TEST(CameraRotate, PositiveYawTurnsLeftAboutWorldUp) {
  CameraSpec c = straightCamera();
  c.rotate.yaw_deg_per_s = 90.0f;
  expectVec(poseAt(c, 60).forward(), {-1, 0, 0});  // t=1: 90 degrees
  expectVec(poseAt(c, 120).forward(), {0, 0, 1});  // t=2: 180 degrees
  expectVec(poseAt(c, 30).forward(), {-std::sqrt(0.5), 0, -std::sqrt(0.5)});
}

TEST(CameraRotate, PitchIsATriangleWaveBetweenPlusAndMinusThirtyDegrees) {
  const double t[] = {0.0, 0.5, 1.0, 1.5, 2.0, 3.0, 4.0, 5.0};
  const double expected[] = {0, 15, 30, 15, 0, -30, 0, 30};
  for (int i = 0; i < 8; ++i) EXPECT_NEAR(pitchDegrees(30.0, t[i]), expected[i], 1e-12) << t[i];
  EXPECT_NEAR(pitchDegrees(-30.0, 1.0), -30.0, 1e-12);  // a negative rate starts downwards
  CameraSpec c = straightCamera();
  c.rotate.pitch_deg_per_s = 30.0f;
  const CameraPose p = poseAt(c, 60);  // t=1: fully up
  expectVec(p.forward(), {0, std::sin(glm::radians(30.0)), -std::cos(glm::radians(30.0))});
  expectOrthonormal(p.orientation);
}

TEST(CameraRotate, PitchAppliesAboutTheYawedRightAxis) {
  CameraSpec c = straightCamera();
  c.rotate.yaw_deg_per_s = 90.0f;
  c.rotate.pitch_deg_per_s = 30.0f;
  const CameraPose p = poseAt(c, 60);  // facing -X, pitched up 30 degrees
  expectVec(p.forward(), {-std::cos(glm::radians(30.0)), std::sin(glm::radians(30.0)), 0});
  EXPECT_NEAR(p.right().y, 0.0, 1e-12);  // the horizon stays level
}

TEST(CameraBob, VerticalOffsetIsAmplitudeTimesSine) {
  CameraSpec c = straightCamera();
  c.bob.amplitude = 0.5f;
  c.bob.frequency_hz = 1.0f;
  EXPECT_NEAR(poseAt(c, 15).position.y, 0.5, 1e-12);   // t=0.25
  EXPECT_NEAR(poseAt(c, 30).position.y, 0.0, 1e-12);   // t=0.5
  EXPECT_NEAR(poseAt(c, 45).position.y, -0.5, 1e-12);  // t=0.75
  EXPECT_NEAR(poseAt(c, 10).position.y, 0.5 * std::sin(glm::pi<double>() / 3), 1e-12);
}

TEST(CameraStrafe, TriangleWaveAlongTheRightVector) {
  CameraSpec c = straightCamera();
  c.strafe.speed = 2.0f;
  c.strafe.distance = 1.0f;
  expectVec(poseAt(c, 15).position, {0.5, 0, 0});  // t=0.25
  expectVec(poseAt(c, 30).position, {1, 0, 0});    // t=0.5: right turning point
  expectVec(poseAt(c, 60).position, {0, 0, 0});    // t=1
  expectVec(poseAt(c, 90).position, {-1, 0, 0});   // t=1.5: left turning point
  expectVec(poseAt(c, 120).position, {0, 0, 0});   // t=2
  c.target = {1.0f, 0.0f, 0.0f};                   // facing +X: right is +Z
  expectVec(poseAt(c, 30).position, {0, 0, 1});
}

TEST(CameraStrafe, ZeroDistanceStrafesAtConstantVelocity) {
  CameraSpec c = straightCamera();
  c.strafe.speed = 2.0f;
  expectVec(poseAt(c, 180).position, {6, 0, 0});  // t=3
}

TEST(CameraPath, PathReplacesPositionAndLookAlongFacesTheTangent) {
  CameraSpec c = straightCamera();
  c.path.type = taa::spec::CurveType::CatmullRom;
  c.path.points = {{0, 1, 0}, {4, 1, 0}};  // a straight line along +X
  c.path.duration_s = 2.0f;
  c.path.look = LookMode::Along;
  const CameraPose p = poseAt(c, 60);  // t=1: halfway
  expectVec(p.position, {2, 1, 0});
  expectVec(p.forward(), {1, 0, 0});
}

TEST(CameraPath, LookTargetFacesTheBaseTargetAndFixedKeepsBaseOrientation) {
  CameraSpec c = straightCamera();
  c.target = {2.0f, 1.0f, 5.0f};
  c.path.points = {{0, 1, 0}, {4, 1, 0}};
  c.path.duration_s = 2.0f;
  c.path.look = LookMode::Target;
  expectVec(poseAt(c, 60).forward(), {0, 0, 1});  // from (2,1,0) to (2,1,5)
  c.path.look = LookMode::Fixed;
  const glm::dvec3 base = glm::normalize(glm::dvec3(2, 1, 5));
  expectVec(poseAt(c, 60).forward(), base);
  expectVec(poseAt(c, 60).position, {2, 1, 0});
}

TEST(CameraProjection, ReversedZMapsNearToOneAndFarToZero) {
  const glm::mat4 p = reversedZPerspective(glm::radians(60.0f), 1.5f, 0.1f, 1000.0f);
  EXPECT_NEAR(worldToPixel(p, {0, 0, -0.1}, {2, 2}).z, 1.0, 1e-6);
  EXPECT_NEAR(worldToPixel(p, {0, 0, -1000}, {2, 2}).z, 0.0, 1e-6);
  EXPECT_GT(worldToPixel(p, {0, 0, -1}, {2, 2}).z, worldToPixel(p, {0, 0, -2}, {2, 2}).z);
}

TEST(CameraProjection, ExtremeNearAndFarStayInsideUnitDepthRange) {
  const float n = 1e-4f, f = 1e6f;
  const glm::mat4 p = reversedZPerspective(glm::radians(60.0f), 16.0f / 9.0f, n, f);
  // Evaluated in float, as the GPU does.
  auto depth = [&](float d) {
    const glm::vec4 c = p * glm::vec4(0.0f, 0.0f, -d, 1.0f);
    return c.z / c.w;
  };
  EXPECT_NEAR(depth(n), 1.0f, 1e-6f);
  EXPECT_NEAR(depth(f), 0.0f, 1e-6f);
  float prev = 2.0f;
  for (float d = n; d <= f; d *= 3.0f) {
    const float z = depth(d);
    EXPECT_GE(z, 0.0f) << d;
    EXPECT_LE(z, 1.0f) << d;
    EXPECT_LT(z, prev) << d;  // strictly decreasing: distinct depths stay distinct
    prev = z;
  }
  // Reversed Z keeps far geometry apart: 1% apart at 1e5 units is still resolved.
  EXPECT_GT(depth(1.0e5f), depth(1.01e5f));
}

TEST(CameraProjection, YIsFlippedSoWorldUpIsTheTopRow) {
  const glm::mat4 p = reversedZPerspective(glm::radians(90.0f), 1.0f, 0.1f, 100.0f);
  const glm::dvec3 above = worldToPixel(p, {0, 1, -2}, {100, 100});
  const glm::dvec3 right = worldToPixel(p, {1, 0, -2}, {100, 100});
  EXPECT_NEAR(above.x, 50.0, 1e-4);
  EXPECT_NEAR(above.y, 25.0, 1e-4);  // tan(45)=1: half way from centre to the top
  EXPECT_NEAR(right.x, 75.0, 1e-4);
  EXPECT_NEAR(right.y, 50.0, 1e-4);
}
