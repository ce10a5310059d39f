// Positives per environment: a golden set holds, for each environment it was blessed on, the
// hashes of every frame, so each such machine compares bit for bit; another machine's positive
// comes from its run folder (bless --from ... --add-environment) with no Vulkan device; a machine
// without one takes the tolerance path and says so, or fails under --require-exact.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "harness/cli_fixture.h"
#include "support/text.h"

namespace taa::positives_test {
namespace {

namespace fs = std::filesystem;
using test::HarnessCli;
using test::kSmallCase;

const std::string kSse = "GALLIUM_OVERRIDE_CPU_CAPS=sse4.1";
// No Vulkan driver at all: the loader finds no ICD, so anything that needs a device exits 3.
const std::string kNoDevice =
    "VK_ICD_FILENAMES=/nonexistent/icd.json VK_DRIVER_FILES=/nonexistent/icd.json";

nlohmann::json readJson(const fs::path& p) {
  std::ifstream in(p);
  return nlohmann::json::parse(in);
}

size_t exrCount(const fs::path& dir) {
  size_t n = 0;
  for (const auto& e : fs::directory_iterator(dir)) n += e.path().extension() == ".exr";
  return n;
}

class Positives : public HarnessCli {
 protected:
  std::string out() const { return (root_ / "out").string(); }
  test::ProcessResult blessFrom(const std::string& extra, const std::string& env = kNoDevice) {
    return harness(
        "bless --from " + out() + " " + casePath("small") + " --reason 'sse4.1 runner' " + extra,
        env);
  }
};

TEST_F(Positives, AnotherLevelGetsItsOwnPositiveFromItsRunFolderAndIsThenExact) {
  ASSERT_EQ(bless("small").exitCode, 0);
  // No positive for sse4.1 yet: --require-exact fails the case, naming the way to add one.
  auto r = run("small", "--require-exact", kSse);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("tolerance: no positive for"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("then taa-harness bless --add-environment"), std::string::npos) << r.output;
  EXPECT_EQ(results()["cases"][0]["golden_mode"], "tolerance");
  // TAA_REQUIRE_EXACT=1 is the same for CI.
  EXPECT_EQ(run("small", "", kSse + " TAA_REQUIRE_EXACT=1").exitCode, 1);
  // That run's folder becomes the level's positive, with no Vulkan device present.
  ASSERT_EQ(run("small", "", kSse).exitCode, 0);
  EXPECT_EQ(harness("run " + casePath("small") + " --out " + (root_ / "nodev").string(), kNoDevice)
                .exitCode,
            3);
  const std::string exrBefore = test::readFile(root_ / "goldens/small/frame_0005.exr");
  r = blessFrom("--add-environment");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("ADDED small environment"), std::string::npos) << r.output;
  EXPECT_EQ(test::readFile(root_ / "goldens/small/frame_0005.exr"), exrBefore);  // only the manifest changes
  const auto m = readJson(root_ / "goldens/small/manifest.json");
  ASSERT_EQ(m["other_environments"].size(), 1u);
  EXPECT_EQ(m["other_environments"][0]["environment"]["cpu_features"], "override:sse4.1");
  EXPECT_EQ(m["other_environments"][0]["reason"], "sse4.1 runner");
  // It records the commit that rendered it: the run's, from the folder's results.json.
  const std::string runCommit = results()["commit"];
  EXPECT_GE(runCommit.size(), 40u);
  EXPECT_EQ(m["other_environments"][0]["renderer_commit"], runCommit);
  EXPECT_EQ(m["reason"], "test bless");  // the primary positive and its images stay
  EXPECT_EQ(exrCount(root_ / "goldens/small"), 2u);
  // Adding it again changes nothing.
  r = blessFrom("--add-environment");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("UNCHANGED small"), std::string::npos) << r.output;
  // Now sse4.1 compares bit for bit, and a sun a third of a percent brighter fails there.
  r = run("small", "--require-exact", kSse);
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_EQ(results()["cases"][0]["golden_mode"], "exact");
  const std::string edited = test::smallCaseWith(R"("lighting": {"intensity": 3.01})");
  writeCase("small", edited);
  r = run("small", "", kSse);
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("pixels differ from this environment's positive"), std::string::npos)
      << r.output;
  // A level without a positive fails the edited case as stale, although within tolerances.
  r = run("small", "", "GALLIUM_OVERRIDE_CPU_CAPS=ssse3");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(results()["cases"][0]["status"], "stale");
  EXPECT_NE(r.output.find("its frames match no positive"), std::string::npos) << r.output;
  // A run of the case's earlier bytes is refused as a source of goldens for today's case.
  writeCase("small", kSmallCase);
  ASSERT_EQ(run("small", "", kSse).exitCode, 0);
  writeCase("small", edited);
  r = blessFrom("");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("was rendered from other case, scene, track or shader bytes"),
            std::string::npos)
      << r.output;
}

