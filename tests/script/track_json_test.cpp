// The JSON track format: lossless round trip (what bit-identical replay rests on),
// timing by fps or per-frame "t", and key errors named by path.
#include "script/track_json.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "track_test_util.h"

namespace taa::script {
namespace {

using test::contains;
using test::errorOf;

template <class T>
bool sameBits(const T& a, const T& b) {
  return std::memcmp(&a, &b, sizeof(T)) == 0;
}

TEST(TrackJson, RoundTripKeepsEveryBit) {
  TrackFile f;
  f.fps = 60;
  f.description = "round trip";
  RawTrack cam;
  cam.hasFov = cam.hasNear = cam.hasFar = true;
  RawTrack mover;
  uint32_t x = 12345;
  auto next = [&x] {  // deterministic awkward numbers
    x = x * 1664525u + 1013904223u;
    return (double(x) / 4294967296.0 - 0.5) * std::pow(10.0, double(x % 9) - 4.0);
  };
  for (int k = 0; k < 50; ++k) {
    TrackSample s;
    s.time = k / 60.0;
    s.position = {next(), next(), next()};
    s.orientation = glm::normalize(glm::dquat(next(), next(), next(), next()));
    s.fovYDeg = float(40.0 + std::fabs(next()));
    s.nearPlane = float(0.01 + std::fabs(next()) * 1e-3);
    s.farPlane = float(1000.0 + std::fabs(next()));
    s.cut = k % 17 == 5;
    if (k % 2) {  // a baked camera: the rotation matrix beside its quaternion
      s.basis = orientationFromQuat(s.orientation);
      s.orientation = quatFromOrientation(*s.basis);
    }
    cam.samples.push_back(s);
    TrackSample m;
    m.time = s.time;
    glm::mat4 matrix;
    for (int i = 0; i < 16; ++i) matrix[i / 4][i % 4] = float(next());
    m.matrix = matrix;
    mover.samples.push_back(m);
  }
  f.camera = cam;
  f.movers = {mover};
  const TrackFile back = parseJsonTrack(writeJsonTrack(f), "rt.json");
  ASSERT_TRUE(back.camera);
  ASSERT_EQ(back.movers.size(), 1u);
  EXPECT_EQ(back.fps, 60.0);
  EXPECT_EQ(back.description, "round trip");
  EXPECT_TRUE(back.camera->hasFov && back.camera->hasNear && back.camera->hasFar);
  for (int k = 0; k < 50; ++k) {
    const TrackSample& a = cam.samples[k];
    const TrackSample& b = back.camera->samples[k];
    EXPECT_TRUE(sameBits(a.time, b.time)) << k;
    EXPECT_TRUE(sameBits(a.position, b.position)) << k;
    EXPECT_TRUE(sameBits(a.orientation, b.orientation)) << k;
    EXPECT_TRUE(sameBits(a.fovYDeg, b.fovYDeg) && sameBits(a.nearPlane, b.nearPlane) &&
                sameBits(a.farPlane, b.farPlane))
        << k;
    EXPECT_EQ(a.cut, b.cut) << k;
    ASSERT_EQ(bool(a.basis), bool(b.basis)) << k;
    if (a.basis) {
      EXPECT_TRUE(sameBits(*a.basis, *b.basis)) << k;
    }
    ASSERT_TRUE(back.movers[0].samples[k].matrix);
    EXPECT_TRUE(sameBits(*mover.samples[k].matrix, *back.movers[0].samples[k].matrix)) << k;
  }
}

TEST(TrackJson, TimestampedFramesAndMoverTransforms) {
  const TrackFile f = parseJsonTrack(R"({"format": "taa-track", "version": 1,
    "camera": {"frames": [{"t": 0.25, "position": [1, 2, 3], "orientation": [0, 0, 0, 1]}]},
    "movers": [{"frames": [{"t": 0, "position": [1, 0, 0], "orientation": [0, 0, 0, 1],
                            "scale": [2, 2, 2]}]}]})",
                                     "t.json");
  EXPECT_EQ(f.camera->samples[0].time, 0.25);
  EXPECT_FALSE(f.camera->hasFov);
  EXPECT_EQ(f.movers[0].samples[0].scale, glm::dvec3(2.0));
  EXPECT_EQ(sampleMatrix(f.movers[0].samples[0])[0][0], 2.0f);
  EXPECT_EQ(sampleMatrix(f.movers[0].samples[0])[3][0], 1.0f);
}

std::string error(const std::string& body) {
  return errorOf<TrackError>([&] { parseJsonTrack(body, "t.json"); });
}

