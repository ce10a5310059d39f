// CSV captures: columns, comments, the frame-numbered form, and every per-value
// problem named by file:line.
#include "script/track_csv.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "script/track_json.h"
#include "support/text.h"
#include "track_test_util.h"

namespace taa::script {
namespace {

using test::contains;
using test::errorOf;

RawTrack camera(const std::string& text) {
  return parseCsvTrack(text, "cap.csv", TrackSubject::Camera);
}

TEST(TrackCsv, ReadsColumnsInAnyOrderWithCommentsAndBlankLines) {
  const RawTrack t = camera(
      "# exported by an engine\n"
      "\n"
      "qw, qx,qy,qz, time, px,py,pz, fov_y_deg, near, far, cut\r\n"
      "1,0,0,0, 0.0, 1,2,3, 50, 0.05, 300, 0\r\n"
      "# a comment between rows\n"
      "0.7071068,0,0.7071068,0, 0.01, 4,5,6, 55.5, 0.05, 300, 1\n");
  ASSERT_EQ(t.samples.size(), 2u);
  EXPECT_TRUE(t.hasFov && t.hasNear && t.hasFar);
  const TrackSample& s = t.samples[1];
  EXPECT_EQ(s.time, 0.01);
  EXPECT_EQ(s.position, glm::dvec3(4, 5, 6));
  EXPECT_EQ(s.orientation.w, 0.7071068);
  EXPECT_EQ(s.orientation.y, 0.7071068);
  EXPECT_EQ(s.fovYDeg, 55.5f);
  EXPECT_EQ(s.nearPlane, 0.05f);
  EXPECT_EQ(s.farPlane, 300.0f);
  EXPECT_TRUE(s.cut);
  EXPECT_FALSE(t.samples[0].cut);
  EXPECT_EQ(s.where, "cap.csv:6");
  checkTrack(t);
}

TEST(TrackCsv, FrameColumnUsesTheFpsDirective) {
  const RawTrack t =
      camera("# fps: 144\nframe,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n1,0,0,1,0,0,0,1\n");
  ASSERT_EQ(t.samples.size(), 2u);
  EXPECT_EQ(t.samples[1].time, 1.0 / 144.0);
  EXPECT_FALSE(t.hasFov);
  // The space after the colon is optional.
  const RawTrack tight =
      camera("# fps:24\nframe,px,py,pz,qx,qy,qz,qw\n0,0,0,0,0,0,0,1\n1,0,0,1,0,0,0,1\n");
  EXPECT_EQ(tight.samples[1].time, 1.0 / 24.0);
}

TEST(TrackCsv, MoverScaleColumns) {
  const RawTrack t = parseCsvTrack("time,px,py,pz,qx,qy,qz,qw,sx,sy,sz\n0,1,2,3,0,0,0,1,2,3,4\n",
                                   "m.csv", TrackSubject::Mover);
  EXPECT_EQ(t.samples[0].scale, glm::dvec3(2, 3, 4));
}

// Excel's "CSV UTF-8" starts with a byte-order mark; JSON tracks take one through nlohmann.
TEST(TrackCsv, AByteOrderMarkBeforeTheHeaderIsAccepted) {
  const RawTrack t = camera("\xEF\xBB\xBFtime,px,py,pz,qx,qy,qz,qw\n0,1,2,3,0,0,0,1\n");
  ASSERT_EQ(t.samples.size(), 1u);
  EXPECT_EQ(t.samples[0].position, glm::dvec3(1, 2, 3));
  EXPECT_EQ(t.samples[0].where, "cap.csv:2");
  const std::string json = taa::test::readFile(std::filesystem::path(TAA_SOURCE_DIR) /
                                               "cases/tracks/flythrough.track.json");
  EXPECT_NO_THROW(parseJsonTrack("\xEF\xBB\xBF" + json, "flythrough.track.json"));
}

TEST(TrackCsv, HeaderProblemsNameTheLineAndTheFix) {
  EXPECT_TRUE(contains(errorOf<TrackError>([] { camera("time,px,py,pz,qx,qy,qz,qw,sx\n"); }),
                       "cap.csv:1: unknown column 'sx'; a camera track allows"));
  EXPECT_TRUE(contains(errorOf<TrackError>([] { camera("time,px,py,pz,qx,qy,qz\n"); }),
                       "cap.csv:1: missing column 'qw'"));
  EXPECT_TRUE(contains(errorOf<TrackError>([] { camera("frame,px,py,pz,qx,qy,qz,qw\n"); }),
                       "add a line '# fps: 60' above the header"));
  EXPECT_TRUE(contains(errorOf<TrackError>([] { camera("time,frame,px,py,pz,qx,qy,qz,qw\n"); }),
                       "exactly one of the columns time"));
  EXPECT_TRUE(contains(errorOf<TrackError>([] { camera("# only comments\n"); }),
                       "cap.csv: no header line"));
}

TEST(TrackCsv, RowProblemsNameTheLine) {
  const std::string h = "time,px,py,pz,qx,qy,qz,qw\n";
  EXPECT_TRUE(contains(errorOf<TrackError>([&] { camera(h + "0,1,2,3,0,0,0\n"); }),
                       "cap.csv:2: 7 values for 8 columns"));
  EXPECT_TRUE(contains(errorOf<TrackError>([&] { camera(h + "0,1,x,3,0,0,0,1\n"); }),
                       "cap.csv:2: column py: 'x' is not a number"));
  EXPECT_TRUE(contains(
      errorOf<TrackError>([&] { camera("time,px,py,pz,qx,qy,qz,qw,cut\n0,0,0,0,0,0,0,1,2\n"); }),
      "cap.csv:2: cut must be 0 or 1"));
}

}  // namespace
}  // namespace taa::script