TEST_F(Positives, APlainBlessKeepsThePositivesWhoseFramesItReproducesAndDropsTheRest) {
  ASSERT_EQ(bless("small").exitCode, 0);
  ASSERT_EQ(run("small", "", kSse).exitCode, 0);
  ASSERT_EQ(blessFrom("--add-environment").exitCode, 0);
  // A machine that renders the primary's very bytes (as x86-64-v3 and v4 do on lavapipe).
  auto m = readJson(root_ / "goldens/small/manifest.json");
  auto twin = m["other_environments"][0];
  twin["environment"] = m["environment"];
  twin["environment"]["cpu_features"] = "x86-64-twin";
  twin.erase("frame_sha256");
  twin.erase("frame_signatures");
  twin["same_frames_as_primary"] = true;
  m["other_environments"].push_back(twin);
  std::ofstream(root_ / "goldens/small/manifest.json") << m.dump(2);
  // An edit that changes no frame here: the twin stays, sse4.1's other frames cannot be vouched for.
  std::string edited = kSmallCase;
  edited.replace(edited.find("small moving case"), 5, "tiny");
  writeCase("small", edited);
  const auto r = bless("small");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("kept the positives of 1 other environment(s)"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("the positives of 1 other environment(s) were dropped"), std::string::npos) << r.output;
  const auto after = readJson(root_ / "goldens/small/manifest.json");
  ASSERT_EQ(after["other_environments"].size(), 1u);
  EXPECT_EQ(after["other_environments"][0]["environment"]["cpu_features"], "x86-64-twin");
}

TEST_F(Positives, ALevelWithoutAPositiveTakesTheTolerancePathAndSaysSo) {
  ASSERT_EQ(bless("small").exitCode, 0);
  const auto r = run("small", "", "GALLIUM_OVERRIDE_CPU_CAPS=ssse3");
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("NOTE small: tolerance: no positive for"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("1 by tolerance (no positive for"), std::string::npos) << r.output;
  // The way out adds this machine's positive; a plain bless would replace the primary's set.
  EXPECT_NE(r.output.find("; refresh with taa-harness bless --add-environment " + casePath("small") +
                          " --reason \"<which machine this is>\""),
            std::string::npos)
      << r.output;
  const auto c = results()["cases"][0];
  EXPECT_EQ(c["golden_mode"], "tolerance");
  const std::string xml = test::readFile(root_ / "out/junit.xml");
  EXPECT_NE(xml.find("golden: tolerance: no positive for"), std::string::npos);
}

TEST_F(Positives, AnAlteredRunFolderIsRefusedAndNoGoldenChanges) {
  ASSERT_EQ(bless("small").exitCode, 0);
  ASSERT_EQ(run("small", "", kSse).exitCode, 0);
  const std::string before = readJson(root_ / "goldens/small/manifest.json").dump();
  const fs::path frame = root_ / "out/small/frame_0005.exr";
  // A stored image swapped for another frame of the run.
  fs::copy_file(root_ / "out/small/frame_0002.exr", frame, fs::copy_options::overwrite_existing);
  auto r = blessFrom("--add-environment");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("does not hash to what"), std::string::npos) << r.output;
  // A frame that leads out of the folder, and one that is a FIFO: refused unread.
  fs::remove(frame);
  fs::create_symlink("/etc/passwd", frame);
  r = blessFrom("--add-environment");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  fs::remove(frame);
  ASSERT_EQ(mkfifo(frame.c_str(), 0600), 0);
  r = blessFrom("--add-environment");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  fs::remove(frame);
  r = blessFrom("--add-environment");  // missing
  EXPECT_EQ(r.exitCode, 2) << r.output;
  // A results.json whose status or fingerprint was edited cannot pose as another environment.
  auto res = readJson(root_ / "out/results.json");
  res["fingerprint"] = "forged";
  std::ofstream(root_ / "out/results.json") << res.dump();
  r = blessFrom("--add-environment");
  EXPECT_EQ(r.exitCode, 2) << r.output;
  // Options that only a render reads are refused with --from rather than ignored.
  EXPECT_EQ(blessFrom("--jobs 2").exitCode, 2);
  EXPECT_EQ(readJson(root_ / "goldens/small/manifest.json").dump(), before);
}

}  // namespace
}  // namespace taa::positives_test
