#include "core/input_file.h"

#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string_view>
#include <vector>

#include "core/json_guard.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

fs::path scratch() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(TAA_TEST_OUT) / "input_file" / info->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string refusal(const fs::path& file, uint64_t limit = kMaxCaseFileBytes) {
  try {
    readInputFile(file, limit);
  } catch (const InputFileError& e) {
    return e.what();
  }
  return "";
}

TEST(InputFile, ReadsARegularFileWhole) {
  const fs::path f = scratch() / "a.json";
  std::ofstream(f, std::ios::binary) << std::string("{\"x\": 1}\n\0tail", 14);
  EXPECT_EQ(readInputFile(f, 100), std::string("{\"x\": 1}\n\0tail", 14));
}

// A read(2) on NFS or FUSE may deliver fewer bytes than asked, or stop with EINTR: each piece
// lands after the last, whatever the pieces' sizes.
TEST(InputFile, ShortReadsAndInterruptionsFillTheBufferInOrder) {
  const std::string source = "0123456789abcdefghijklmnopqrstuvwxyz";
  for (size_t piece : {1u, 3u, 7u, 64u}) {
    size_t at = 0;
    bool interrupted = false;
    auto readSome = [&](char* dst, size_t n) -> ssize_t {
      if (!interrupted && at == piece) {  // once, after the first piece
        interrupted = true;
        errno = EINTR;
        return -1;
      }
      const size_t k = std::min({n, piece, source.size() - at});
      std::memcpy(dst, source.data() + at, k);
      at += k;
      return ssize_t(k);
    };
    std::string buf(source.size(), '.');
    EXPECT_EQ(readFully(buf.data(), buf.size(), readSome, "f"), source.size()) << piece;
    EXPECT_EQ(buf, source) << piece;
  }
  // A file that shrank: what was there; a read error: refused, naming the file.
  size_t calls = 0;
  std::string shrunk(8, '.');
  EXPECT_EQ(readFully(shrunk.data(), shrunk.size(),
                      [&](char* dst, size_t) -> ssize_t { return calls++ ? 0 : (*dst = 'a', 1); }, "f"),
            1u);
  EXPECT_EQ(shrunk, "a.......");
  try {
    readFully(shrunk.data(), shrunk.size(), [](char*, size_t) -> ssize_t { return errno = EIO, -1; },
              "/data/broken.bin");
    ADD_FAILURE() << "a read error was not refused";
  } catch (const InputFileError& e) {
    EXPECT_NE(std::string(e.what()).find("/data/broken.bin: cannot be read"), std::string::npos)
        << e.what();
  }
}

TEST(InputFile, RefusesWhatIsNotARegularFileWithoutReadingIt) {
  const fs::path dir = scratch();
  ASSERT_EQ(::mkfifo((dir / "fifo.json").c_str(), 0600), 0);
  fs::create_symlink("/dev/zero", dir / "zero.json");
  fs::create_directories(dir / "folder.gltf");
  // Each would hang, never end or fail with bad_alloc if it were read.
  EXPECT_NE(refusal(dir / "fifo.json").find("fifo.json: is a FIFO"), std::string::npos);
  EXPECT_NE(refusal(dir / "zero.json").find("zero.json: is a device"), std::string::npos);
  EXPECT_NE(refusal(dir / "folder.gltf").find("folder.gltf: is a directory"), std::string::npos);
  EXPECT_NE(refusal(dir / "missing.json").find("missing.json: does not exist"), std::string::npos);
  // A file where a folder of the path should be: not there either, for callers that tell
  // absence apart (a cache, a golden manifest).
  EXPECT_THROW(readInputFile(dir / "fifo.json" / "x.json", 100), InputFileMissing);
}

// A path resolved once is read without following a link put in its place: the link is named
// as such, and a loop in the folders before it as a loop, not as a link.
TEST(InputFile, ALastLinkRefusedIsNamedApartFromALoopBeforeIt) {
  const fs::path dir = scratch();
  std::ofstream(dir / "real.json") << "{}";
  fs::create_symlink(dir / "real.json", dir / "link.json");
  fs::create_symlink(dir / "loop_b", dir / "loop_a");
  fs::create_symlink(dir / "loop_a", dir / "loop_b");
  EXPECT_EQ(readInputFile(dir / "link.json", 100), "{}");
  auto refused = [](const fs::path& f) {
    try {
      readInputFile(f, 100, LastLink::Refuse);
    } catch (const InputFileError& e) {
      return std::string(e.what());
    }
    return std::string("read");
  };
  EXPECT_NE(refused(dir / "link.json").find("link.json: is a symbolic link;"), std::string::npos);
  const std::string loop = refused(dir / "loop_a" / "x.json");
  EXPECT_NE(loop.find("x.json: is a symbolic-link loop"), std::string::npos) << loop;
}