// Any positive rate is a rate: a time-lapse track at half a frame a second spaces its frames
// two seconds apart; zero, a negative rate and a string are refused.
TEST(TrackJson, AnyPositiveFrameRateTimesTheFrames) {
  const std::string camera = R"("camera": {"frames": [
      {"position": [0, 0, 0], "orientation": [0, 0, 0, 1]},
      {"position": [1, 0, 0], "orientation": [0, 0, 0, 1]}]}})";
  const std::string head = R"({"format": "taa-track", "version": 1, "fps": )";
  const TrackFile f = parseJsonTrack(head + "0.5, " + camera, "t.json");
  EXPECT_EQ(f.fps, 0.5);
  ASSERT_EQ(f.camera->samples.size(), 2u);
  EXPECT_EQ(f.camera->samples[1].time, 2.0);
  for (const char* bad : {"0", "-30", "\"30\""})
    EXPECT_TRUE(
        contains(error(head + bad + ", " + camera), "t.json: fps: expected a positive frame rate"))
        << bad;
}

TEST(TrackJson, ErrorsNameTheKeyPath) {
  EXPECT_TRUE(contains(error(R"({"camera": {}})"), "t.json: not a track file"));
  const std::string head = R"({"format": "taa-track", "version": 1, )";
  EXPECT_TRUE(contains(
      error(
          head +
          R"("fps": 60, "camera": {"frames": [{"t": 0, "position": [0, 0, 0], "orientation": [0, 0, 0, 1]}]}})"),
      "t.json: camera.frames[0].t: the file sets a top-level fps"));
  EXPECT_TRUE(contains(
      error(
          head +
          R"("fps": 60, "camera": {"frames": [{"position": [0, 0], "orientation": [0, 0, 0, 1]}]}})"),
      "t.json: camera.frames[0].position: expected an array of 3 numbers"));
  EXPECT_TRUE(contains(
      error(
          head +
          R"("fps": 60, "camera": {"frames": [{"position": [0, 0, 0], "orientation": [0, 0, 0, 1], "fov": 60}]}})"),
      "t.json: camera.frames[0].fov: unknown key"));
  EXPECT_TRUE(contains(error(head + R"("fps": 60, "camera": {"frames": [
      {"position": [0, 0, 0], "orientation": [0, 0, 0, 1], "fov_y_deg": 60},
      {"position": [0, 0, 0], "orientation": [0, 0, 0, 1]}]}})"),
                       "t.json: camera.frames[1]: has no fov_y_deg but frames[0] does"));
  EXPECT_TRUE(
      contains(error(head + R"("fps": 60, "movers": [{"frames": [{"matrix": [1, 0, 0, 0]}]}]})"),
               "t.json: movers[0].frames[0].matrix: expected an array of 16 numbers"));
  EXPECT_TRUE(contains(error("{\"format\": "), "t.json:1:11: not valid JSON"));
  EXPECT_TRUE(
      contains(error(head + R"("fps": 60, "camera": {"frames": [{"position": [0, 0, 0]}]}})"),
               "t.json: camera.frames[0]: missing \"orientation\""));
}

TEST(TrackJson, BasisMustBeARotationAgreeingWithItsQuaternion) {
  auto check = [](const std::string& frame) {
    return errorOf<TrackError>([&] {
      checkTrack(*parseJsonTrack(R"({"format": "taa-track", "version": 1, "fps": 30,
          "camera": {"frames": [)" + frame +
                                     "]}}",
                                 "b.json")
                      .camera);
    });
  };
  EXPECT_TRUE(contains(check(R"({"position": [0, 0, 0], "basis": [1, 0, 0, 0, 2, 0, 0, 0, 1]})"),
                       "b.json: camera.frames[0]: the basis is not a rotation"));
  EXPECT_TRUE(contains(check(R"({"position": [0, 0, 0], "basis": [1, 0, 0, 0, 1, 0, 0, 0, 1],
                                 "orientation": [0, 1, 0, 0]})"),
                       "the basis and the orientation quaternion disagree"));
  const TrackFile ok = parseJsonTrack(R"({"format": "taa-track", "version": 1, "fps": 30,
      "camera": {"frames": [{"position": [0, 0, 0], "basis": [0, 0, -1, 0, 1, 0, 1, 0, 0]}]}})",
                                      "b.json");
  checkTrack(*ok.camera);
  // Only a basis: its quaternion is derived (a quarter turn about +Y).
  EXPECT_NEAR(std::fabs(ok.camera->samples[0].orientation.y), std::sqrt(0.5), 1e-15);
}

}  // namespace
}  // namespace taa::script
