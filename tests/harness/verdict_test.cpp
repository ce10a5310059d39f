// Verdicts that cannot miss or lie: a case's status is the worst of its checks in the
// console, results.json, JUnit and the report; every frame is checked against the golden
// sequence; goldens are verified before use; outputs never land in the goldens folder.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/image_io.h"
#include "harness/cli_fixture.h"
#include "support/text.h"

namespace taa {
namespace {

namespace fs = std::filesystem;
using test::HarnessCli;
using test::kSmallCase;

// energy with epsilon 0 on a moving checkerboard: an invariant that always fails.
const char* kFailingInvariant = R"({
  "scene": {"builtin": "checkerboard"}, "render": {"width": 48, "height": 27},
  "script": {"frames": 4}, "checks": {"invariants": ["energy"], "energy": {"epsilon": 0}}
})";

std::string readText(const fs::path& file) {
  std::ifstream in(file);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

nlohmann::json readJson(const fs::path& file) {
  return nlohmann::json::parse(readText(file));
}

void writeJson(const fs::path& file, const nlohmann::json& j) {
  std::ofstream(file) << j.dump(2);
}

class Verdicts : public HarnessCli {
 protected:
  std::string junit() const { return readText(root_ / "out/junit.xml"); }
  std::string report() const { return readText(root_ / "out/report.html"); }
};

TEST_F(Verdicts, FailedInvariantOnANewCaseIsAFailureEverywhere) {
  writeCase("strict", kFailingInvariant);
  const auto r = run("strict");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("FAIL strict invariant energy"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("failing: strict (fail)"), std::string::npos) << r.output;
  EXPECT_EQ(results()["cases"][0]["status"], "fail");
  const std::string xml = junit();
  EXPECT_NE(xml.find("failures=\"1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("skipped=\"0\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("invariant energy"), std::string::npos) << xml;
  EXPECT_NE(report().find("<section class=\"case st-fail\""), std::string::npos);
}

TEST_F(Verdicts, FailedInvariantOnAStaleCaseIsAFailureNotAStaleNote) {
  writeCase("strict", kFailingInvariant);
  ASSERT_EQ(bless("strict", "--force").exitCode, 0);
  // Same pixels, edited file: stale. Before, this was a pass with a note.
  std::string edited = kFailingInvariant;
  edited.insert(edited.find('{') + 1, "\"description\": \"edited\",");
  writeCase("strict", edited);
  const auto r = run("strict");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(results()["cases"][0]["status"], "fail");
  EXPECT_NE(junit().find("failures=\"1\""), std::string::npos);
}

TEST_F(Verdicts, NoGoldensIsASkipLocallyAndAFailureInCi) {
  auto r = run("small");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(junit().find("skipped=\"1\""), std::string::npos);
  r = run("small", "", "CI=true");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("CI=true: a case without goldens fails in CI"), std::string::npos)
      << r.output;
  EXPECT_EQ(results()["cases"][0]["status"], "fail");
  const std::string xml = junit();
  EXPECT_NE(xml.find("failures=\"1\""), std::string::npos) << xml;
  EXPECT_NE(xml.find("skipped=\"0\""), std::string::npos) << xml;
}

TEST_F(Verdicts, ManifestHashesEveryFrameAndRunsRecordThem) {
  ASSERT_EQ(bless("small").exitCode, 0);
  const auto m = readJson(root_ / "goldens/small/manifest.json");
  ASSERT_EQ(m["frame_sha256"].size(), 6u);  // script.frames, though only frames 2 and 5 are stored
  EXPECT_EQ(m["frame_sha256"][2], m["frames"][0]["sha256"]);
  EXPECT_EQ(m["frame_sha256"][5], m["frames"][1]["sha256"]);
  EXPECT_NE(m["frame_sha256"][3], m["frame_sha256"][4]);  // a moving camera: every frame differs
  ASSERT_EQ(m["frame_signatures"].size(), 6u);
  EXPECT_EQ(m["frame_signatures"][0].get<std::string>().size(), 140u);
  ASSERT_EQ(run("small").exitCode, 0);
  EXPECT_EQ(results()["cases"][0]["frame_sha256"], m["frame_sha256"]);
}

TEST_F(Verdicts, AChangedMiddleFrameFailsAndIsShownBesideItsGoldenNeighbours) {
  ASSERT_EQ(bless("small").exitCode, 0);
  // The golden sequence says frame 3 looked otherwise: no stored EXR covers it.
  auto m = readJson(root_ / "goldens/small/manifest.json");
  m["frame_sha256"][3] = std::string(64, '0');
  writeJson(root_ / "goldens/small/manifest.json", m);
  const auto r = run("small");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(
      r.output.find(
          "FAIL small frame 3 sequence: frame 3 is the first whose pixels differ from the golden "
          "sequence"),
      std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("frames 0-2 are identical"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("PASS small frame 5 golden exact"), std::string::npos) << r.output;
  const auto res = results()["cases"][0];
  EXPECT_EQ(res["status"], "fail");
  EXPECT_EQ(res["first_difference"]["frame"], 3);
  ASSERT_EQ(res["first_difference"]["golden_neighbours"].size(), 2u);
  EXPECT_EQ(res["first_difference"]["golden_neighbours"][0]["frame"], 2);
  EXPECT_EQ(res["first_difference"]["golden_neighbours"][1]["frame"], 5);
  for (const char* f :
       {"small/frame_0003.png", "small/frame_0002.golden.png", "small/frame_0005.golden.png"})
    EXPECT_TRUE(fs::exists(root_ / "out" / f)) << f;
  EXPECT_NE(junit().find("frame 3: frame 3 is the first whose pixels differ"), std::string::npos);
  const std::string html = report();
  EXPECT_NE(html.find("First differing frame"), std::string::npos);
  EXPECT_NE(html.find("src=\"small/frame_0003.png\""), std::string::npos);
}

TEST_F(Verdicts, ARealChangeBeforeACutIsCaughtThoughTheStoredFramesMatch) {
  // A cut at frame 4 resets the history, so frames 4 and 5 do not see what happened before.
  const std::string cut = R"({
    "scene": {"builtin": "checkerboard"}, "render": {"width": 64, "height": 36},
    "camera": {"cuts": [{"frame": 4, "position": [0, 1, 4], "target": [0, 0, 0]}]},
    "script": {"frames": 6}, "output": {"frames": [5]})";
  writeCase("cut", cut + "}");
  ASSERT_EQ(bless("cut").exitCode, 0);
  writeCase("cut", cut + R"(, "inject": {"frames": [2], "pixels": [[10, 10]], "value": "inf"}})");
  const auto r = run("cut");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("PASS cut frame 5 golden exact"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("FAIL cut frame 2 sequence"), std::string::npos) << r.output;
  EXPECT_EQ(results()["cases"][0]["status"], "stale");  // the case file changed: bless if intended
}

// The last rendered frame is hashed and checked like every other, also when output.frames
// does not store it: only the sequence guards it then, by hash here and by signature on
// another CPU level.
TEST_F(Verdicts, AChangedLastFrameFailsThoughNoStoredFrameCoversIt) {
  const std::string tail = R"({
    "scene": {"builtin": "checkerboard"}, "render": {"width": 64, "height": 36},
    "camera": {"strafe": {"speed": 0.5, "distance": 0.2}},
    "script": {"frames": 6}, "output": {"frames": [2]})";
  writeCase("tail", tail + "}");
  ASSERT_EQ(bless("tail").exitCode, 0);
  writeCase("tail", tail + R"(, "inject": {"frames": [5], "value": "inf",
      "pixels": [[10, 10], [11, 10], [12, 10], [13, 10], [10, 11], [11, 11], [12, 11], [13, 11]]}})");
  auto r = run("tail");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("PASS tail frame 2 golden exact"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("FAIL tail frame 5 sequence: frame 5 is the first whose pixels differ"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(results()["cases"][0]["first_difference"]["frame"], 5);
  r = run("tail", "", "GALLIUM_OVERRIDE_CPU_CAPS=sse4.1");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(
      r.output.find(
          "FAIL tail frame 5 sequence: frame 5 is the first whose signature is out of tolerance"),
      std::string::npos)
      << r.output;
}

// A frame added to output.frames after the bless has no golden: the case fails (it is not a
// pass with a stale note) until someone looks at the frame and blesses it.
TEST_F(Verdicts, AFrameAddedToOutputFramesWithoutBlessingItFails) {
  ASSERT_EQ(bless("small").exitCode, 0);
  std::string added = kSmallCase;
  added.replace(added.find("[2, 5]"), 6, "[2, 3, 5]");
  writeCase("small", added);
  const auto r = run("small");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("frame 3 is checked but was never blessed"), std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("PASS small frame 5 golden exact"), std::string::npos) << r.output;
  const auto res = results()["cases"][0];
  EXPECT_NE(res["status"], "pass");
  ASSERT_EQ(res["frames"].size(), 3u);
  EXPECT_EQ(res["frames"][1]["frame"], 3);
  EXPECT_EQ(res["frames"][1]["status"], "missing_golden");
  EXPECT_NE(junit().find("failures=\"1\""), std::string::npos);
}

