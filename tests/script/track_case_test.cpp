// Tracks in case files: the keys a track replaces are errors when also set, paths obey
// the asset rule, tracks load once with the case, and the shipped cases replay.
#include <gtest/gtest.h>

#include "case/case_error.h"
#include "case/case_loader.h"
#include "script/frame_state.h"
#include "script/tracks.h"
#include "support/gpu.h"
#include "track_test_util.h"

namespace taa::script {
namespace {

using test::contains;

std::string problemsOf(const std::string& json) {
  return test::errorOf<cases::CaseError>([&] { test::caseFromJson(json, "track_rules"); });
}

TEST(TrackCase, SettingsATrackReplacesAreErrors) {
  const std::string e = problemsOf(R"({"camera": {"track": "tracks/capture.csv",
      "position": [0, 1, 2], "path": {"points": [[0, 0, 0], [1, 1, 1]]}, "cuts": [{"frame": 1}]},
      "movers": [{"track": "tracks/capture_mover.csv", "speed": 2, "size": 3}]})");
  for (const char* key :
       {"camera.position", "camera.path", "camera.cuts", "movers[0].speed", "movers[0].size"})
    EXPECT_TRUE(contains(e, std::string("cases/track_rules.json: ") + key + ": ")) << key;
  EXPECT_TRUE(contains(e, "camera.track replaces it"));
}

TEST(TrackCase, LensKeysATrackCarriesAreErrors) {
  // capture.csv has a fov_y_deg column but no near/far: camera.near stays allowed.
  const std::string e = problemsOf(R"({"script": {"frames": 10},
      "camera": {"track": "tracks/capture.csv", "fov_y_deg": 40, "near": 0.2}})");
  EXPECT_TRUE(contains(e, "camera.fov_y_deg: the camera track carries fov_y_deg for every frame"));
  EXPECT_FALSE(contains(e, "camera.near:"));
  const auto ok = test::caseFromJson(
      R"({"script": {"frames": 10}, "camera": {"track": "tracks/capture.csv", "near": 0.2}})",
      "track_rules");
  EXPECT_EQ(frameState(ok, 3).camera.nearPlane, 0.2f);
}

TEST(TrackCase, TrackOnlyKeysNeedATrack) {
  const std::string e = problemsOf(R"({"camera": {"track_camera": "Cam", "track_time_offset_s": 1},
      "movers": [{"track_time_offset_s": 1}]})");
  EXPECT_TRUE(contains(e, "camera.track_camera: set but camera.track is not"));
  EXPECT_TRUE(contains(e, "camera.track_time_offset_s: set but camera.track is not"));
  EXPECT_TRUE(contains(e, "movers[0].track_time_offset_s: set but movers[0].track is not"));
  EXPECT_TRUE(
      contains(problemsOf(R"({"camera": {"track": "tracks/capture.csv", "track_camera": "C"}})"),
               "camera.track_camera: names a glTF camera node, but camera.track is not"));
}

TEST(TrackCase, PathsStayInsideTheCaseFolder) {
  EXPECT_TRUE(contains(problemsOf(R"({"camera": {"track": "../outside.csv"}})"),
                       "camera.track: '../outside.csv' leaves the case's folder"));
  EXPECT_TRUE(
      contains(problemsOf(R"({"camera": {"track": "https://example.com/t.csv"}})"), "is a URI"));
  EXPECT_TRUE(contains(problemsOf(R"({"camera": {"track": "tracks/capture.txt"}})"),
                       "camera.track: 'tracks/capture.txt' is not a track file"));
  EXPECT_TRUE(contains(problemsOf(R"({"movers": [{"track": "tracks/camera_anim.gltf"}]})"),
                       "movers[0].track: 'tracks/camera_anim.gltf' is not a track file"));
  EXPECT_TRUE(contains(problemsOf(R"({"camera": {"track": "tracks/missing.csv"}})"),
                       "missing.csv: the track does not exist"));
}

TEST(TrackCase, UnloadedTracksAreALogicErrorNotASilentScript) {
  auto spec = test::caseFromJson(
      R"({"script": {"frames": 10}, "camera": {"track": "tracks/capture.csv"}})", "track_rules");
  EXPECT_NO_THROW(frameState(spec, 9));
  EXPECT_THROW(frameState(spec, 10), std::out_of_range);  // the recording ends there
  spec.script.frames = 12;  // edited after loading: the tracks no longer fit
  EXPECT_THROW(frameState(spec, 0), std::logic_error);
  spec.tracks = std::make_shared<const Tracks>(loadTracks(spec));
  EXPECT_NO_THROW(frameState(spec, 11));
}

TEST(TrackCase, ShippedCsvCaptureCaseReplaysWithItsCut) {
  const auto loaded =
      cases::loadCase(std::filesystem::path(TAA_SOURCE_DIR) / "cases" / "track_csv_capture.json");
  const auto& spec = loaded.spec;
  ASSERT_TRUE(spec.tracks);
  int cuts = 0;
  for (int f = 0; f < spec.script.frames; ++f) {
    const FrameState fs = frameState(spec, f);
    if (fs.cameraCut) {
      ++cuts;
      EXPECT_EQ(f, 34) << "capture.csv's cut at t = 0.556 s is first replayed at frame 34";
      EXPECT_TRUE(fs.resetHistory);
    }
    ASSERT_EQ(fs.movers.size(), 1u);
  }
  EXPECT_EQ(cuts, 1);
  // The capture zooms: 60 - 8 t degrees, linearly resampled.
  EXPECT_NEAR(frameState(spec, 30).camera.fovY, glm::radians(60.0f - 8.0f * 0.5f), 2e-6f);
  // The mover circles at radius 1.8 (7 printed digits, linearly resampled).
  EXPECT_NEAR(glm::length(glm::vec2(frameState(spec, 20).movers[0][3].x,
                                    frameState(spec, 20).movers[0][3].z)),
              1.8f, 2e-3f);
}

}  // namespace
}  // namespace taa::script
