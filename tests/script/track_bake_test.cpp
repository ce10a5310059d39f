// Bake then replay: a case's motion written as a track and replayed by a case that
// names it gives the same FrameState bits for every frame and the same rendered
// pixels (colorSha256), including jitter, movers and camera cuts.
#include "script/track_bake.h"

#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "case/case_loader.h"
#include "frame_state_bytes.h"
#include "script/frame_state.h"
#include "support/gpu.h"
#include "support/process.h"
#include "support/text.h"
#include "track_test_util.h"

namespace taa::script {
namespace {

using taa::test::readFile;

namespace fs = std::filesystem;

// Jitter, a teleporting cut, every procedural camera motion and three kinds of mover.
const char* kBusy = R"({
  "scene": {"builtin": "checkerboard"},
  "render": {"width": 96, "height": 54},
  "script": {"fps": 30, "frames": 12, "reset_history_at": [3]},
  "camera": {"position": [0, 1.6, 6], "target": [0, 0.5, 0], "fov_y_deg": 55, "near": 0.05,
             "far": 400, "rotate": {"yaw_deg_per_s": 20, "pitch_deg_per_s": 15},
             "bob": {"amplitude": 0.05, "frequency_hz": 2}, "strafe": {"speed": 1, "distance": 0.3},
             "cuts": [{"frame": 7, "position": [4, 2, 3], "target": [0, 0.3, 0]}]},
  "movers": [
    {"shape": "cube", "start": [-2, 0.5, 0], "end": [2, 0.5, 0], "speed": 3, "rotation_speed_deg": 90},
    {"shape": "sphere", "size": 0.6, "start": [0, 0.4, 2], "end": [0, 0.4, -2], "speed": 0.2,
     "speed_unit": "per_frame", "repeat": "cyclic", "continuous_rotation": false,
     "rotation_speed_deg": 40}
  ],
  "jitter": {"pattern": "halton", "length": 8},
  "output": {"frames": [0, 6, 7, 11]}
})";

// The replay case: the original with its camera and mover motion replaced by the track.
std::string replayJson(const std::string& original, const std::string& track) {
  auto j = nlohmann::json::parse(original);
  j["camera"] = {{"track", track}};
  if (!j.contains("movers")) return j.dump(2);
  for (auto& m : j["movers"]) {
    nlohmann::json kept = {{"track", track}};
    for (const char* key : {"shape", "gltf", "color", "animation_speed"})
      if (m.contains(key)) kept[key] = m[key];
    m = kept;
  }
  return j.dump(2);
}

struct Pair {
  spec::CaseSpec original, replay;
};

Pair bakeAndReplay(const std::string& json) {
  const fs::path dir = test::trackScratch();
  Pair p{cases::parseCase(json, dir / "original.json").spec, {}};
  test::writeText(dir / "baked.track.json", bakeTrackJson(p.original, "test bake"));
  p.replay = cases::parseCase(replayJson(json, "baked.track.json"), dir / "replay.json").spec;
  return p;
}

void expectSameFrameStates(const Pair& p) {
  ASSERT_TRUE(p.replay.tracks);
  for (int f = 0; f < p.original.script.frames; ++f)
    ASSERT_EQ(test::frameStateBytes(frameState(p.original, f)),
              test::frameStateBytes(frameState(p.replay, f)))
        << "frame " << f;
}

TEST(TrackBake, ReplayGivesBitIdenticalFrameStates) {
  const Pair p = bakeAndReplay(kBusy);
  expectSameFrameStates(p);
  EXPECT_TRUE(frameState(p.replay, 7).cameraCut);
  EXPECT_FALSE(frameState(p.replay, 6).cameraCut);
}

