// The case input hash (LoadedCase::sha256) covers every file a case reads, transitively: a
// verdict reused by `run --verdict-from` and a golden's staleness both hang on it, so a
// texture or buffer a glTF references counts as much as the case file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "case/case_loader.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

class InputHash : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    dir_ = fs::path(TAA_TEST_OUT) / "input_hash" / info->name();
    fs::remove_all(dir_);
    fs::create_directories(dir_ / "scenes" / "tex");
    write("scenes/mesh.bin", std::string(12, '\1'));
    write("scenes/tex/a b.png", "png one");
    write("scenes/scene.gltf", R"({"asset": {"version": "2.0"},
      "buffers": [{"uri": "mesh.bin", "byteLength": 12},
                  {"uri": "data:application/octet-stream;base64,AAAA", "byteLength": 3}],
      "images": [{"uri": "tex/a%20b.png"}]})");
    write("case.json", R"({"scene": {"gltf": "scenes/scene.gltf"}, "script": {"frames": 2}})");
  }
  void write(const std::string& rel, const std::string& bytes) {
    std::ofstream(dir_ / rel, std::ios::binary) << bytes;
  }
  std::string hash() { return cases::loadCase(dir_ / "case.json").sha256; }
  fs::path dir_;
};

TEST_F(InputHash, AGltfsImageAndBufferAreInputs) {
  const std::string before = hash();
  EXPECT_EQ(hash(), before);               // the same bytes, the same hash
  write("scenes/tex/a b.png", "png two");  // the texture replaced (a percent-encoded uri)
  const std::string texture = hash();
  EXPECT_NE(texture, before);
  write("scenes/mesh.bin", std::string(12, '\2'));  // the external buffer edited
  EXPECT_NE(hash(), texture);
}

TEST_F(InputHash, AnUnreadableReferenceIsHashedNotRefused) {
  // Loading the scene reports a missing buffer; the hash only has to differ.
  const std::string before = hash();
  fs::remove(dir_ / "scenes" / "mesh.bin");
  EXPECT_NE(hash(), before);
}

TEST_F(InputHash, AMoverModelsFilesAreInputsToo) {
  write("case.json", R"({"movers": [{"shape": "gltf", "gltf": "scenes/scene.gltf"}],
                         "script": {"frames": 2}})");
  const std::string before = hash();
  write("scenes/tex/a b.png", "png two");
  EXPECT_NE(hash(), before);
}

}  // namespace
}  // namespace taa
