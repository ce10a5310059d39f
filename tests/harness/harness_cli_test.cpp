// The harness as users drive it: exit codes, bless, stale goldens, the tolerance
// path on another CPU feature level, metric mode, shards and re-blessing failures.
// Each test works in its own temporary tree (cases/ + goldens/), never the repo's.
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <regex>

#include "harness/cli_fixture.h"

namespace taa {
namespace {

namespace fs = std::filesystem;
using test::HarnessCli;
using test::kSmallCase;

TEST_F(HarnessCli, MissingGoldensSkipLocallyThenBlessThenExactPass) {
  auto r = run("small");
  EXPECT_EQ(r.exitCode, 0)
      << r.output;  // a new case on a developer's machine: a skip (CI: verdict_test)
  EXPECT_NE(r.output.find("SKIP small: no goldens"), std::string::npos) << r.output;
  EXPECT_EQ(results()["cases"][0]["status"], "no_golden");
  r = bless("small");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(root_ / "goldens/small/manifest.json"));
  EXPECT_TRUE(fs::exists(root_ / "goldens/small/frame_0005.exr"));
  r = run("small");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("PASS small frame 5 golden exact"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(root_ / "out/report.html"));
  EXPECT_TRUE(fs::exists(root_ / "out/junit.xml"));
  EXPECT_EQ(results()["cases"][0]["status"], "pass");
}

TEST_F(HarnessCli, ManifestRecordsReasonDriverCommitAndHistory) {
  const auto first = bless("small");
  ASSERT_EQ(first.exitCode, 0) << first.output;
  EXPECT_NE(first.output.find("small frame 5: new golden"), std::string::npos) << first.output;
  const auto second = harness("bless " + casePath("small") + " --out " + (root_ / "b2").string() +
                              " --reason 'second'");
  ASSERT_EQ(second.exitCode, 0) << second.output;
  // The same pixels again: each frame says so, and no metric of a change is printed.
  EXPECT_NE(second.output.find("small frame 5: unchanged"), std::string::npos) << second.output;
  EXPECT_EQ(second.output.find("changed:"), std::string::npos) << second.output;
  std::ifstream in(root_ / "goldens/small/manifest.json");
  const auto m = nlohmann::json::parse(in);
  EXPECT_EQ(m["reason"], "second");
  EXPECT_EQ(m["history"][0]["reason"], "test bless");
  EXPECT_NE(m["environment"]["device"].get<std::string>().find("llvmpipe"), std::string::npos);
  EXPECT_FALSE(m["environment"]["driver_info"].get<std::string>().empty());
  EXPECT_FALSE(m["environment"]["cpu_features"].get<std::string>().empty());
  // git's answer as one token: a commit and -dirty for local edits, never a line break.
  EXPECT_TRUE(std::regex_match(m["renderer_commit"].get<std::string>(),
                               std::regex("[0-9a-f]{40}(-dirty)?|unknown")))
      << m["renderer_commit"];
  EXPECT_EQ(m["frames"].size(), 2u);
  EXPECT_EQ(m["case_sha256"].get<std::string>().size(), 64u);
}

TEST_F(HarnessCli, ChangedPixelsInTheSameEnvironmentAreARegression) {
  ASSERT_EQ(bless("small").exitCode, 0);
  // A brighter sun is a real change of the output.
  writeCase("small", test::smallCaseWith(R"("lighting": {"intensity": 4.5})"));
  const auto r = run("small");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("pixels differ from this environment's positive"),
            std::string::npos)
      << r.output;
  EXPECT_NE(r.output.find("STALE small"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::exists(root_ / "out/small/frame_0005.diff.png"));
  // A regression is magnified where it is worst; an exact match has no worst region to show.
  EXPECT_TRUE(fs::exists(root_ / "out/small/frame_0005.zoom_diff.png"));
  writeCase("small", kSmallCase);
  fs::remove_all(root_ / "out");
  ASSERT_EQ(run("small").exitCode, 0);
  EXPECT_FALSE(fs::exists(root_ / "out/small/frame_0005.zoom_diff.png"));
  EXPECT_FALSE(fs::exists(root_ / "out/small/frame_0005.zoom_actual.png"));
}

TEST_F(HarnessCli, EditedCaseWithUnchangedPixelsPassesWithStaleNote) {
  ASSERT_EQ(bless("small").exitCode, 0);
  std::string edited = kSmallCase;
  edited.replace(edited.find("small moving case"), 5, "tiny");
  writeCase("small", edited);
  const auto r = run("small");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("NOTE small: the case file (or a file it references) changed"),
            std::string::npos)
      << r.output;
}