TEST(TrackBake, ReplayOfACurveFlyThroughIsBitIdentical) {
  // Several curve types and look modes over many frames: each frame's quaternion must
  // replay its view matrix exactly.
  for (
      const char* path :
      {R"({"type": "catmull_rom", "points": [[-4, 2, 7], [0, 1.6, 5], [3, 2.2, 3], [4, 1.8, -1]], "duration_s": 1.5})",
       R"({"type": "bspline3", "cyclic": true, "look": "target", "duration_s": 0.7, "points": [[0, 2, 8], [3, 2, 4], [0, 3, 0], [-4, 2, 2], [-2, 1, 6]]})",
       R"({"type": "bezier", "look": "fixed", "points": [[0, 9, 0.01], [0, 1, 0], [1, 5, 1]]})"}) {
    const Pair p = bakeAndReplay(std::string(R"({"script": {"fps": 144, "frames": 200},
        "jitter": {"pattern": "uniform4"}, "camera": {"path": )") +
                                 path + "}}");
    expectSameFrameStates(p);
  }
}

TEST(TrackBake, RebakingATrackCaseKeepsItsFrames) {
  const std::string csvCase = R"({"script": {"fps": 60, "frames": 48},
      "camera": {"track": "capture.csv"}, "movers": [{"track": "capture_mover.csv"}]})";
  const fs::path dir = test::trackScratch();
  for (const char* f : {"capture.csv", "capture_mover.csv"})
    fs::copy_file(fs::path(TAA_SOURCE_DIR) / "cases" / "tracks" / f, dir / f);
  const auto original = cases::parseCase(csvCase, dir / "original.json").spec;
  test::writeText(dir / "baked.json", bakeTrackJson(original, "rebake"));
  const auto replay = cases::parseCase(replayJson(csvCase, "baked.json"), dir / "replay.json").spec;
  expectSameFrameStates({original, replay});
  EXPECT_TRUE(frameState(replay, 34).cameraCut);
}

TEST(TrackBake, RenderedFramesAreBitIdentical) {
  const Pair p = bakeAndReplay(kBusy);
  const std::vector<int> frames = {0, 3, 6, 7, 8, 11};
  const auto a = test::renderCase(p.original, frames);
  const auto b = test::renderCase(p.replay, frames);
  ASSERT_EQ(a.size(), b.size());
  std::set<std::string> distinct;
  for (int f : frames) {
    ASSERT_TRUE(a[f].hasImages && b[f].hasImages);
    EXPECT_EQ(a[f].colorSha256, b[f].colorSha256) << "frame " << f;
    EXPECT_EQ(a[f].cameraCut, b[f].cameraCut);
    distinct.insert(a[f].colorSha256);
  }
  EXPECT_EQ(distinct.size(), frames.size());  // the frames differ, so equality means something
}

TEST(TrackBake, ShippedBakedCaseIsCurrentAndReplaysItsSource) {
  const fs::path cases = fs::path(TAA_SOURCE_DIR) / "cases";
  const auto source = cases::loadCase(cases / "tracks" / "flythrough_source.json").spec;
  const auto replay = cases::loadCase(cases / "track_baked_flythrough.json").spec;
  const std::string committed = readFile(cases / "tracks" / "flythrough.track.json");
  const std::string description = parseJsonTrack(committed, "committed").description;
  EXPECT_EQ(bakeTrackJson(source, description), committed)
      << "re-bake: taa-harness bake cases/tracks/flythrough_source.json --out "
         "cases/tracks/flythrough.track.json";
  expectSameFrameStates({source, replay});
  const auto a = test::renderCase(source, {0, 15, 31});
  const auto b = test::renderCase(replay, {0, 15, 31});
  for (int f : {0, 15, 31}) EXPECT_EQ(a[f].colorSha256, b[f].colorSha256) << "frame " << f;
}

TEST(TrackBake, CommandWritesTheTrackAndRejectsBadCases) {
  const fs::path dir = test::trackScratch();
  test::writeText(dir / "busy.json", kBusy);
  const auto ok = test::runHarness("bake " + (dir / "busy.json").string() + " --out " +
                                   (dir / "out" / "busy.track.json").string());
  ASSERT_EQ(ok.exitCode, 0) << ok.output;
  const auto original = cases::parseCase(kBusy, dir / "busy.json").spec;
  EXPECT_EQ(
      readFile(dir / "out" / "busy.track.json"),
      bakeTrackJson(original, "baked by taa-harness bake from busy.json: 12 frames at 30 fps"));
  test::writeText(dir / "bad.json", R"({"camera": {"track": "nothing.csv"}})");
  const auto bad = test::runHarness("bake " + (dir / "bad.json").string() + " --out " +
                                    (dir / "bad.track.json").string());
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_TRUE(test::contains(bad.output, "nothing.csv: the track does not exist"));
  EXPECT_EQ(test::runHarness("bake " + (dir / "busy.json").string()).exitCode, 2);
}

}  // namespace
}  // namespace taa::script
