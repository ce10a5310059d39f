// The digest of the files a case reads (a reference kept on disk is keyed by it) is exactly
// SHA-256 over each file as (key length, byte length, key, bytes): the lengths delimit the
// parts, so moving bytes from one file's end to the next file's start changes the digest, and
// nothing but those parts (no padding, no stack bytes) goes in.
#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>

#include "case/case_loader.h"
#include "core/sha256.h"

namespace taa::referenced_files_hash_test {
namespace {

namespace fs = std::filesystem;

TEST(ReferencedFilesHash, IsEachFilesLengthsKeyAndBytesInOrder) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "referenced_files_hash";
  fs::remove_all(dir);
  fs::create_directories(dir / "scenes");
  const std::string gltf = R"({"asset": {"version": "2.0"},
    "buffers": [{"uri": "mesh.bin", "byteLength": 12}]})";
  const std::string bin(12, '\7');
  std::ofstream(dir / "scenes/scene.gltf", std::ios::binary) << gltf;
  std::ofstream(dir / "scenes/mesh.bin", std::ios::binary) << bin;
  std::ofstream(dir / "case.json") << R"({"scene": {"gltf": "scenes/scene.gltf"}, "script": {"frames": 2}})";

  Sha256 h;
  for (const auto& [key, bytes] : {std::pair<std::string, std::string>{"scene.gltf", gltf},
                                   {"scene.gltf mesh.bin", bin}}) {
    const uint64_t n[2] = {key.size(), bytes.size()};
    h.update(n, sizeof(n));
    h.update(key.data(), key.size());
    h.update(bytes.data(), bytes.size());
  }
  const auto digest = h.finish();
  EXPECT_EQ(cases::referencedFilesSha256(cases::loadCase(dir / "case.json").spec),
            toHex(digest.data(), digest.size()));
}

}  // namespace
}  // namespace taa::referenced_files_hash_test
