// The one output-path rule (core/output_file.h): outputs go to a new path or over a regular
// file, never to a device, FIFO or link, nor over the command's own input.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/sysmacros.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/input_file.h"
#include "core/output_file.h"
#include "support/text.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

fs::path outputScratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(TAA_TEST_OUT) / "output_path" / info->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string outputRefusal(const fs::path& file, const std::vector<fs::path>& inputs = {}) {
  try {
    checkOutputPath(file, inputs, "--out");
  } catch (const OutputPathError& e) {
    return e.what();
  }
  return "";
}

TEST(OutputPath, ANewPathOrARegularFileIsWritten) {
  const fs::path dir = outputScratch();
  EXPECT_EQ(outputRefusal(dir / "new.png"), "");
  std::ofstream(dir / "old.png") << "old";
  EXPECT_EQ(outputRefusal(dir / "old.png"), "");
  writeFileAtomically(dir / "old.png", "new");
  EXPECT_EQ(test::readFile(dir / "old.png"), "new");
}

// A harness started with its standard input closed (`<&-`, some CI runners and daemons) gets
// descriptor 0 for the next file it opens: a valid descriptor, for writing and for reading.
TEST(OutputPath, AFileOpenedOnDescriptorZeroIsWrittenAndRead) {
  const fs::path dir = outputScratch();
  const int saved = ::dup(0);
  ASSERT_GE(saved, 0);
  ::close(0);
  std::string failure, read;
  try {
    writeFileAtomically(dir / "on_fd0.txt", "written");
    read = readInputFile(dir / "on_fd0.txt", 100);
  } catch (const std::exception& e) {
    failure = e.what();
  }
  ::dup2(saved, 0);
  ::close(saved);
  EXPECT_EQ(failure, "");
  EXPECT_EQ(read, "written");
  EXPECT_EQ(test::readFile(dir / "on_fd0.txt"), "written");
}

TEST(OutputPath, AFifoOrALinkIsRefusedAndSurvives) {
  const fs::path dir = outputScratch();
  ASSERT_EQ(::mkfifo((dir / "fifo").c_str(), 0600), 0);
  std::ofstream(dir / "target") << "kept";
  fs::create_symlink(dir / "target", dir / "link");
  fs::create_symlink("/dev/null", dir / "null");
  for (const char* name : {"fifo", "link", "null"}) {
    EXPECT_NE(outputRefusal(dir / name).find(std::string(dir / name) + ": is a"), std::string::npos)
        << name;
    // writeFileAtomically applies the type rule itself, for every writer.
    EXPECT_THROW(writeFileAtomically(dir / name, "x"), OutputPathError) << name;
  }
  EXPECT_NE(outputRefusal(dir / "fifo").find("FIFO"), std::string::npos);
  EXPECT_TRUE(fs::is_fifo(dir / "fifo"));
  EXPECT_TRUE(fs::is_symlink(dir / "link"));
  EXPECT_EQ(test::readFile(dir / "target"), "kept");
  EXPECT_EQ(fs::directory_iterator(dir) == fs::directory_iterator(), false);
  for (const auto& e : fs::directory_iterator(dir))  // no temporary left beside them
    EXPECT_EQ(e.path().filename().string().find(".tmp-"), std::string::npos) << e.path();
}

// The temporary file is created, never opened: a link or a file someone put under the name a
// write would pick (".NAME.tmp-PID-N" is predictable, and a cache folder may be shared) is passed
// over and left as it was. A child process writes, so that the test knows its PID beforehand.
TEST(OutputPath, ATemporaryNameTakenByALinkOrAFileIsPassedOver) {
  const fs::path dir = outputScratch();
  std::ofstream(dir / "victim") << "kept";
  int go[2];
  ASSERT_EQ(::pipe(go), 0);
  const pid_t child = ::fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    ::close(go[1]);
    char c = 0;
    if (::read(go[0], &c, 1) != 1) ::_exit(3);
    try {
      writeFileAtomically(dir / "out.txt", "written");
    } catch (...) {
      ::_exit(2);
    }
    ::_exit(0);
  }
  ::close(go[0]);
  const std::string taken = ".out.txt.tmp-" + std::to_string(child) + "-";
  fs::create_symlink(dir / "victim", dir / (taken + "0"));
  std::ofstream(dir / (taken + "1")) << "someone else's";
  ASSERT_EQ(::write(go[1], "x", 1), 1);
  ::close(go[1]);
  int status = 0;
  ASSERT_EQ(::waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0);
  EXPECT_EQ(test::readFile(dir / "out.txt"), "written");
  EXPECT_EQ(test::readFile(dir / "victim"), "kept");
  EXPECT_TRUE(fs::is_symlink(dir / (taken + "0")));
  EXPECT_EQ(test::readFile(dir / (taken + "1")), "someone else's");
}

TEST(OutputPath, ADeviceIsRefusedAndSurvives) {
  // As root a device's folder is writable, so a rename would replace the node with a file. The
  // node is /dev/full's twin made here (root only), so a regression replaces it, not /dev/full.
  if (::geteuid() != 0) GTEST_SKIP() << "making a device node needs root";
  const fs::path full = outputScratch() / "full";
  ASSERT_EQ(::mknod(full.c_str(), S_IFCHR | 0666, ::makedev(1, 7)), 0);
  EXPECT_NE(outputRefusal(full).find("a device"), std::string::npos);
  EXPECT_THROW(writeFileAtomically(full, "x"), OutputPathError);
  struct stat st {};
  ASSERT_EQ(::lstat(full.c_str(), &st), 0);
  EXPECT_TRUE(S_ISCHR(st.st_mode));
  EXPECT_THROW(createOutputDirectory(full), OutputPathError);
}

TEST(OutputPath, TheCommandsOwnInputIsRefused) {
  const fs::path dir = outputScratch();
  std::ofstream(dir / "v.json") << "{}";
  EXPECT_NE(outputRefusal(dir / "v.json", {dir / "v.json"}).find("own input"), std::string::npos);
  // Another spelling of the same file.
  EXPECT_NE(outputRefusal(dir / "sub" / ".." / "v.json", {dir / "v.json"}).find("own input"),
            std::string::npos);
  EXPECT_EQ(outputRefusal(dir / "w.json", {dir / "v.json"}), "");
}

}  // namespace
}  // namespace taa
