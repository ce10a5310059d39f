// The harness CLI facing hostile inputs and a hostile environment: exit codes 2 and 3
// with the file named, never a hang, a crash or a regression verdict for a full disk.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "support/process.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

const char* kHarnessHostileSmallCase = R"({
  "scene": {"builtin": "checkerboard"},
  "render": {"width": 64, "height": 36},
  "script": {"frames": 3},
  "output": {"frames": [2]}
})";

class HarnessHostile : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::path(TAA_TEST_OUT) / "harness-hostile" / info->name();
    fs::remove_all(root_);
    fs::create_directories(root_ / "cases");
    std::ofstream(root_ / "cases/small.json") << kHarnessHostileSmallCase;
  }
  std::string path(const std::string& rel) const { return (root_ / rel).string(); }
  fs::path root_;
};

::testing::AssertionResult exits(const test::ProcessResult& r, int code, const std::string& part) {
  if (r.exitCode != code)
    return ::testing::AssertionFailure() << "exit " << r.exitCode << ", not " << code << ":\n" << r.output;
  if (r.output.find(part) == std::string::npos)
    return ::testing::AssertionFailure() << "'" << part << "' not in:\n" << r.output;
  return ::testing::AssertionSuccess();
}

TEST_F(HarnessHostile, ScenesAndTracksThatAreNotFilesAreBadInput) {
  ASSERT_EQ(::mkfifo(path("cases/fifo.gltf").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", root_ / "cases/zero.glb");
  fs::create_directories(root_ / "cases/dir.gltf");
  fs::create_symlink("/etc/passwd", root_ / "cases/passwd.csv");
  std::ofstream(root_ / "cases/fifo_scene.json") << R"({"scene": {"gltf": "fifo.gltf"}})";
  std::ofstream(root_ / "cases/zero_scene.json") << R"({"scene": {"gltf": "zero.glb"}})";
  std::ofstream(root_ / "cases/dir_scene.json") << R"({"scene": {"gltf": "dir.gltf"}})";
  std::ofstream(root_ / "cases/passwd_track.json") << R"({"scene": {"builtin": "checkerboard"},
    "camera": {"track": "passwd.csv"}})";
  for (const char* c : {"fifo_scene", "zero_scene", "dir_scene", "passwd_track"}) {
    SCOPED_TRACE(c);
    const std::string file = path(std::string("cases/") + c + ".json");
    for (const std::string& args : {"validate " + file, "render " + file + " --out " + path("out")}) {
      const auto r = test::runHarness(args);
      EXPECT_TRUE(exits(r, 2, std::string(c) + ".json"));
      EXPECT_EQ(r.output.find("root:"), std::string::npos) << r.output;
    }
  }
}

TEST_F(HarnessHostile, UnwritableOutIsAnEnvironmentError) {
  std::ofstream(root_ / "file") << "x";
  const auto r = test::runHarness("run " + path("cases/small.json") + " --out " + path("file/out"));
  EXPECT_TRUE(exits(r, 3, path("file/out")));
}

TEST_F(HarnessHostile, FullDiskDuringRunIsAnEnvironmentErrorNotARegression) {
  // A file-size limit makes every write past 16 KiB fail with EFBIG, as a full disk fails
  // with ENOSPC; SIGXFSZ is ignored so the write reports the error instead of killing.
  const auto r = test::runHarness("run " + path("cases/small.json") + " --out " + path("out"),
                                  "trap '' XFSZ; ulimit -f 16;");
  EXPECT_TRUE(exits(r, 3, "cannot write " + path("out")));
  // Nothing under a real name is truncated: results.json is whole or absent.
  if (fs::exists(root_ / "out/results.json")) {
    std::ifstream in(root_ / "out/results.json");
    EXPECT_TRUE(nlohmann::json::parse(in).is_object());
  }
}

TEST_F(HarnessHostile, ConcurrentBlessesOfOneCaseBothSucceedAndKeepBothInTheHistory) {
  const std::string bless = std::string(TAA_HARNESS_BIN) + " bless " + path("cases/small.json") +
                            " --goldens " + path("goldens") + " --out " + path("b1") + " --reason first";
  const auto r = test::runHarness("bless " + path("cases/small.json") + " --goldens " + path("goldens") +
                                      " --out " + path("b2") +
                                      " --reason second >second.log 2>&1; s=$?; wait $pid; echo exits $s $?",
                                  "cd " + root_.string() + "; " + bless + " >first.log 2>&1 & pid=$!;");
  EXPECT_NE(r.output.find("exits 0 0"), std::string::npos) << r.output;
  std::ifstream in(root_ / "goldens/small/manifest.json");
  const auto m = nlohmann::json::parse(in);
  const std::string last = m.at("reason");
  ASSERT_EQ(m.at("history").size(), 1u) << m.dump(1);
  const std::string earlier = m.at("history")[0].at("reason");
  EXPECT_TRUE((last == "first" && earlier == "second") || (last == "second" && earlier == "first"))
      << m.dump(1);
  for (const auto& e : fs::directory_iterator(root_ / "goldens"))
    EXPECT_EQ(e.path().filename().string().rfind(".small.bless-", 0), std::string::npos)
        << "staging folder left behind: " << e.path();
}

}  // namespace
}  // namespace taa
