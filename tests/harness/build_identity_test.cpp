// The digests a verdict is reused under (run/build_identity.h): a golden folder's and the
// SPIR-V folder's read every file's bytes, so a file rewritten in place at the same size (a
// re-blessed manifest, a rebuilt shader with one constant changed) is another digest.
#include "run/build_identity.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

namespace taa::build_identity_test {

namespace fs = std::filesystem;

fs::path freshFolder(const std::string& name) {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "build-identity" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

void write(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

TEST(FolderDigest, ReadsEveryFilesBytesAndName) {
  const fs::path dir = freshFolder("goldens");
  write(dir / "manifest.json", R"({"reason": "first bless"})");
  write(dir / "frame_0003.exr", "pixels");
  const std::string digest = run::folderDigest(dir);
  EXPECT_EQ(run::folderDigest(dir), digest);
  write(dir / "manifest.json", R"({"reason": "other bless"})");  // same size
  const std::string rewritten = run::folderDigest(dir);
  EXPECT_NE(rewritten, digest);
  write(dir / "frame_0003.exr", "pixelz");
  EXPECT_NE(run::folderDigest(dir), rewritten);
  write(dir / "frame_0003.exr", "pixels");
  EXPECT_EQ(run::folderDigest(dir), rewritten);
  fs::rename(dir / "frame_0003.exr", dir / "frame_0004.exr");
  EXPECT_NE(run::folderDigest(dir), rewritten);
  EXPECT_EQ(run::folderDigest(dir / "absent"), "none");
}

}  // namespace taa::build_identity_test