TEST_F(HarnessCli, OtherCpuFeatureLevelUsesTolerancesAndStillCatchesARegression) {
  ASSERT_EQ(bless("small").exitCode, 0);
  const std::string sse = "GALLIUM_OVERRIDE_CPU_CAPS=sse4.1";
  auto r = run("small", "", sse);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("golden tolerance"), std::string::npos) << r.output;
  const auto res = results();
  EXPECT_NE(res["fingerprint"], res["cases"][0]["golden_fingerprint"]);
  EXPECT_NE(res["fingerprint"].get<std::string>().find("override:sse4.1"), std::string::npos);
  EXPECT_TRUE(res["cases"][0]["frames"][1]["tolerance_mode"].get<bool>());
  // The same environment change with a real regression (no jitter: the frame aliases).
  writeCase("small", test::smallCaseWith(R"("jitter": {"pattern": "none"})"));
  r = run("small", "", sse);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("FAIL small frame 5 golden tolerance"), std::string::npos) << r.output;
}

TEST_F(HarnessCli, BadInputExitsTwoAndNamesFileKeyAndFix) {
  writeCase("bad", R"({"taa": {"alpah": 0.2}})");
  const auto r = run("bad");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("bad.json: taa.alpah: unknown key; did you mean 'taa.alpha'?"),
            std::string::npos)
      << r.output;
}

TEST_F(HarnessCli, HelpPrintsUsageAndExitsZeroUnknownOptionsExitTwo) {
  for (const char* cmd :
       {"run", "render", "bless", "sweep", "bake", "new-case", "validate", "techniques"}) {
    const auto r = harness(std::string(cmd) + " --help");
    EXPECT_EQ(r.exitCode, 0) << cmd << ": " << r.output;
    EXPECT_EQ(r.output.rfind("usage: taa-harness " + std::string(cmd), 0), 0u)
        << cmd << ": " << r.output;
  }
  // An option a command does not know is an error, never silently ignored.
  for (const char* cmd : {"techniques --bogus", "validate --bogus x.json", "run --bogus x.json"}) {
    const auto r = harness(cmd);
    EXPECT_EQ(r.exitCode, 2) << cmd << ": " << r.output;
    EXPECT_NE(r.output.find("unknown option --bogus"), std::string::npos)
        << cmd << ": " << r.output;
  }
  EXPECT_EQ(harness("techniques extra").exitCode, 2);
  EXPECT_EQ(harness("validate").exitCode, 2);
}

TEST_F(HarnessCli, MissingDeviceExitsThreeWithTheFix) {
  const auto r = run("small", "--device no-such-gpu");
  EXPECT_EQ(r.exitCode, 3) << r.output;
  EXPECT_NE(r.output.find("no Vulkan 1.3 device matches 'no-such-gpu'"), std::string::npos)
      << r.output;
}

TEST_F(HarnessCli, BlessRefusesFailingInvariantsUnlessForced) {
  // A moving camera cannot converge: the invariant is inapplicable and validation refuses
  // it, so use energy with an impossible bound instead.
  writeCase("strict", R"({
    "scene": {"builtin": "checkerboard"}, "render": {"width": 48, "height": 27},
    "script": {"frames": 4}, "checks": {"invariants": ["energy"], "energy": {"epsilon": 0}}
  })");
  auto r = bless("strict");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("REFUSED strict"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(root_ / "goldens/strict"));
  r = bless("strict", "--force");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_TRUE(fs::exists(root_ / "goldens/strict/manifest.json"));
}

TEST_F(HarnessCli, BlessNeedsAReason) {
  const auto r = harness("bless " + casePath("small") + " --reason ''");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("--reason is given an empty value"), std::string::npos) << r.output;
}

