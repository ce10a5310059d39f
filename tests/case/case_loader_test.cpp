#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "case/case_loader.h"
#include "support/case_problems.h"

using taa::cases::parseCase;
using taa::test::caseProblems;

TEST(CaseLoader, EmptyObjectGivesDefaults) {
  const auto loaded = parseCase("{}", "cases/defaults.json");
  EXPECT_EQ(loaded.spec.name, "defaults");
  EXPECT_EQ(loaded.spec.render.width, 320);
  EXPECT_EQ(loaded.spec.script.frames, 16);
  ASSERT_EQ(loaded.spec.output.frames.size(), 1u);
  EXPECT_EQ(loaded.spec.output.frames[0], 15);  // the last frame by default
}

// Listed frames are the checked frames, sorted: the last frame is only the default, never
// added to a list that leaves it out.
TEST(CaseLoader, OutputFramesAreTheListedOnesSorted) {
  const auto loaded =
      parseCase(R"({"script": {"frames": 10}, "output": {"frames": [6, 2]}})", "cases/o.json");
  EXPECT_EQ(loaded.spec.output.frames, (std::vector<int>{2, 6}));
}

TEST(CaseLoader, UnknownKeySuggestsNearMiss) {
  const auto p = caseProblems(R"({"render": {"widht": 64}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("cases/t.json: render.widht: unknown key; did you mean 'render.width'?"), std::string::npos) << p[0];
}

TEST(CaseLoader, OutOfRangeNamesKeyAndRange) {
  const auto p = caseProblems(R"({"render": {"width": 9000}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("render.width: 9000 is out of range; allowed [1, 8192]"), std::string::npos) << p[0];
}

TEST(CaseLoader, FrameCountBounded) {
  const auto p = caseProblems(R"({"script": {"frames": 100001}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("script.frames"), std::string::npos);
}

TEST(CaseLoader, WrongTypeIsReported) {
  const auto p = caseProblems(R"({"script": {"fps": 59.5}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("script.fps: expected an integer"), std::string::npos) << p[0];
}

TEST(CaseLoader, BadEnumSuggestsName) {
  const auto p = caseProblems(R"({"jitter": {"pattern": "haltn"}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("did you mean 'halton'"), std::string::npos) << p[0];
}

TEST(CaseLoader, SyntaxErrorGivesLineAndColumn) {
  const auto p = caseProblems("{\n  \"render\": {\"width\": 64,}\n}");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("cases/t.json:2:"), std::string::npos) << p[0];
}

TEST(CaseLoader, AllProblemsReportedTogether) {
  const auto p = caseProblems(R"({"render": {"width": 0, "height": -1}, "bogus": 1})");
  EXPECT_EQ(p.size(), 3u);
}

TEST(CaseLoader, OutputFramePastEndIsRejected) {
  const auto p = caseProblems(R"({"script": {"frames": 4}, "output": {"frames": [4]}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("output.frames[0]"), std::string::npos) << p[0];
}

TEST(CaseLoader, SceneOutsideCaseFolderIsRefused) {
  EXPECT_FALSE(caseProblems(R"({"scene": {"gltf": "../secret.gltf"}})").empty());
  EXPECT_FALSE(caseProblems(R"({"scene": {"gltf": "http://example.com/a.gltf"}})").empty());
  EXPECT_FALSE(caseProblems(R"({"scene": {"gltf": "/etc/a.gltf"}})").empty());
}

// Any rotation speed but 0 needs an axis to turn about, 1 degree a second as much as 45.
TEST(CaseLoader, AMoverThatRotatesNeedsANonZeroAxis) {
  for (const char* speed : {"1", "45", "-0.5"}) {
    const auto p = caseProblems(std::string(R"({"movers": [{"shape": "cube", "rotation_speed_deg": )") +
                                speed + R"(, "rotation_axis": [0, 0, 0]}]})");
    ASSERT_EQ(p.size(), 1u) << speed;
    EXPECT_NE(p[0].find("movers[0].rotation_axis: a zero axis cannot rotate"), std::string::npos) << p[0];
  }
}

// report.zoom must lie in the output, across (the eyes side by side) and down.
TEST(CaseLoader, AZoomRegionLeavingTheOutputIsRefused) {
  auto zoomProblems = [](const std::string& zoom, const std::string& more = "") {
    return caseProblems(R"({"render": {"width": 64, "height": 36}, "report": {"zoom": )" + zoom + "}" +
                        more + "}");
  };
  EXPECT_TRUE(zoomProblems(R"({"x": 48, "y": 27, "width": 16, "height": 9})").empty());
  for (const char* zoom : {R"({"x": 49, "y": 0, "width": 16, "height": 9})",
                           R"({"x": 0, "y": 28, "width": 16, "height": 9})"}) {
    const auto p = zoomProblems(zoom);
    ASSERT_EQ(p.size(), 1u) << zoom;
    EXPECT_NE(p[0].find("leaves the 64x36 output"), std::string::npos) << p[0];
  }
  const std::string stereo = R"(, "taa": {"mode": "tscmaa"}, "tscmaa": {"eyes": 2})";
  EXPECT_TRUE(zoomProblems(R"({"x": 112, "y": 0, "width": 16, "height": 9})", stereo).empty());
}

TEST(CaseLoader, SettingIgnoredByChosenPatternIsAnError) {
  const auto p = caseProblems(R"({"jitter": {"pattern": "uniform4", "length": 16}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("jitter.length"), std::string::npos);
}

TEST(CaseLoader, SchemaListsEveryLeafWithDefault) {
  const auto rows = taa::cases::settingsSchema();
  bool foundWidth = false;
  for (const auto& r : rows)
    if (r["key"] == "render.width") {
      foundWidth = true;
      EXPECT_EQ(r["default"], 320);
      EXPECT_EQ(r["range"][1], 8192);
    }
  EXPECT_TRUE(foundWidth);
}
