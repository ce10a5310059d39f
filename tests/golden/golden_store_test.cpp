// Replacing a case's goldens is all or nothing: a failure part-way (or a bless
// killed before its exchange) leaves the previous set whole and loadable.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/image_io.h"
#include "golden/golden_store.h"

namespace taa::golden {
namespace {

namespace fs = std::filesystem;

// A manifest whose frames are 4x3 images of `value` everywhere, as filesFor writes them.
Manifest manifestFor(const std::string& reason, const std::vector<int>& frames, float value) {
  Manifest m;
  m.caseName = "c";
  m.caseSha256 = std::string(64, 'a');
  m.bless = {"2026-11-22", "abc", reason};
  const std::string sha = pixelSha256(Image(4, 3, 4, value));
  m.sequence.assign(10, std::string(64, 'b'));
  for (int f : frames) {
    m.frames.push_back({f, "frame_" + std::to_string(f) + ".exr", sha, 4, 3});
    m.sequence[size_t(f)] = sha;
  }
  return m;
}

std::vector<std::pair<GoldenFrame, Image>> filesFor(const Manifest& m, float value) {
  std::vector<std::pair<GoldenFrame, Image>> out;
  for (const auto& f : m.frames) out.emplace_back(f, Image(4, 3, 4, value));
  return out;
}

fs::path freshRoot(const char* name) {
  const fs::path root = fs::path(TAA_TEST_OUT) / "golden-store" / name;
  fs::remove_all(root);
  fs::create_directories(root);
  return root;
}

TEST(GoldenStore, ReplaceWritesAndSwapsTheWholeSet) {
  const fs::path root = freshRoot("swap");
  const auto first = manifestFor("first", {1, 2}, 0.25f);
  replaceGoldens(root, first, filesFor(first, 0.25f));
  const auto second = manifestFor("second", {3}, 0.5f);
  replaceGoldens(root, second, filesFor(second, 0.5f));
  const auto loaded = loadGoldens(root, "c");
  ASSERT_TRUE(loaded);
  EXPECT_EQ(loaded->manifest.bless.reason, "second");
  ASSERT_EQ(loaded->manifest.frames.size(), 1u);
  EXPECT_FLOAT_EQ(loaded->load(loaded->manifest.frames[0]).at(0, 0, 0), 0.5f);
  EXPECT_FALSE(fs::exists(root / "c" / "frame_1.exr"));  // nothing of the old set lingers
  for (const auto& e : fs::directory_iterator(root)) EXPECT_EQ(e.path().filename(), "c");
}

TEST(GoldenStore, FailurePartWayLeavesTheOldSetWhole) {
  const fs::path root = freshRoot("failure");
  const auto good = manifestFor("good", {1, 2}, 0.25f);
  replaceGoldens(root, good, filesFor(good, 0.25f));
  const auto bad = manifestFor("bad", {1, 2}, 0.75f);
  auto files = filesFor(bad, 0.75f);
  files[1].second = Image();  // the second frame cannot be written
  EXPECT_ANY_THROW(replaceGoldens(root, bad, files));
  const auto loaded = loadGoldens(root, "c");
  ASSERT_TRUE(loaded);
  EXPECT_EQ(loaded->manifest.bless.reason, "good");
  for (const auto& f : loaded->manifest.frames) EXPECT_FLOAT_EQ(loaded->load(f).at(0, 0, 0), 0.25f);
  for (const auto& e : fs::directory_iterator(root)) EXPECT_EQ(e.path().filename(), "c");  // no staging left
}

// A goldens folder bless may not write to is refused up front, by name, with the old set
// untouched. Root passes every permission check, so as root the bless runs in a child that
// first drops to user nobody.
TEST(GoldenStore, AnUnwritableGoldensFolderIsRefusedByName) {
  const fs::path root = freshRoot("unwritable");
  const auto good = manifestFor("good", {1}, 0.25f);
  replaceGoldens(root, good, filesFor(good, 0.25f));
  const auto next = manifestFor("next", {2}, 0.5f);
  const auto files = filesFor(next, 0.5f);
  fs::permissions(root, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                            fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
  const pid_t pid = ::fork();
  if (pid == 0) {
    if (::geteuid() == 0 && ::setuid(65534) != 0) ::_exit(3);
    try {
      replaceGoldens(root, next, files);
    } catch (const std::exception& e) {
      ::_exit(std::string(e.what()).find("the goldens folder is not writable") != std::string::npos ? 0 : 1);
    }
    ::_exit(2);
  }
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  fs::permissions(root, fs::perms::owner_all);
  ASSERT_TRUE(WIFEXITED(status));
  EXPECT_EQ(WEXITSTATUS(status), 0) << "1: refused for another reason; 2: not refused; 3: cannot drop root";
  const auto loaded = loadGoldens(root, "c");
  ASSERT_TRUE(loaded);
  EXPECT_EQ(loaded->manifest.bless.reason, "good");
}

TEST(GoldenStore, LeftoversOfAKilledBlessAreIgnoredThenCleaned) {
  const fs::path root = freshRoot("killed");
  const auto good = manifestFor("good", {1}, 0.25f);
  replaceGoldens(root, good, filesFor(good, 0.25f));
  // What a bless killed before its exchange leaves: a hidden, half-written folder.
  fs::create_directories(root / ".c.bless-999999");
  std::ofstream(root / ".c.bless-999999" / "frame_1.exr") << "partial";
  EXPECT_EQ(loadGoldens(root, "c")->manifest.bless.reason, "good");
  const auto next = manifestFor("next", {1}, 0.5f);
  replaceGoldens(root, next, filesFor(next, 0.5f));
  EXPECT_FALSE(fs::exists(root / ".c.bless-999999"));
  EXPECT_EQ(loadGoldens(root, "c")->manifest.bless.reason, "next");
}

// The sweep at the start of every run and bless: the staging folder of a process that has
// ended goes, with a note naming it; a live process's, this process's and a name that is no
// staging folder stay.
TEST(GoldenStore, StaleStagingOfEndedProcessesIsRemovedAndOnlyThat) {
  const fs::path root = freshRoot("stale-staging");
  const pid_t ended = fork();
  ASSERT_GE(ended, 0);
  if (ended == 0) _exit(0);
  ASSERT_EQ(waitpid(ended, nullptr, 0), ended);
  const std::string dead = ".c.bless-" + std::to_string(ended);
  const std::vector<std::string> kept = {".c.bless-1", ".c.bless-" + std::to_string(getpid()),
                                         ".c.bless-", ".c.bless-12x", "c.bless-" + std::to_string(ended)};
  for (const auto& name : kept) fs::create_directories(root / name);
  fs::create_directories(root / dead);
  const auto notes = removeStaleStaging(root);
  EXPECT_FALSE(fs::exists(root / dead));
  ASSERT_EQ(notes.size(), 1u);
  EXPECT_NE(notes[0].find(dead), std::string::npos) << notes[0];
  for (const auto& name : kept) EXPECT_TRUE(fs::exists(root / name)) << name;
}

TEST(GoldenStore, MalformedManifestNamesTheFile) {
  const fs::path root = freshRoot("malformed");
  fs::create_directories(root / "c");
  std::ofstream(root / "c" / "manifest.json") << "{\"case\": 1}";
  try {
    loadGoldens(root, "c");
    FAIL() << "expected an error";
  } catch (const GoldenError& e) {
    EXPECT_NE(std::string(e.what()).find("manifest.json"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("git checkout -- "), std::string::npos) << e.what();
  }
}

// case_file is a folder and a file name (golden/case_owner.h), never a path: the fuzz corpus's
// two manifests, one well formed and one naming ../../etc/passwd, read and are refused.
TEST(GoldenStore, AManifestsCaseFileIsANameNotAPath) {
  const fs::path corpus = fs::path(TAA_SOURCE_DIR) / "tests/fuzz/corpus/results";
  EXPECT_EQ(readManifest(corpus / "manifest_with_case_file.json").caseFile, "cases/x.json");
  try {
    readManifest(corpus / "manifest_forged_case_file.json");
    FAIL() << "expected an error";
  } catch (const GoldenError& e) {
    EXPECT_NE(std::string(e.what()).find("case_file is not a case's folder and file name"),
              std::string::npos)
        << e.what();
  }
}

// What `loadGoldens` must refuse before anything is compared with the set.
std::string loadError(const fs::path& root) {
  try {
    loadGoldens(root, "c");
  } catch (const GoldenError& e) {
    return e.what();
  }
  return "";
}

TEST(GoldenStore, AnExrWhosePixelsDoNotMatchItsHashIsRefused) {
  const fs::path root = freshRoot("overwritten");
  const auto m = manifestFor("good", {1, 2}, 0.25f);
  replaceGoldens(root, m, filesFor(m, 0.25f));
  writeExr(root / "c" / "frame_2.exr", Image(4, 3, 4, 0.26f));  // what `render --out goldens` did
  const std::string e = loadError(root);
  EXPECT_NE(e.find("frame_2.exr: pixels"), std::string::npos) << e;
  EXPECT_NE(e.find("do not match manifest.json"), std::string::npos) << e;
}

TEST(GoldenStore, AMissingOrUnreadableExrIsRefused) {
  const fs::path root = freshRoot("missing");
  const auto m = manifestFor("good", {1, 2}, 0.25f);
  replaceGoldens(root, m, filesFor(m, 0.25f));
  std::ofstream(root / "c" / "frame_1.exr") << "not an exr";
  EXPECT_NE(loadError(root).find("frame_1.exr"), std::string::npos) << loadError(root);
  fs::remove(root / "c" / "frame_1.exr");
  EXPECT_NE(loadError(root).find("frame_1.exr: missing"), std::string::npos) << loadError(root);
}

TEST(GoldenStore, AManifestWhoseFrameHashDisagreesWithItsSequenceIsRefused) {
  const fs::path root = freshRoot("sequence");
  auto m = manifestFor("good", {1}, 0.25f);
  replaceGoldens(root, m, filesFor(m, 0.25f));
  m.sequence[1] = std::string(64, 'c');
  std::ofstream(root / "c" / "manifest.json") << m.toJson().dump(2);
  EXPECT_NE(loadError(root).find("disagrees with frame_sha256"), std::string::npos)
      << loadError(root);
  // Images without a manifest are no set at all, not an absent one.
  fs::remove(root / "c" / "manifest.json");
  const std::string missing = loadError(root);
  EXPECT_NE(missing.find("manifest.json: missing"), std::string::npos) << missing;
  EXPECT_NE(missing.find("git checkout -- "), std::string::npos) << missing;
  EXPECT_NE(missing.find("or re-bless"), std::string::npos) << missing;  // bless starts afresh
}

TEST(GoldenStore, ManifestRoundTripKeepsEveryField) {
  auto m = manifestFor("why", {7}, 0.25f);
  m.environment = {"llvmpipe (LLVM 15.0.6, 256 bits)", "llvmpipe", "Mesa 22.3.6", "1.3.230", "x86-64-v3"};
  m.history.push_back({"2026-01-01", "def", "older"});
  const auto back = Manifest::fromJson(m.toJson(), "m.json");
  EXPECT_EQ(back.toJson(), m.toJson());
  EXPECT_EQ(back.environment.fingerprint(), m.environment.fingerprint());
}

TEST(GoldenStore, RunsOfEqualFrameHashesAreStoredOnceAndExpandExactly) {
  auto m = manifestFor("runs", {7}, 0.25f);  // frames 0-6 'b', 7 the image, 8-9 'b'
  m.signatures.assign(m.sequence.size(), "s");
  m.signatures[9] = "t";
  const auto j = m.toJson();
  ASSERT_EQ(j["frame_sha256"].size(), 4u) << j["frame_sha256"];  // run of 7, frame 7, frames 8 and 9
  EXPECT_EQ(j["frame_sha256"][0]["frames"], 7);
  EXPECT_EQ(j["frame_sha256"][2], std::string(64, 'b'));  // a run of two stays two strings
  const auto back = Manifest::fromJson(j, "m.json");
  EXPECT_EQ(back.sequence, m.sequence);
  EXPECT_EQ(back.signatures, m.signatures);
}

TEST(GoldenStore, AnotherEnvironmentsPositiveOfTheSameFramesIsStoredOnce) {
  auto m = manifestFor("why", {7}, 0.25f);
  m.signatures.assign(m.sequence.size(), "s");
  Positive same{{"llvmpipe", "llvmpipe", "Mesa", "1.3", "override:avx2"}, {"2026-12-06", "abc", "v3 runner"},
                m.sequence, m.signatures};
  Positive own = same;
  own.environment.cpuFeatures = "override:sse4.1";
  own.sequence[3] = std::string(64, 'e');
  m.others = {same, own};
  const auto j = m.toJson();
  ASSERT_EQ(j["other_environments"].size(), 2u);
  EXPECT_TRUE(j["other_environments"][0]["same_frames_as_primary"].get<bool>());
  EXPECT_FALSE(j["other_environments"][0].contains("frame_sha256"));  // no second list
  EXPECT_TRUE(j["other_environments"][1].contains("frame_sha256"));
  const auto back = Manifest::fromJson(j, "m.json");
  EXPECT_EQ(back.toJson(), j);
  ASSERT_TRUE(back.positiveFor(own.environment.fingerprint()));
  EXPECT_EQ(back.positiveFor(own.environment.fingerprint())->sequence, own.sequence);
  EXPECT_EQ(back.positiveFor(same.environment.fingerprint())->sequence, m.sequence);
  EXPECT_FALSE(back.positiveFor("elsewhere"));
  // Two positives for one environment cannot both be right.
  auto twice = j;
  twice["other_environments"][1]["environment"] = twice["other_environments"][0]["environment"];
  EXPECT_THROW(Manifest::fromJson(twice, "m.json"), GoldenError);
}

// Three equal frames in a row or more are stored once with their count; two stay as they are.
TEST(GoldenStore, RunsOfThreeOrMoreEqualFramesAreStoredOnce) {
  Manifest m = manifestFor("runs", {}, 0.25f);
  const std::string x(64, 'c'), y(64, 'd'), z(64, 'e');
  m.sequence = {x, x, x, y, y, z, z, z, z};
  const auto list = m.toJson()["frame_sha256"];
  EXPECT_EQ(list, (nlohmann::json{{{"repeat", x}, {"frames", 3}}, y, y,
                                  {{"repeat", z}, {"frames", 4}}}));
  EXPECT_EQ(Manifest::fromJson(m.toJson(), "m.json").sequence, m.sequence);
}

TEST(GoldenStore, AHostileRepeatCountIsRefusedByName) {
  auto j = manifestFor("runs", {7}, 0.25f).toJson();
  for (const auto& frames : {nlohmann::json(0), nlohmann::json(uint64_t(1) << 40), nlohmann::json(-3)}) {
    j["frame_sha256"][0]["frames"] = frames;
    try {
      Manifest::fromJson(j, "m.json");
      FAIL() << "accepted a repeat of " << frames;
    } catch (const GoldenError& e) {
      EXPECT_NE(std::string(e.what()).find("m.json: malformed golden manifest"), std::string::npos) << e.what();
    }
  }
}

// A forged frame number or size is named as written: get<int>() would report 10^12 as
// -727379968 and take 2.5 for 2.
TEST(GoldenStore, AForgedFrameNumberOrSizeIsNamedAsWritten) {
  const auto good = manifestFor("forged", {7}, 0.25f).toJson();
  const std::vector<std::pair<const char*, nlohmann::json>> forged = {
      {"frame", uint64_t(1000000000000)},
      {"frame", -1},
      {"frame", 2.5},
      {"width", 0},
      {"height", "3"},
      {"width", int64_t(1) << 31}};
  for (const auto& [key, value] : forged) {
    auto j = good;
    j["frames"][0][key] = value;
    try {
      Manifest::fromJson(j, "m.json");
      ADD_FAILURE() << "accepted " << key << " = " << value;
    } catch (const GoldenError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("frames[].") + key + " is " + value.dump()),
                std::string::npos)
          << e.what();
      EXPECT_NE(std::string(e.what()).find("git checkout -- "), std::string::npos) << e.what();
    }
  }
  EXPECT_EQ(Manifest::fromJson(good, "m.json").toJson(), good);
}

}  // namespace
}  // namespace taa::golden
