// The one output-path rule at the commands (core/output_file.h checkOutputPath): `bake --out`
// and `compare --heatmap` never write to a FIFO, a device or a link, nor over their own input;
// each is refused with exit 2 before any work, and the path is left as it was (issue 43).
// `coverage --results` a FIFO is refused at once rather than waiting for a writer.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <set>
#include <nlohmann/json.hpp>

#include "core/image.h"
#include "core/image_io.h"
#include "harness/cli_fixture.h"
#include "run/results.h"
#include "support/text.h"

namespace taa {
namespace {

namespace fs = std::filesystem;
using test::HarnessCli;

std::string readWhole(const fs::path& p) {
  return test::readFile(p);
}

class OutputPathCli : public HarnessCli {
 protected:
  void SetUp() override {
    HarnessCli::SetUp();
    ASSERT_EQ(::mkfifo((root_ / "fifo").c_str(), 0600), 0);
    std::ofstream(root_ / "target") << "kept";
    fs::create_symlink(root_ / "target", root_ / "link");
  }
  // Refused with exit 2 naming the path, and the FIFO, the link and its target as they were.
  void expectRefused(const std::string& args, const std::string& path, const std::string& why) {
    const auto r = harness(args);
    EXPECT_EQ(r.exitCode, 2) << args << "\n" << r.output;
    EXPECT_NE(r.output.find(path), std::string::npos) << r.output;
    EXPECT_NE(r.output.find(why), std::string::npos) << r.output;
    EXPECT_TRUE(fs::is_fifo(root_ / "fifo"));
    EXPECT_TRUE(fs::is_symlink(root_ / "link"));
    EXPECT_EQ(readWhole(root_ / "target"), "kept");
  }
};

TEST_F(OutputPathCli, BakeWritesNoFifoLinkDeviceNorItsOwnCase) {
  const std::string bake = "bake " + casePath("small") + " --out ";
  expectRefused(bake + (root_ / "fifo").string(), "fifo", "a FIFO");
  expectRefused(bake + (root_ / "link").string(), "link", "a symbolic link");
  const std::string before = readWhole(casePath("small"));
  expectRefused(bake + casePath("small"), "small.json", "own input");
  expectRefused(bake + (root_ / "cases" / "." / "small.json").string(), "small.json", "own input");
  EXPECT_EQ(readWhole(casePath("small")), before);
  if (::geteuid() == 0) {  // /dev/full's twin, so a regression replaces it, not /dev/full
    const fs::path full = root_ / "full";
    ASSERT_EQ(::mknod(full.c_str(), S_IFCHR | 0666, ::makedev(1, 7)), 0);
    expectRefused(bake + full.string(), full.string(), "a device");
    struct stat st {};
    ASSERT_EQ(::lstat(full.c_str(), &st), 0);
    EXPECT_TRUE(S_ISCHR(st.st_mode));
  }
  const auto ok = harness(bake + (root_ / "track.json").string());
  EXPECT_EQ(ok.exitCode, 0) << ok.output;  // a new path is written
}

TEST_F(OutputPathCli, CompareHeatmapWritesNoFifoLinkNorAnInput) {
  const std::string a = (root_ / "a.png").string(), b = (root_ / "b.png").string();
  writePng(a, Image(8, 8, 4, 0.25f));
  writePng(b, Image(8, 8, 4, 0.5f));
  const std::string compare = "compare " + a + " " + b + " --heatmap ";
  expectRefused(compare + (root_ / "fifo").string(), "fifo", "a FIFO");
  expectRefused(compare + (root_ / "link").string(), "link", "a symbolic link");
  const std::string before = readWhole(b);
  expectRefused(compare + b, "b.png", "own input");
  EXPECT_EQ(readWhole(b), before);
  const auto ok = harness(compare + (root_ / "heat.png").string());
  EXPECT_NE(ok.exitCode, 2) << ok.output;
  EXPECT_TRUE(fs::is_regular_file(root_ / "heat.png"));
}

TEST_F(OutputPathCli, CoverageResultsAFifoIsRefusedAtOnce) {
  const auto start = std::chrono::steady_clock::now();
  const auto r =
      harness("coverage " + casePath("small") + " --results " + (root_ / "fifo").string());
  EXPECT_EQ(r.exitCode, 2) << r.output;
  EXPECT_NE(r.output.find("a FIFO"), std::string::npos) << r.output;
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(30));
  // A traced constant that is no number: exit 2 naming the file and the key (was "stoi", 3).
  run::RunResults forged;
  forged.cases.emplace_back();
  forged.cases[0].name = "small";
  forged.cases[0].log = {"taa_resolve spec constants: 0=99999999999"};
  std::ofstream(root_ / "results.json") << run::toJson(forged).dump();
  const auto bad =
      harness("coverage " + casePath("small") + " --results " + (root_ / "results.json").string());
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("results.json: cases[0].log"), std::string::npos) << bad.output;
}

// The resolve's lines are named as a developer finds them, from the repository's shaders/ folder,
// wherever the build installed the sources.
TEST_F(OutputPathCli, CoverageNamesTheResolvesLinesUnderShaders) {
  run::RunResults traced;
  traced.cases.emplace_back();
  traced.cases[0].name = "small";
  traced.cases[0].log = {
      "taa_resolve spec constants: 0=2 1=1 19=0 20=0 21=0 2=0 3=2 4=2 5=3 6=1 7=0 8=1 9=0 10=0 "
      "11=0 23=0 12=0 13=1 14=0 15=0 16=0 24=0 17=0 18=0 25=0 26=0 27=0 22=0"};
  std::ofstream(root_ / "results.json") << run::toJson(traced).dump();
  const auto r = harness("coverage " + casePath("small") + " --results " +
                         (root_ / "results.json").string() + " --json");
  ASSERT_EQ(r.exitCode, 0) << r.output;
  const auto j = nlohmann::json::parse(r.output.substr(r.output.find('{')));
  std::set<std::string> files;
  for (const auto& line : j.at("resolve_lines")) files.insert(line.at("file").get<std::string>());
  EXPECT_TRUE(files.count("shaders/taa/rectify.glsl")) << r.output.substr(0, 2000);
  for (const auto& f : files) EXPECT_EQ(f.rfind("shaders/", 0), 0u) << f;
}

}  // namespace
}  // namespace taa
