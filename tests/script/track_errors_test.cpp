// Every class of bad track is rejected with a message naming the file and the line,
// key or frame at fault: NaN or Inf values, non-unit quaternions, missing or repeated
// timestamps, and a track shorter than the case. The last tests go through the case
// loader, which is what users see (exit code 2).
#include <gtest/gtest.h>

#include "case/case_error.h"
#include "case/case_loader.h"
#include "script/track_csv.h"
#include "script/track_json.h"
#include "track_test_util.h"

namespace taa::script {
namespace {

using test::contains;
using test::errorOf;

const std::string kHeader = "time,px,py,pz,qx,qy,qz,qw\n";

std::string csvError(const std::string& rows) {
  return errorOf<TrackError>(
      [&] { checkTrack(parseCsvTrack(kHeader + rows, "cap.csv", TrackSubject::Camera)); });
}

std::string jsonError(const std::string& frames, const std::string& top = "") {
  return errorOf<TrackError>([&] {
    const TrackFile f = parseJsonTrack(R"({"format": "taa-track", "version": 1, )" + top +
                                           R"("camera": {"frames": [)" + frames + "]}}",
                                       "t.json");
    checkTrack(*f.camera);
  });
}

TEST(TrackErrors, NanAndInfinity) {
  EXPECT_TRUE(contains(csvError("0,0,0,0,0,0,0,1\n0.1,nan,0,0,0,0,0,1\n"),
                       "cap.csv:3: column px: 'nan' is not a finite number"));
  EXPECT_TRUE(contains(csvError("0,0,0,0,0,0,0,1\n0.1,0,-inf,0,0,0,0,1\n"),
                       "cap.csv:3: column py: '-inf' is not a finite number"));
  EXPECT_TRUE(contains(csvError("0,0,0,0,0,0,0,1\n0.1,0,0,1e999,0,0,0,1\n"),
                       "cap.csv:3: column pz: '1e999' is not a finite number"));
  // JSON has no NaN or Infinity; what exporters write instead is a syntax error there.
  EXPECT_TRUE(
      contains(jsonError(R"({"t": 0, "position": [0, 1e999, 0], "orientation": [0, 0, 0, 1]})"),
               "t.json: not valid JSON (number overflow)"));
  EXPECT_TRUE(contains(jsonError(R"({"t": 0,
      "position": [0, NaN, 0], "orientation": [0, 0, 0, 1]})"),
                       "t.json:2:"));
}

TEST(TrackErrors, NonUnitQuaternion) {
  EXPECT_TRUE(contains(csvError("0,0,0,0,0,0,0,1\n0.1,0,0,0,0,0,0,0.9\n"),
                       "cap.csv:3: the orientation quaternion (x, y, z, w) has length 0.9"));
  // Euler angles in the quaternion columns: the typical exporter mistake.
  EXPECT_TRUE(
      contains(jsonError(R"({"t": 0, "position": [0, 0, 0], "orientation": [10, 45, 0, 1]})"),
               "t.json: camera.frames[0]: the orientation quaternion"));
  // Within the tolerance (7 printed digits) passes.
  EXPECT_NO_THROW(checkTrack(parseCsvTrack(kHeader + "0,0,0,0,0.7071068,0,0,0.7071068\n", "cap.csv",
                                           TrackSubject::Camera)));
}

TEST(TrackErrors, MissingTimestamps) {
  EXPECT_TRUE(contains(csvError("0,0,0,0,0,0,0,1\n,0,0,0,0,0,0,1\n"),
                       "cap.csv:3: missing timestamp (column time is empty)"));
  EXPECT_TRUE(contains(jsonError(R"({"t": 0, "position": [0, 0, 0], "orientation": [0, 0, 0, 1]},
                                   {"position": [0, 0, 0], "orientation": [0, 0, 0, 1]})"),
                       "t.json: camera.frames[1]: missing timestamp \"t\""));
  const std::string frames = errorOf<TrackError>([] {
    parseCsvTrack(
        "# fps: 60\nframe,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n1,0,0,0,0,0,0,1\n"
        "4,0,0,0,0,0,0,1\n",
        "cap.csv", TrackSubject::Camera);
  });
  EXPECT_TRUE(contains(frames, "cap.csv:5: frames 2 to 3 are missing (line 4 has frame 1)"));
}

TEST(TrackErrors, RepeatedOrDecreasingTimestamps) {
  EXPECT_TRUE(contains(csvError("0,0,0,0,0,0,0,1\n0.1,0,0,0,0,0,0,1\n0.1,0,0,0,0,0,0,1\n"),
                       "cap.csv:4: timestamp 0.1 s repeats the one at cap.csv:3"));
  EXPECT_TRUE(contains(csvError("0,0,0,0,0,0,0,1\n0.2,0,0,0,0,0,0,1\n0.1,0,0,0,0,0,0,1\n"),
                       "cap.csv:4: timestamp 0.1 s comes before 0.2 s at cap.csv:3"));
  EXPECT_TRUE(contains(jsonError(R"({"t": 0.5, "position": [0, 0, 0], "orientation": [0, 0, 0, 1]},
                                   {"t": 0.5, "position": [0, 0, 0], "orientation": [0, 0, 0, 1]})"),
                       "t.json: camera.frames[1]: timestamp 0.5 s repeats the one at t.json: "
                       "camera.frames[0]"));
  const std::string frames = errorOf<TrackError>([] {
    parseCsvTrack("# fps: 60\nframe,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n0,0,0,0,0,0,0,1\n",
                  "cap.csv", TrackSubject::Camera);
  });
  EXPECT_TRUE(contains(frames, "cap.csv:4: frame 0 repeats (line 3 has frame 0)"));
}

// A case in a scratch folder replaying `track` (written as cap.csv beside it).
std::string caseError(const std::string& track, const std::string& caseExtra) {
  const auto dir = test::trackScratch();
  test::writeText(dir / "cap.csv", track);
  const std::string json =
      R"({"scene": {"builtin": "checkerboard"}, "script": {"fps": 60, "frames": 30},
    "camera": {"track": "cap.csv")" +
      caseExtra + "}}";
  return errorOf<cases::CaseError>([&] { cases::parseCase(json, dir / "case.json"); });
}

TEST(TrackErrors, TrackShorterThanTheCaseNamesTheFrame) {
  std::string rows = kHeader;
  for (int i = 0; i <= 18; ++i) rows += std::to_string(i / 40.0) + ",0,0,0,0,0,0,1\n";
  const std::string e = caseError(rows, "");
  EXPECT_TRUE(contains(e, "case.json: camera.track: "));
  EXPECT_TRUE(contains(e, "cap.csv: frame 28 replays t = 0.4666666"));
  EXPECT_TRUE(contains(e, "outside the track's 0 .. 0.45 s; the track is shorter than the case"));
  // The offset counts: starting late runs out sooner, before the first sample too.
  EXPECT_TRUE(contains(caseError(rows, R"(, "track_time_offset_s": -0.1)"),
                       "frame 0 replays t = -0.1 s (track_time_offset_s + frame / 60)"));
}

TEST(TrackErrors, CaseLoaderNamesTheCaseKeyAndTheTrackLine) {
  const std::string e = caseError(kHeader + "0,0,0,0,0,0,0,1\n0.1,0,0,0,0,0,0,2\n", "");
  EXPECT_TRUE(contains(e, "case.json: camera.track: "));
  EXPECT_TRUE(contains(e, "cap.csv:3: the orientation quaternion (x, y, z, w) has length 2"));
}

}  // namespace
}  // namespace taa::script