TEST_F(HarnessCli, ReblessOnlyTheCasesThatFailedLastRun) {
  writeCase("other", kSmallCase);
  ASSERT_EQ(bless("other").exitCode, 0);
  auto r = harness("run " + (root_ / "cases").string() + " --out " + (root_ / "out").string(),
                   "CI=true");
  EXPECT_EQ(r.exitCode, 1) << r.output;  // small has no goldens yet: a failure in CI
  r = harness("bless --failed-from " + (root_ / "out/results.json").string() + " --out " +
              (root_ / "bo").string() + " --reason 'bless what failed'");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("BLESSED small"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("BLESSED other"), std::string::npos) << r.output;
}

TEST_F(HarnessCli, MetricModeBoundsDriftInsteadOfBitExactness) {
  ASSERT_EQ(bless("small").exitCode, 0);
  writeCase("small", test::smallCaseWith(R"("lighting": {"intensity": 3.1})"));
  EXPECT_EQ(run("small").exitCode, 1);
  EXPECT_EQ(run("small", "--metric flip_mean --above 0.5").exitCode, 0);
  const auto r = run("small", "--metric flip_mean --above 0.0000001");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("ABOVE small frame 5 flip_mean"), std::string::npos) << r.output;
  EXPECT_EQ(run("small", "--metric nonsense --above 1").exitCode, 2);
  // A case the renderer refuses is bad input whatever the bound: it has no frame to measure.
  fs::create_directories(root_ / "cases/scenes/refused");
  fs::copy_file(fs::path(TAA_SOURCE_DIR) / "cases/scenes/refused/requires_basisu.gltf",
                root_ / "cases/scenes/refused/requires_basisu.gltf");
  writeCase("refused", R"({"scene": {"gltf": "scenes/refused/requires_basisu.gltf"},
    "render": {"width": 32, "height": 18}, "script": {"frames": 1}})");
  const auto refused = run("refused", "--metric flip_mean --above 0.5");
  EXPECT_EQ(refused.exitCode, 2) << refused.output;
  EXPECT_NE(refused.output.find("ERROR refused"), std::string::npos) << refused.output;
}

TEST_F(HarnessCli, ShardsPartitionTheCases) {
  for (const char* n : {"a", "b", "c"})
    writeCase(
        n,
        R"({"render": {"width": 16, "height": 9}, "script": {"frames": 1}, "checks": {"golden": false}})");
  fs::remove(root_ / "cases/small.json");
  std::string seen;
  for (int i = 1; i <= 2; ++i) {
    const auto r = harness("run " + (root_ / "cases").string() + " --shard " + std::to_string(i) +
                           "/2 --out " + (root_ / ("o" + std::to_string(i))).string());
    EXPECT_EQ(r.exitCode, 0) << r.output;
    std::ifstream in(root_ / ("o" + std::to_string(i)) / "results.json");
    const auto results = nlohmann::json::parse(in);
    for (const auto& c : results["cases"]) seen += c["name"].get<std::string>();
  }
  EXPECT_EQ(seen, "acb");
  EXPECT_EQ(harness("run " + (root_ / "cases").string() + " --shard 3/2").exitCode, 2);
}

}  // namespace
}  // namespace taa

namespace taa {
namespace {

TEST_F(HarnessCli, EditingAReferencedSceneFileMakesTheGoldensStale) {
  fs::create_directories(root_ / "cases/scenes");
  fs::copy_file(fs::path(TAA_SOURCE_DIR) / "cases/scenes/textured_box.gltf",
                root_ / "cases/scenes/box.gltf");
  writeCase("box", R"({"scene": {"gltf": "scenes/box.gltf"}, "render": {"width": 32, "height": 18},
                      "camera": {"position": [0, 2, 6], "target": [0, 1, 0]}, "script": {"frames": 2}})");
  ASSERT_EQ(bless("box").exitCode, 0);
  EXPECT_EQ(run("box").output.find("NOTE box"), std::string::npos);
  std::ofstream(root_ / "cases/scenes/box.gltf", std::ios::app) << "\n";  // same scene, other bytes
  const auto r = run("box");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("NOTE box: the case file (or a file it references) changed"),
            std::string::npos)
      << r.output;
}

}  // namespace
}  // namespace taa

