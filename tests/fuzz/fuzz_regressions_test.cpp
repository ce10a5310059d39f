// Replays the checked-in fuzz corpus (tests/fuzz/corpus/TARGET/*): hostile inputs made by
// hand and every input a fuzzer found crashing. Each must be read or refused with the
// reader's own error; under ci/sanitize.sh this also runs with ASan and UBSan.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "fuzz_inputs.h"
#include "support/text.h"

namespace taa::fuzz {
namespace {

namespace fs = std::filesystem;

std::vector<fs::path> corpus(const std::string& target) {
  std::vector<fs::path> files;
  for (const auto& e :
       fs::directory_iterator(fs::path(TAA_SOURCE_DIR) / "tests/fuzz/corpus" / target))
    if (e.is_regular_file()) files.push_back(e.path());
  std::sort(files.begin(), files.end());
  return files;
}

void replay(const std::string& target, void (*read)(const std::string&)) {
  const auto files = corpus(target);
  EXPECT_GE(files.size(), 3u) << "the " << target << " corpus is missing";
  for (const fs::path& f : files) {
    SCOPED_TRACE(f.string());
    EXPECT_NO_THROW(read(test::readFile(f)));
  }
}

TEST(FuzzRegressions, CaseCorpus) {
  replay("case", &readCase);
}
TEST(FuzzRegressions, ShaderCorpus) {
  replay("shader", &compileHlsl);
}
TEST(FuzzRegressions, TrackCorpus) {
  replay("track", &readTrack);
}
TEST(FuzzRegressions, GltfCorpus) {
  replay("gltf", &readGltf);
}
TEST(FuzzRegressions, ImageCorpus) {
  replay("image", &readImageBytes);
}
TEST(FuzzRegressions, ResultsCorpus) {
  replay("results", &readFolderJson);
}
TEST(FuzzRegressions, LanesCorpus) {
  replay("lanes", &readLanes);
}
TEST(FuzzRegressions, ReferenceEntryCorpus) {
  replay("reference_entry", &readReferenceEntry);
  // The corpus's valid entries decode: the fuzzer starts from inputs that reach the pixels.
  EXPECT_TRUE(decodeReferenceEntry(
      test::readFile(fs::path(TAA_SOURCE_DIR) / "tests/fuzz/corpus/reference_entry/valid_2x2_rgba"),
      kFuzzReferenceKey));
}
TEST(FuzzRegressions, SpirvCacheCorpus) {
  replay("spirv_cache", [](const std::string& deps) { (void)readSpirvCacheEntry(deps); });
  // The corpus's whole entry is a hit: the fuzzer starts from lines that reach the words.
  EXPECT_TRUE(readSpirvCacheEntry(
      test::readFile(fs::path(TAA_SOURCE_DIR) / "tests/fuzz/corpus/spirv_cache/whole_entry")));
}

}  // namespace
}  // namespace taa::fuzz