TEST_F(Verdicts, OnAnotherCpuLevelEveryFrameIsCheckedBySignature) {
  const std::string sse = "GALLIUM_OVERRIDE_CPU_CAPS=sse4.1";
  const std::string cut = R"({
    "scene": {"builtin": "checkerboard"}, "render": {"width": 64, "height": 36},
    "camera": {"cuts": [{"frame": 4, "position": [0, 1, 4], "target": [0, 0, 0]}]},
    "script": {"frames": 6}, "output": {"frames": [5]})";
  writeCase("cut", cut + "}");
  ASSERT_EQ(bless("cut").exitCode, 0);
  auto r = run("cut", "", sse);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("PASS cut sequence: 6 frames within signature tolerance"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(results()["cases"][0]["sequence_check"]["mode"], "signature");
  // Eight bright pixels in frame 2 only: the stored frame 5 is within tolerance, frame 2 is not.
  writeCase("cut", cut + R"(, "inject": {"frames": [2], "value": "inf",
      "pixels": [[10, 10], [11, 10], [12, 10], [13, 10], [10, 11], [11, 11], [12, 11], [13, 11]]}})");
  r = run("cut", "", sse);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("PASS cut frame 5 golden tolerance"), std::string::npos) << r.output;
  EXPECT_NE(
      r.output.find(
          "FAIL cut frame 2 sequence: frame 2 is the first whose signature is out of tolerance"),
      std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("cell (row 2, column 1 of 8x8)"), std::string::npos) << r.output;
  // The worst cell over the sequence is frame 2's, though frames 3 to 5 came after it.
  const auto q = results()["cases"][0]["sequence_check"];
  EXPECT_EQ(q["worst_cell_frame"], 2) << q.dump();
  EXPECT_EQ(q["worst_mean_frame"], 2) << q.dump();
}

