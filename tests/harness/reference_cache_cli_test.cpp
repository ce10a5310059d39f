// References kept across runs, as runs use them (api/reference_store.h): a second process
// reads every reference from disk and gets the first one's results; a tampered entry, two
// runs at once, an edited shader and a folder that cannot be written, each through the
// executable. Each test has its own cache folder (TAA_REFERENCE_CACHE_DIR).
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <regex>
#include <sstream>

#include "api/device.h"
#include "cli_fixture.h"
#include "support/text.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

// Moving (every frame a new reference), with the energy invariant reading the reference, in
// taa.mode `mode`. "off" unless the test is about the resolve: the reference reads none of its
// settings, and a run costs half the CPU without the resolve's pipelines.
std::string refCase(const std::string& mode = "off") {
  return R"({
  "scene": {"builtin": "checkerboard"}, "render": {"width": 48, "height": 27},
  "camera": {"strafe": {"speed": 0.5, "distance": 0.2}},
  "script": {"frames": 6}, "output": {"frames": [5]}, "reference": {"samples": 4},
  "checks": {"golden": false, "invariants": ["energy"], "energy": {"epsilon": 1}},
  "taa": {"mode": ")" +
         mode + R"("}
})";
}

struct Counts {
  long rendered = -1, fromDisk = -1, reused = -1;
};

Counts countsOf(const std::string& output) {
  static const std::regex line(R"(references: (\d+) rendered, (\d+) from disk, (\d+) reused)");
  std::smatch m;
  Counts c;
  if (std::regex_search(output, m, line)) c = {std::stol(m[1]), std::stol(m[2]), std::stol(m[3])};
  return c;
}

class ReferenceCacheCli : public test::HarnessCli {
 protected:
  void SetUp() override {
    HarnessCli::SetUp();
    cache_ = root_ / "reference-cache";
    writeCase("ref", refCase());
  }
  test::ProcessResult runRef(const std::string& extra = "", const std::string& env = "") {
    return run("ref", extra, "TAA_REFERENCE_CACHE_DIR=" + cache_.string() + " " + env);
  }
  // Each checked frame's reference RMSE: equal doubles for bit-identical references.
  nlohmann::json referenceRmse(const fs::path& out) const {
    const auto j = nlohmann::json::parse(test::readFile(out / "results.json"));
    return j["cases"][0]["reference_rmse"];
  }
  std::vector<fs::path> entries() const {
    std::vector<fs::path> out;
    for (const auto& e : fs::directory_iterator(cache_))
      if (e.path().extension() == ".ref") out.push_back(e.path());
    return out;
  }
  fs::path cache_;
};

TEST_F(ReferenceCacheCli, ASecondRunReadsEveryReferenceFromDiskWithTheSameResults) {
  const auto cold = runRef();
  ASSERT_EQ(cold.exitCode, 0) << cold.output;
  const Counts first = countsOf(cold.output);
  ASSERT_GT(first.rendered, 0) << cold.output;
  EXPECT_EQ(first.fromDisk, 0) << cold.output;
  const auto rmse = referenceRmse(root_ / "out");
  ASSERT_FALSE(rmse.empty());
  EXPECT_EQ(long(entries().size()), first.rendered);

  const auto warm = runRef();
  ASSERT_EQ(warm.exitCode, 0) << warm.output;
  const Counts second = countsOf(warm.output);
  EXPECT_EQ(second.rendered, 0) << warm.output;
  EXPECT_EQ(second.fromDisk, first.rendered) << warm.output;
  EXPECT_EQ(referenceRmse(root_ / "out"), rmse);

  // --no-reference-cache renders every one and neither reads nor writes the folder.
  fs::remove_all(cache_);
  const auto off = runRef("--no-reference-cache");
  ASSERT_EQ(off.exitCode, 0) << off.output;
  EXPECT_EQ(countsOf(off.output).rendered, first.rendered + first.reused) << off.output;
  EXPECT_EQ(countsOf(off.output).fromDisk, 0) << off.output;
  EXPECT_FALSE(fs::exists(cache_));
  EXPECT_EQ(referenceRmse(root_ / "out"), rmse);
}