// The problem alone, for callers with a fix of their own: no path before it, no input's fix
// after it.
TEST(InputFile, TheRefusalsProblemStandsWithoutPathOrFix) {
  const fs::path dir = scratch();
  ASSERT_EQ(::mkfifo((dir / "fifo.json").c_str(), 0600), 0);
  std::ofstream(dir / "big.csv") << std::string(1000, 'x');
  for (const auto& [file, problem] :
       {std::pair<fs::path, std::string>{dir / "fifo.json",
                                         "is a FIFO (named pipe), not a regular file"},
        {dir / "big.csv", "is 1000 bytes, over the limit of 0 MiB for this kind of input"}}) {
    try {
      readInputFile(file, 999);
      ADD_FAILURE() << file << " read";
    } catch (const InputFileError& e) {
      EXPECT_EQ(refusalProblem(e, file), problem) << e.what();
    }
  }
}

TEST(InputFile, RefusesAFileOverItsLimitBeforeReading) {
  const fs::path f = scratch() / "big.csv";
  std::ofstream(f) << std::string(1000, 'x');
  EXPECT_NE(refusal(f, 999).find("big.csv: is 1000 bytes, over the limit"), std::string::npos);
  EXPECT_EQ(readInputFile(f, 1000).size(), 1000u);
}

TEST(InputFile, ContainmentSeesThroughSymbolicLinks) {
  const fs::path dir = scratch();
  fs::create_directories(dir / "case" / "sub");
  std::ofstream(dir / "outside.json") << "secret";
  std::ofstream(dir / "case" / "sub" / "inside.json") << "{}";
  fs::create_symlink("../outside.json", dir / "case" / "escape.json");
  fs::create_symlink("sub/inside.json", dir / "case" / "alias.json");
  fs::create_symlink(dir, dir / "case" / "up");
  fs::create_symlink("/etc/passwd", dir / "case" / "passwd.json");
  EXPECT_EQ(containedRealPath(dir / "case", dir / "case" / "alias.json", "the track"),
            fs::canonical(dir / "case" / "sub" / "inside.json"));
  for (const char* name : {"escape.json", "up/outside.json", "passwd.json"}) {
    SCOPED_TRACE(name);
    try {
      containedRealPath(dir / "case", dir / "case" / name, "the track");
      ADD_FAILURE() << "accepted";
    } catch (const InputFileError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(name), std::string::npos) << msg;
      EXPECT_NE(msg.find("outside"), std::string::npos) << msg;
      EXPECT_EQ(msg.find("root:"), std::string::npos) << "content echoed: " << msg;
      EXPECT_EQ(msg.find("secret"), std::string::npos) << "content echoed: " << msg;
    }
  }
}

TEST(JsonGuard, AcceptsOrdinaryJson) {
  EXPECT_EQ(jsonStructureProblem(R"({"a": {"a": [1, {"a": 2}]}, "b": "{\"a\": 1, \"a\": 2}"})"),
            "");
  EXPECT_EQ(jsonStructureProblem("[[[[1]]]]", 4), "");
}

TEST(JsonGuard, DuplicateKeysNameBothPlaces) {
  const std::string p =
      jsonStructureProblem("{\n  \"render\": {\"width\": 64},\n  \"render\": {}\n}");
  EXPECT_NE(p.find("line 3, column 3: key \"render\" appears twice"), std::string::npos) << p;
  EXPECT_NE(p.find("first at line 2, column 3"), std::string::npos) << p;
  // Escapes spell the same key: the parser would merge them too.
  EXPECT_NE(jsonStructureProblem(R"({"ab": 1, "\u0061b": 2})").find("\"ab\" appears twice"),
            std::string::npos);
  EXPECT_NE(jsonStructureProblem(R"([{"x": [{}], "y": {"z": 1, "z": 2}}])").find("\"z\""),
            std::string::npos);
}

TEST(JsonGuard, BoundsNestingWithoutRecursion) {
  const std::string deep = std::string(100000, '[') + std::string(100000, ']');
  const std::string p = jsonStructureProblem(deep);
  EXPECT_NE(p.find("nested more than 256 levels"), std::string::npos) << p;
  EXPECT_EQ(jsonStructureProblem(std::string(256, '[') + std::string(256, ']')), "");
  // Brackets inside strings are text, not nesting.
  EXPECT_EQ(jsonStructureProblem("[\"" + std::string(1000, '[') + "\"]"), "");
}

TEST(JsonGuard, MalformedTextEndsTheScanWithoutAProblem) {
  for (const char* text : {"{\"a", "{\"a\\", "\"\\u12", "}}]]", "{\"a\": 1,,, \"a\"", ""}) {
    EXPECT_NO_THROW(jsonStructureProblem(text)) << text;
    // The text ending exactly where its allocation ends (no terminating zero after it, as a
    // file's bytes or a fuzzer's input): under ASan a read past the end is a report.
    const std::string_view view(text);
    const std::vector<char> exact(view.begin(), view.end());
    EXPECT_EQ(jsonStructureProblem(std::string_view(exact.data(), exact.size())),
              jsonStructureProblem(text))
        << text;
  }
}

}  // namespace
}  // namespace taa
