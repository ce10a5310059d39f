// Files read out of another run's folder (core/contained_file.h): inside it after resolving
// links, regular, bounded; a forged path, a link out, a FIFO or a device is refused unread.
#include "core/contained_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <chrono>
#include <filesystem>
#include <fstream>

namespace taa {
namespace {

namespace fs = std::filesystem;

fs::path containedScratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(TAA_TEST_OUT) / "contained_file" / info->name();
  fs::remove_all(dir);
  fs::create_directories(dir / "run" / "case");
  return dir;
}

std::string containedRefusal(const fs::path& folder, const fs::path& rel, uint64_t limit = 1024) {
  try {
    readContainedFile(folder, rel, limit, "the image");
  } catch (const InputFileError& e) {
    return e.what();
  }
  return "";
}

TEST(ContainedFile, ReadsAFileInsideTheFolder) {
  const fs::path run = containedScratch() / "run";
  std::ofstream(run / "case" / "f.png") << "png";
  EXPECT_EQ(readContainedFile(run, "case/f.png", 1024, "the image"), "png");
}

TEST(ContainedFile, RefusesWhatLeadsOutside) {
  const fs::path dir = containedScratch(), run = dir / "run";
  std::ofstream(dir / "secret") << "secret";
  fs::create_symlink(dir / "secret", run / "case" / "link.png");
  fs::create_symlink("..", run / "case" / "up");
  for (const char* rel : {"../secret", "case/../../secret", "case/link.png", "case/up/../secret",
                          "/etc/passwd", "../../../../../../etc/passwd"})
    EXPECT_NE(containedRefusal(run, rel).find("leads outside"), std::string::npos) << rel;
}

TEST(ContainedFile, RefusesFifosDevicesFoldersAndLargeFilesWithoutWaiting) {
  const fs::path run = containedScratch() / "run";
  ASSERT_EQ(::mkfifo((run / "case" / "fifo.png").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", run / "case" / "zero.png");
  std::ofstream(run / "case" / "big.png") << std::string(2048, 'x');
  const auto start = std::chrono::steady_clock::now();
  EXPECT_NE(containedRefusal(run, "case/fifo.png").find("a FIFO"), std::string::npos);
  EXPECT_NE(containedRefusal(run, "case").find("a directory"), std::string::npos);
  EXPECT_NE(containedRefusal(run, "case/big.png").find("over the limit"), std::string::npos);
  EXPECT_NE(containedRefusal(run, "case/zero.png").find("leads outside"), std::string::npos);
  EXPECT_NE(containedRefusal("/dev", "zero").find("a device"), std::string::npos);
  EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(5));
}

// The limit is the largest size read, not the first size refused.
TEST(ContainedFile, AFileOfExactlyTheLimitIsReadAndOneByteMoreIsNot) {
  const fs::path run = containedScratch() / "run";
  std::ofstream(run / "case" / "at.png") << std::string(1024, 'x');
  std::ofstream(run / "case" / "over.png") << std::string(1025, 'x');
  EXPECT_EQ(readContainedFile(run, "case/at.png", 1024, "the image").size(), 1024u);
  EXPECT_NE(containedRefusal(run, "case/over.png").find("over the limit"), std::string::npos);
}

}  // namespace
}  // namespace taa
