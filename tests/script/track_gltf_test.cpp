// Importing an animated glTF camera: cases/tracks/camera_anim.gltf holds "ShotCam", a
// perspective camera (yfov 0.9 rad, znear 0.05, zfar 200) under "Rig" (raised 1 unit),
// moving linearly through (0,0.6,6) -> (2,0.6,5) -> (4,1,3) at t = 0, 1, 2 s while
// yawing 0 -> 20 -> 40 degrees (make_track_assets.py).
#include "script/track_gltf.h"

#include <gtest/gtest.h>

#include <glm/trigonometric.hpp>

#include "script/frame_state.h"
#include "support/gpu.h"
#include "track_test_util.h"

namespace taa::script {
namespace {

const std::filesystem::path kFile =
    std::filesystem::path(TAA_SOURCE_DIR) / "cases" / "tracks" / "camera_anim.gltf";

glm::dvec3 forwardOf(const glm::dquat& q) {
  return orientationFromQuat(q) * glm::dvec3(0, 0, -1);
}

glm::dvec3 yawedForward(double degrees) {
  return {-std::sin(glm::radians(degrees)), 0.0, -std::cos(glm::radians(degrees))};
}

void expectNear(const glm::dvec3& a, const glm::dvec3& b, double tol) {
  EXPECT_NEAR(a.x, b.x, tol);
  EXPECT_NEAR(a.y, b.y, tol);
  EXPECT_NEAR(a.z, b.z, tol);
}

TEST(TrackGltf, CameraNodeWorldPoseAtKnownTimes) {
  const RawTrack t = gltfCameraTrack(kFile, "ShotCam", {0.0, 0.5, 1.0, 1.5, 2.0});
  checkTrack(t);
  ASSERT_EQ(t.samples.size(), 5u);
  // Float animation sampling: 1e-5 is a few float ulps at these magnitudes.
  const double tol = 1e-5;
  expectNear(t.samples[0].position, {0.0, 1.6, 6.0}, tol);  // parent's +1 in y included
  expectNear(t.samples[1].position, {1.0, 1.6, 5.5}, tol);
  expectNear(t.samples[3].position, {3.0, 1.8, 4.0}, tol);
  expectNear(t.samples[4].position, {4.0, 2.0, 3.0}, tol);
  expectNear(forwardOf(t.samples[0].orientation), yawedForward(0.0), tol);
  expectNear(forwardOf(t.samples[1].orientation), yawedForward(10.0), tol);
  expectNear(forwardOf(t.samples[4].orientation), yawedForward(40.0), tol);
  EXPECT_TRUE(t.hasFov && t.hasNear && t.hasFar);
  EXPECT_NEAR(t.samples[2].fovYDeg, glm::degrees(0.9), 1e-4);
  EXPECT_FLOAT_EQ(t.samples[2].nearPlane, 0.05f);
  EXPECT_FLOAT_EQ(t.samples[2].farPlane, 200.0f);
  // The only camera node is found without a name.
  EXPECT_EQ(gltfCameraTrack(kFile, "", {0.5}).samples[0].position, t.samples[1].position);
}

TEST(TrackGltf, ErrorsNameTheNodeOrTheFrame) {
  EXPECT_TRUE(
      test::contains(test::errorOf<TrackError>([] { gltfCameraTrack(kFile, "Cam", {0.0}); }),
                     "no node is named 'Cam'; camera nodes in the file: 'ShotCam'"));
  EXPECT_TRUE(
      test::contains(test::errorOf<TrackError>([] { gltfCameraTrack(kFile, "Rig", {0.0}); }),
                     "node 'Rig' has no camera"));
  EXPECT_TRUE(test::contains(test::errorOf<TrackError>([] {
                               gltfCameraTrack(kFile, "ShotCam", {1.0, 2.0, 2.5});
                             }),
                             "frame 2 replays t = 2.5 s, outside the animation's 0 .. 2 s"));
}

TEST(TrackGltf, CaseReplaysTheCameraAtItsFps) {
  const auto spec = test::caseFromJson(R"({"scene": {"builtin": "checkerboard"},
    "script": {"fps": 30, "frames": 61},
    "camera": {"track": "tracks/camera_anim.gltf", "track_camera": "ShotCam"}})",
                                       "track_gltf_case");
  ASSERT_TRUE(spec.tracks);
  const FrameState fs = frameState(spec, 15);  // t = 0.5 s
  EXPECT_NEAR(fs.camera.position.x, 1.0f, 1e-5f);
  EXPECT_NEAR(fs.camera.position.y, 1.6f, 1e-5f);
  EXPECT_NEAR(fs.camera.position.z, 5.5f, 1e-5f);
  EXPECT_NEAR(fs.camera.fovY, 0.9f, 1e-6f);
  EXPECT_EQ(fs.camera.nearPlane, 0.05f);
  EXPECT_EQ(fs.camera.farPlane, 200.0f);
  EXPECT_NEAR(frameState(spec, 60).camera.position.x, 4.0f, 1e-5f);
  // One frame past the 2 s animation is a track shorter than the case.
  EXPECT_THROW(test::caseFromJson(R"({"script": {"fps": 30, "frames": 62},
    "camera": {"track": "tracks/camera_anim.gltf"}})",
                                  "track_gltf_case"),
               std::exception);
}

}  // namespace
}  // namespace taa::script