TEST_F(ReferenceCacheCli, ATamperedEntryIsRenderedAgain) {
  const auto cold = runRef();
  ASSERT_EQ(cold.exitCode, 0) << cold.output;
  const auto rmse = referenceRmse(root_ / "out");
  const auto files = entries();
  ASSERT_FALSE(files.empty());
  for (const auto& f : files) {  // one pixel bit each
    std::string b = test::readFile(f);
    b[b.size() - 7] = char(b[b.size() - 7] ^ 0x01);
    std::ofstream(f, std::ios::binary | std::ios::trunc) << b;
  }
  const auto again = runRef();
  ASSERT_EQ(again.exitCode, 0) << again.output;
  EXPECT_EQ(countsOf(again.output).fromDisk, 0) << again.output;
  EXPECT_EQ(countsOf(again.output).rendered, countsOf(cold.output).rendered) << again.output;
  EXPECT_NE(again.output.find("note: reference cache"), std::string::npos) << again.output;
  EXPECT_EQ(referenceRmse(root_ / "out"), rmse);
}

TEST_F(ReferenceCacheCli, TwoRunsAtOnceOnOneCacheGiveTheResultsOfOne) {
  const auto alone = runRef("", "TAA_REFERENCE_CACHE_DIR=" + (root_ / "alone").string());
  ASSERT_EQ(alone.exitCode, 0) << alone.output;
  const auto rmse = referenceRmse(root_ / "out");
  std::string both;
  for (const char* out : {"a", "b"})
    both += std::string("CI=false TAA_REFERENCE_CACHE_DIR=") + cache_.string() + " " +
            TAA_HARNESS_BIN + " run " + casePath("ref") + " --out " + (root_ / out).string() +
            " >" + (root_ / out).string() + ".log 2>&1 & " + out + "=$!; ";
  ASSERT_EQ(std::system(("bash -c '" + both + "wait $a && wait $b'").c_str()), 0)
      << test::readFile(root_ / "a.log") << test::readFile(root_ / "b.log");
  EXPECT_EQ(referenceRmse(root_ / "a"), rmse) << test::readFile(root_ / "a.log");
  EXPECT_EQ(referenceRmse(root_ / "b"), rmse) << test::readFile(root_ / "b.log");
  // What they left is whole: a third run reads every reference.
  const auto third = runRef();
  EXPECT_EQ(countsOf(third.output).rendered, 0) << third.output;
  EXPECT_EQ(referenceRmse(root_ / "out"), rmse);
}

// The SPIR-V of a shader the reference runs is part of the key; the resolve's is not. The
// header's generator word (word 2) is read by no consumer: the shader runs the same.
TEST_F(ReferenceCacheCli, AReferenceShaderEditMissesAResolveShaderEditHits) {
  writeCase("ref", refCase("full"));  // the resolve's SPIR-V is edited
  const fs::path shaders = root_ / "shaders";
  fs::copy(shaderFolder(), shaders, fs::copy_options::recursive);
  const std::string env = "TAA_SHADER_DIR=" + shaders.string();
  auto editGenerator = [&](const char* file) {
    std::string b = test::readFile(shaders / file);
    b[8] = char(b[8] ^ 0x01);
    std::ofstream(shaders / file, std::ios::binary | std::ios::trunc) << b;
  };
  const auto cold = runRef("", env);
  ASSERT_EQ(cold.exitCode, 0) << cold.output;
  const long rendered = countsOf(cold.output).rendered;
  ASSERT_GT(rendered, 0) << cold.output;
  editGenerator("taa_resolve.comp.spv");
  const auto resolveEdit = runRef("", env);
  EXPECT_EQ(countsOf(resolveEdit.output).rendered, 0) << resolveEdit.output;
  EXPECT_EQ(countsOf(resolveEdit.output).fromDisk, rendered) << resolveEdit.output;
  editGenerator("reference_accumulate.comp.spv");
  const auto referenceEdit = runRef("", env);
  EXPECT_EQ(countsOf(referenceEdit.output).rendered, rendered) << referenceEdit.output;
  EXPECT_EQ(countsOf(referenceEdit.output).fromDisk, 0) << referenceEdit.output;
}

TEST_F(ReferenceCacheCli, AFolderThatCannotBeWrittenIsANoteAndABadLimitIsRefused) {
  std::ofstream(root_ / "file") << "x";
  const auto r = run("ref", "", "TAA_REFERENCE_CACHE_DIR=" + (root_ / "file" / "refs").string());
  EXPECT_EQ(r.exitCode, 0) << r.output;
  EXPECT_NE(r.output.find("note: reference cache"), std::string::npos) << r.output;
  EXPECT_GT(countsOf(r.output).rendered, 0) << r.output;
  const auto bad = runRef("", "TAA_REFERENCE_CACHE_MAX_MB=lots");
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("TAA_REFERENCE_CACHE_MAX_MB='lots'"), std::string::npos) << bad.output;
}

}  // namespace
}  // namespace taa