TEST_F(Verdicts, AnOverwrittenGoldenExrIsAFailureNamingTheFileAndTheFix) {
  ASSERT_EQ(bless("small").exitCode, 0);
  writeExr(root_ / "goldens/small/frame_0005.exr", Image(64, 36, 4, 0.5f));
  const auto r = run("small");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(r.output.find("golden exact"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("frame_0005.exr: pixels (sha256"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("do not match manifest.json"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("git checkout -- "), std::string::npos) << r.output;
  EXPECT_EQ(results()["cases"][0]["status"], "fail");
  EXPECT_NE(junit().find("failures=\"1\""), std::string::npos);
}

TEST_F(Verdicts, AMissingGoldenExrOrABrokenManifestIsAFailureNamingTheFile) {
  ASSERT_EQ(bless("small").exitCode, 0);
  fs::remove(root_ / "goldens/small/frame_0002.exr");
  auto r = run("small");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("frame_0002.exr: missing"), std::string::npos) << r.output;
  std::ofstream(root_ / "goldens/small/manifest.json") << "{";
  r = run("small");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("manifest.json: not valid JSON"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("git checkout -- "), std::string::npos) << r.output;
  // A bless needs the previous record to continue its history: it refuses, naming both fixes,
  // and does not suggest the re-bless it refuses.
  r = bless("small");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("git checkout -- "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("to start the case's history over, delete "), std::string::npos)
      << r.output;
  EXPECT_EQ(r.output.find("or re-bless"), std::string::npos) << r.output;
  EXPECT_EQ(test::readFile(root_ / "goldens/small/manifest.json"), "{");  // left as it was
  // The second fix works: without the folder the bless starts a new history.
  fs::remove_all(root_ / "goldens/small");
  r = bless("small");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(run("small").exitCode, 0);
  // Without a manifest at all there is no history to continue: a plain re-bless is the fix.
  fs::remove(root_ / "goldens/small/manifest.json");
  r = run("small");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("manifest.json: missing"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("or re-bless the case"), std::string::npos) << r.output;
  EXPECT_EQ(bless("small").exitCode, 0);
  EXPECT_EQ(run("small").exitCode, 0);
}

TEST_F(Verdicts, AManifestWithoutFrameHashesFailsWithTheReblessCommand) {
  ASSERT_EQ(bless("small").exitCode, 0);
  auto m = readJson(root_ / "goldens/small/manifest.json");
  m.erase("frame_sha256");  // a manifest from before per-frame digests has neither
  m.erase("frame_signatures");
  writeJson(root_ / "goldens/small/manifest.json", m);
  const auto r = run("small");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("has no frame_sha256"), std::string::npos) << r.output;
}

TEST_F(Verdicts, RenderRunSweepAndBlessRefuseAnOutputInsideTheGoldens) {
  ASSERT_EQ(bless("small").exitCode, 0);
  const std::string goldens = (root_ / "goldens").string();
  const std::string presets = std::string(TAA_SOURCE_DIR) + "/cases/presets/presets.json";
  for (const std::string& cmd :
       {"render " + casePath("small") + " --out " + goldens,
        "run " + casePath("small") + " --out " + goldens + "/small",
        "sweep " + casePath("small") + " --presets default --presets-file " + presets + " --out " +
            goldens + "/x",
        "bless " + casePath("small") + " --reason r --out " + root_.string() +
            "/cases/../goldens"}) {
    const auto r = harness(cmd);
    EXPECT_EQ(r.exitCode, 2) << cmd << ": " << r.output;
    EXPECT_NE(r.output.find("is inside the goldens folder"), std::string::npos)
        << cmd << ": " << r.output;
  }
  EXPECT_EQ(run("small").exitCode, 0);  // nothing was written into them
}

TEST_F(Verdicts, BlessThatCannotLoadTheSceneSaysWhy) {
  fs::create_directories(root_ / "cases/scenes");
  std::ofstream(root_ / "cases/scenes/broken.gltf")
      << "{\"asset\": {\"version\": \"2.0\"}, \"meshes\": 7}";
  writeCase("broken",
            R"({"scene": {"gltf": "scenes/broken.gltf"}, "render": {"width": 16, "height": 9},
                          "script": {"frames": 1}})");
  const auto r = bless("broken");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("broken.gltf"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(root_ / "goldens/broken"));
}

}  // namespace
}  // namespace taa