namespace taa {
namespace {

TEST_F(HarnessCli, NoVulkanDriverExitsThreeNamingThePackage) {
  const auto r =
      run("small", "", "VK_ICD_FILENAMES=/nonexistent.json VK_DRIVER_FILES=/nonexistent.json");
  EXPECT_EQ(r.exitCode, 3) << r.output;
  EXPECT_NE(r.output.find("apt-get install mesa-vulkan-drivers"), std::string::npos) << r.output;
}

TEST_F(HarnessCli, NewCaseFramesAGltfSceneAndTheResultRendersAndValidates) {
  fs::create_directories(root_ / "cases/scenes");
  fs::copy_file(fs::path(TAA_SOURCE_DIR) / "cases/scenes/textured_box.gltf",
                root_ / "cases/scenes/box.gltf");
  auto r =
      harness("new-case --scene " + (root_ / "cases/scenes/box.gltf").string() + " --name boxed");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  std::ifstream in(root_ / "cases/boxed.json");
  const auto j = nlohmann::json::parse(in);
  EXPECT_EQ(j["scene"]["gltf"], "scenes/box.gltf");
  // The camera looks at the centre of the scene's bounds from outside them.
  const auto& pos = j["camera"]["position"];
  const auto& target = j["camera"]["target"];
  const double dx = pos[0].get<double>() - target[0].get<double>(),
               dy = pos[1].get<double>() - target[1].get<double>(),
               dz = pos[2].get<double>() - target[2].get<double>();
  EXPECT_GT(std::sqrt(dx * dx + dy * dy + dz * dz), 1.0);
  r = harness("render " + casePath("boxed") + " --out " + (root_ / "render").string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  // Writing it twice would overwrite a case: refused.
  r = harness("new-case --scene " + (root_ / "cases/scenes/box.gltf").string() + " --name boxed");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  // A scene outside the cases folder cannot be referenced by a case.
  r = harness("new-case --scene " + std::string(TAA_SOURCE_DIR) +
              "/cases/scenes/box.glb --name far --cases " + (root_ / "cases").string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("is not inside"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace taa

namespace taa {
namespace {

// A case that allocates some G-buffer targets and not others, with the reference and
// captures an invariant needs: the Khronos validation layer must report nothing.
TEST_F(HarnessCli, ValidationLayerReportsNothing) {
  writeCase("checked", R"({
    "scene": {"builtin": "rough_floor"}, "render": {"width": 48, "height": 27},
    "movers": [{"shape": "sphere", "start": [-2, 0.7, 1.5], "end": [2, 0.7, 1.5], "speed": 2}],
    "taa": {"anti_ghosting": true, "rectify": "clamp"}, "post": {"fxaa": true},
    "script": {"frames": 4}, "reference": {"samples": 4},
    "checks": {"golden": false, "invariants": ["finite", "energy"], "energy": {"epsilon": 1}}
  })");
  const auto r = run("checked", "--validate");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(r.output.find("validation:"), std::string::npos) << r.output;
  // TSCMAA binds its two uniform blocks per eye at offsets of one buffer: a range past an
  // eye's block runs off the buffer's end (VUID-VkDescriptorBufferInfo-range-00342).
  writeCase("stereo", R"({
    "scene": {"builtin": "checkerboard"}, "render": {"width": 48, "height": 27},
    "taa": {"mode": "tscmaa"}, "tscmaa": {"eyes": 2},
    "movers": [{"shape": "sphere", "start": [-2, 0.7, 1.5], "end": [2, 0.7, 1.5], "speed": 2}],
    "script": {"frames": 4}, "checks": {"golden": false, "invariants": ["finite"]}
  })");
  const auto stereo = run("stereo", "--validate");
  EXPECT_EQ(stereo.exitCode, 0) << stereo.output;
  EXPECT_EQ(stereo.output.find("validation:"), std::string::npos) << stereo.output;
}

}  // namespace
}  // namespace taa
