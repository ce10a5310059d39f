// References kept on disk across runs (api/reference_store.h): an entry is read back bit for bit,
// a torn, tampered or stray file is never used, the folder keeps the most recently used entries
// under its limit, and the key (run/reference_key.h) misses when any input of the reference does.
#include "api/reference_store.h"

#include <gtest/gtest.h>
#include <signal.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "api/reference_cache.h"
#include "case/case_loader.h"
#include "core/errors.h"
#include "core/sha256.h"
#include "run/build_identity.h"
#include "run/reference_key.h"
#include "scene/build_scene.h"
#include "support/fifo_guard.h"
#include "support/gpu.h"
#include "support/text.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

fs::path freshFolder() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const fs::path dir = fs::path(TAA_TEST_OUT) / "reference-store" / info->name();
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir;
}

std::string keyOf(const std::string& name) {
  return sha256Hex(name.data(), name.size());
}

Image pattern(int w, int h, float seed) {
  Image image(w, h, 4);
  for (size_t i = 0; i < image.data.size(); ++i) image.data[i] = seed + float(i) * 0.25f;
  return image;
}

void writeAll(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

std::vector<fs::path> filesIn(const fs::path& dir) {
  std::vector<fs::path> out;
  for (const auto& e : fs::directory_iterator(dir)) out.push_back(e.path());
  return out;
}

TEST(ReferenceStore, AnEntryReadsBackBitForBit) {
  const fs::path dir = freshFolder();
  std::ostringstream notes;
  Image image = pattern(5, 3, 1.0f);
  image.data[7] = -0.0f;  // bits a float compare would call equal to 0
  {
    ReferenceStore store(dir, kDefaultReferenceCacheBytes, notes);
    store.save(keyOf("a"), image);
  }
  ReferenceStore again(dir, kDefaultReferenceCacheBytes, notes);  // another process's view
  const auto back = again.load(keyOf("a"));
  ASSERT_TRUE(back);
  EXPECT_TRUE(sameBits(*back, image));
  EXPECT_FALSE(again.load(keyOf("b")));  // another key: a miss
  EXPECT_EQ(notes.str(), "");
}

// A flipped byte anywhere (header, key, shape, digest, pixels), a truncation or an entry filed
// under another key's name: dropped (deleted) with a note, never returned.
TEST(ReferenceStore, ATornOrTamperedEntryIsDroppedNotUsed) {
  const fs::path dir = freshFolder();
  std::ostringstream notes;
  ReferenceStore store(dir, kDefaultReferenceCacheBytes, notes);
  const std::string key = keyOf("a");
  const Image image = pattern(4, 4, 2.0f);
  const std::string good = encodeReferenceEntry(key, image);
  const fs::path file = dir / (key + ".ref");
  std::vector<std::pair<std::string, std::string>> bad;
  for (size_t at : {size_t(3), size_t(14), size_t(8 + 4 + 64 + 1), size_t(8 + 4 + 64 + 12 + 5),
                    good.size() - 1}) {
    std::string b = good;
    b[at] = char(b[at] ^ 0x10);
    bad.emplace_back("byte " + std::to_string(at) + " flipped", b);
  }
  bad.emplace_back("truncated", good.substr(0, good.size() - 4));
  bad.emplace_back("a byte too long", good + "x");
  bad.emplace_back("empty", "");
  bad.emplace_back("another key's entry", encodeReferenceEntry(keyOf("b"), image));
  for (const auto& [what, bytes] : bad) {
    writeAll(file, bytes);
    EXPECT_FALSE(store.load(key)) << what;
    EXPECT_FALSE(fs::exists(file)) << what << ": a bad entry stays for the next reader";
  }
  EXPECT_NE(notes.str().find("dropped " + key + ".ref"), std::string::npos) << notes.str();
  writeAll(file, good);  // the same bytes untouched: read
  const auto back = store.load(key);
  ASSERT_TRUE(back);
  EXPECT_TRUE(sameBits(*back, image));
}

// What a writer killed before its rename leaves (a temporary file, whole or not) is never read
// as an entry; trim() deletes it once no live writer can own it, and leaves a fresh one alone.
TEST(ReferenceStore, AStrayTemporaryFileIsIgnoredAndRemovedLater) {
  const fs::path dir = freshFolder();
  std::ostringstream notes;
  ReferenceStore store(dir, kDefaultReferenceCacheBytes, notes);
  const std::string key = keyOf("a");
  const std::string entry = encodeReferenceEntry(key, pattern(4, 4, 1.0f));
  const fs::path old = dir / ("." + key + ".ref.tmp-4242-0");
  const fs::path fresh = dir / ("." + key + ".ref.tmp-4243-0");
  writeAll(old, entry);
  writeAll(fresh, entry.substr(0, 100));
  EXPECT_FALSE(store.load(key));
  fs::last_write_time(old, fs::file_time_type::clock::now() - std::chrono::hours(2));
  store.trim();
  EXPECT_FALSE(fs::exists(old));
  EXPECT_TRUE(fs::exists(fresh));  // perhaps a writer still at work
}

// Under an entry's name, nothing but a regular file is read: a FIFO is never waited on, a link
// never followed (nor what it leads to dated) and a device never read; each is dropped with a
// note and its reference rendered again. A folder that cannot be dropped costs its own entry,
// not the cache.
TEST(ReferenceStore, NothingButAFileTheStoreWroteIsReadAsAnEntry) {
  const fs::path dir = freshFolder();
  std::ostringstream notes;
  ReferenceStore store(dir, kDefaultReferenceCacheBytes, notes);
  const Image image = pattern(4, 4, 1.0f);
  const auto entryOf = [&](const char* name) { return dir / (keyOf(name) + ".ref"); };
  const fs::path outside = dir.parent_path() / (dir.filename().string() + "-outside.ref");
  writeAll(outside, encodeReferenceEntry(keyOf("link"), image));  // a valid entry, elsewhere
  const auto outsideTime = fs::file_time_type::clock::now() - std::chrono::hours(3);
  fs::last_write_time(outside, outsideTime);
  fs::create_symlink(outside, entryOf("link"));
  fs::create_symlink("/dev/zero", entryOf("device"));
  ASSERT_EQ(::mkfifo(entryOf("fifo").c_str(), 0600), 0);
  fs::create_directories(entryOf("folder") / "inside");
  for (const char* name : {"fifo", "link", "device", "folder"}) {
    EXPECT_FALSE(test::readWithoutWaitingOn(entryOf(name), [&] { return store.load(keyOf(name)); }))
        << name;
    const std::string said = std::string(name) == "folder" ? "cannot drop " : "dropped ";
    EXPECT_NE(notes.str().find(said + keyOf(name) + ".ref"), std::string::npos) << name << "\n"
                                                                                << notes.str();
  }
  EXPECT_TRUE(fs::exists(outside));
  EXPECT_EQ(fs::last_write_time(outside), outsideTime);
  for (const char* name : {"fifo", "link", "device", "folder", "after"})
    store.save(keyOf(name), image);
  for (const char* name : {"fifo", "link", "device", "after"}) {
    // Checked first, so that a FIFO left in place fails here instead of blocking the load.
    ASSERT_TRUE(fs::is_regular_file(fs::symlink_status(entryOf(name))))
        << name << ": its name was not taken back\n"
        << notes.str();
    EXPECT_TRUE(store.load(keyOf(name))) << name;
  }
  EXPECT_NE(notes.str().find("a folder is in its place"), std::string::npos) << notes.str();
  // trim() counts the store's files only: a link to something big and recent, counted, would
  // push every real entry out.
  const fs::path big = dir.parent_path() / (dir.filename().string() + "-big");
  writeAll(big, "x");
  fs::resize_file(big, uint64_t(64) << 20);
  fs::last_write_time(big, fs::file_time_type::clock::now() + std::chrono::hours(1));
  fs::create_symlink(big, entryOf("big"));
  ReferenceStore(dir, uint64_t(1) << 20, notes).trim();
  for (const char* name : {"fifo", "link", "device", "after"})
    EXPECT_TRUE(fs::exists(entryOf(name))) << name << ": trimmed for a link's target";
  EXPECT_TRUE(fs::exists(big));
}

// kill -9 of a writer at any moment: every entry the folder then holds is complete and
// verified (the write goes to a temporary file renamed into place), so no reader can take a
// torn one, even one that did not check. A writer spends a part of its time writing, so the
// kill lands at 24 moments, one in each writer.
TEST(ReferenceStore, KillDuringAWriteLeavesNoTornEntry) {
  const fs::path dir = freshFolder();
  const Image big = pattern(512, 256, 3.0f);  // 2 MiB an entry
  int entries = 0;
  for (int round = 0; round < 24; ++round) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      std::ostringstream notes;
      ReferenceStore store(dir, kDefaultReferenceCacheBytes, notes);
      for (int i = 0;; ++i) store.save(keyOf(std::to_string(i % 8)), big);
    }
    for (int tries = 0; tries < 2000 && filesIn(dir).empty(); ++tries)
      std::this_thread::sleep_for(std::chrono::milliseconds(1));
    std::this_thread::sleep_for(std::chrono::microseconds(500 + 1700 * round));
    kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    for (const auto& f : filesIn(dir)) {
      const std::string name = f.filename().string();
      if (name[0] == '.') continue;  // the killed write's temporary file
      ++entries;
      const auto image = decodeReferenceEntry(test::readFile(f), f.stem().string());
      ASSERT_TRUE(image) << name << " is torn (round " << round << ")";
      EXPECT_TRUE(sameBits(*image, big)) << name;
    }
  }
  EXPECT_GT(entries, 0);
}

// Processes sharing one folder: two writers saving the same entries over and over while a
// reader loads them. A reader sees an entry whole or not at all (a partial one would be
// dropped with a note), and neither writer's temporary file is the other's (a clash fails a
// rename, which is a note too). A writer that noted anything exits 1 instead of being killed.
TEST(ReferenceStore, WritersAndAReaderAtOnceSeeOnlyWholeEntries) {
  const fs::path dir = freshFolder();
  const Image big = pattern(256, 256, 5.0f);  // 1 MiB an entry: a write takes a while
  std::vector<pid_t> writers;
  for (int w = 0; w < 2; ++w) {
    const pid_t child = fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
      std::ostringstream notes;
      ReferenceStore store(dir, kDefaultReferenceCacheBytes, notes);
      for (int i = 0;; ++i) {
        store.save(keyOf(std::to_string(i % 4)), big);
        if (!notes.str().empty()) _exit(1);
      }
    }
    writers.push_back(child);
  }
  std::ostringstream notes;
  ReferenceStore reader(dir, kDefaultReferenceCacheBytes, notes);
  int whole = 0, exited = 0;
  std::vector<int> status(writers.size(), 0);
  for (int i = 0; whole < 100 && i < 1000000 && notes.str().empty() && exited == 0; ++i) {
    if (const auto image = reader.load(keyOf(std::to_string(i % 4)))) {
      ++whole;
      EXPECT_TRUE(sameBits(*image, big));
    }
    for (size_t w = 0; w < writers.size(); ++w)
      if (writers[w] && waitpid(writers[w], &status[w], WNOHANG) == writers[w]) {
        writers[w] = 0;
        ++exited;
      }
  }
  for (size_t w = 0; w < writers.size(); ++w) {
    if (writers[w]) {
      kill(writers[w], SIGKILL);
      waitpid(writers[w], &status[w], 0);
    }
    EXPECT_TRUE(WIFSIGNALED(status[w])) << "writer " << w << " noted a failure (exit "
                                        << WEXITSTATUS(status[w]) << ")";
  }
  EXPECT_EQ(notes.str(), "");
  EXPECT_GT(whole, 0);
}

// The folder over its limit: the least recently used entries go (a read counts as a use), the
// rest stay.
TEST(ReferenceStore, TrimKeepsTheMostRecentlyUsedUnderTheLimit) {
  const fs::path dir = freshFolder();
  std::ostringstream notes;
  const Image image = pattern(16, 16, 1.0f);
  const uint64_t entryBytes = encodeReferenceEntry(keyOf("a"), image).size();
  ReferenceStore store(dir, entryBytes * 2 + entryBytes / 2, notes);
  const auto now = fs::file_time_type::clock::now();
  int age = 4;
  for (const char* name : {"a", "b", "c"}) {
    store.save(keyOf(name), image);
    fs::last_write_time(dir / (keyOf(name) + ".ref"), now - std::chrono::hours(age--));
  }
  ASSERT_TRUE(store.load(keyOf("a")));  // the oldest written, now the most recently used
  store.trim();
  EXPECT_TRUE(fs::exists(dir / (keyOf("a") + ".ref")));
  EXPECT_FALSE(fs::exists(dir / (keyOf("b") + ".ref")));  // least recently used
  EXPECT_TRUE(fs::exists(dir / (keyOf("c") + ".ref")));
}

TEST(ReferenceStore, AFolderThatCannotBeWrittenIsANote) {
  const fs::path dir = freshFolder();
  writeAll(dir / "file", "x");
  std::ostringstream notes;
  ReferenceStore store(dir / "file" / "references", kDefaultReferenceCacheBytes, notes);
  EXPECT_NO_THROW(store.save(keyOf("a"), pattern(2, 2, 0.0f)));
  EXPECT_NO_THROW(store.save(keyOf("b"), pattern(2, 2, 0.0f)));
  EXPECT_FALSE(store.load(keyOf("a")));
  EXPECT_NO_THROW(store.trim());
  const std::string n = notes.str();
  EXPECT_NE(n.find("note: reference cache"), std::string::npos) << n;
  EXPECT_EQ(n.find("note:"), n.rfind("note:")) << "one note, not one per reference: " << n;
}

// Restores the variables on every way out: the unit shards run many suites in one process.
struct CacheVariables {
  ~CacheVariables() {
    unsetenv("TAA_REFERENCE_CACHE_DIR");
    unsetenv("TAA_REFERENCE_CACHE_MAX_MB");
  }
};

TEST(ReferenceStore, TheEnvironmentNamesTheFolderAndTheLimit) {
  const fs::path dir = freshFolder();
  std::ostringstream notes;
  const CacheVariables restore;
  setenv("TAA_REFERENCE_CACHE_DIR", dir.c_str(), 1);
  setenv("TAA_REFERENCE_CACHE_MAX_MB", "3", 1);
  auto store = ReferenceStore::fromEnvironment(notes);
  ASSERT_TRUE(store);
  EXPECT_EQ(store->folder(), dir);
  EXPECT_EQ(store->maxBytes(), uint64_t(3) << 20);
  for (const char* bad : {"lots", "-1", "1.5", "12MB"}) {
    setenv("TAA_REFERENCE_CACHE_MAX_MB", bad, 1);
    try {
      ReferenceStore::fromEnvironment(notes);
      ADD_FAILURE() << bad << " accepted";
    } catch (const InputError& e) {
      EXPECT_NE(std::string(e.what()).find("TAA_REFERENCE_CACHE_MAX_MB='" + std::string(bad)),
                std::string::npos)
          << e.what();
    }
  }
  unsetenv("TAA_REFERENCE_CACHE_MAX_MB");
  EXPECT_EQ(ReferenceStore::fromEnvironment(notes)->maxBytes(), kDefaultReferenceCacheBytes);
}

// A second process's references, read from disk, are the bits a render gives: a fresh
// in-memory cache over the same folder renders nothing.
TEST(ReferenceStore, ASecondProcessReadsWhatARenderGives) {
  const fs::path dir = freshFolder();
  std::ostringstream notes;
  const auto spec = test::caseFromJson(R"({"scene": {"builtin": "checkerboard"},
    "render": {"width": 32, "height": 18}, "camera": {"strafe": {"speed": 0.5, "distance": 0.2}},
    "script": {"frames": 3}, "output": {"frames": [0, 1, 2]}, "reference": {"samples": 4}})",
                                       "reference_store");
  auto renderWith = [&](ReferenceCache* cache) {
    RenderOptions o;
    o.captures |= {Capture::Reference};
    run::shareReferences(o, cache, spec, test::device().identity());
    return test::renderCaseWith(spec, o);
  };
  ReferenceStore first(dir, kDefaultReferenceCacheBytes, notes);
  ReferenceCache cold(size_t(128) << 20, &first);
  renderWith(&cold);
  EXPECT_EQ(cold.stats().rendered, 3u);
  ReferenceStore second(dir, kDefaultReferenceCacheBytes, notes);
  ReferenceCache warm(size_t(128) << 20, &second);
  const auto fromDisk = renderWith(&warm);
  EXPECT_EQ(warm.stats().rendered, 0u);
  EXPECT_EQ(warm.stats().fromDisk, 3u);
  const auto rendered = renderWith(nullptr);
  ASSERT_EQ(fromDisk.size(), rendered.size());
  for (size_t i = 0; i < rendered.size(); ++i) {
    ASSERT_TRUE(fromDisk[i].hasReference && rendered[i].hasReference);
    EXPECT_TRUE(sameBits(fromDisk[i].reference, rendered[i].reference)) << "frame " << i;
  }
}

// Each part of the key that a path cannot vouch for across runs, changed alone, is another
// key; an edit of the resolve (its settings) changes none of them.
TEST(ReferenceKey, EachPartMissesAndTheResolveIsNoPart) {
  const fs::path dir = freshFolder();
  const fs::path scenes = fs::path(TAA_SOURCE_DIR) / "cases/scenes";
  fs::copy_file(scenes / "animated.gltf", dir / "animated.gltf");
  fs::copy_file(scenes / "animated.bin", dir / "animated.bin");
  const std::string caseText = R"({"scene": {"gltf": "animated.gltf"},
    "render": {"width": 32, "height": 18}, "script": {"frames": 2}, "reference": {"samples": 4}})";
  writeAll(dir / "c.json", caseText);
  DeviceIdentity device = test::device().identity();
  const auto base = run::referenceKeyParts(cases::loadCase(dir / "c.json").spec, device);
  EXPECT_EQ(base.build, run::executableIdentity());
  EXPECT_FALSE(base.environment.empty());

  // The resolve's settings: the same parts.
  auto resolveEdit = nlohmann::json::parse(caseText);
  resolveEdit["taa"] = {{"history_filter", "bilinear"}, {"rectify", "clamp"}};
  writeAll(dir / "c.json", resolveEdit.dump());
  const auto edited = run::referenceKeyParts(cases::loadCase(dir / "c.json").spec, device);
  EXPECT_EQ(edited.joined(), base.joined());
  writeAll(dir / "c.json", caseText);

  // A byte of the scene's buffer (the glTF itself unchanged).
  std::string bin = test::readFile(dir / "animated.bin");
  bin[bin.size() / 2] = char(bin[bin.size() / 2] ^ 1);
  writeAll(dir / "animated.bin", bin);
  const auto buffer = run::referenceKeyParts(cases::loadCase(dir / "c.json").spec, device);
  EXPECT_NE(buffer.inputFiles, base.inputFiles);
  EXPECT_EQ(buffer.settings, base.settings);

  // Another driver.
  device.driverInfo += " (another build)";
  EXPECT_NE(run::referenceKeyParts(cases::loadCase(dir / "c.json").spec, device).environment,
            buffer.environment);

  // Each part reaches the joined key on its own.
  for (std::string run::ReferenceKeyParts::*part :
       {&run::ReferenceKeyParts::settings, &run::ReferenceKeyParts::inputFiles,
        &run::ReferenceKeyParts::environment, &run::ReferenceKeyParts::build}) {
    run::ReferenceKeyParts changed = base;
    changed.*part += "x";
    EXPECT_NE(changed.joined(), base.joined());
  }
}

// The shaders whose SPIR-V the frame key holds: the reference's own and those of the passes it
// reads, not the resolve's (an edit of the resolve shader keeps the references).
TEST(ReferenceKey, TheReferenceShadersAreThePassesItReads) {
  const auto spec = test::caseFromJson(R"({"scene": {"builtin": "checkerboard"},
    "render": {"width": 32, "height": 18}, "lighting": {"shadows": true},
    "script": {"frames": 1}, "reference": {"samples": 4}})",
                                       "reference_shaders");
  const scene::Scene scene = scene::buildScene(spec);
  RenderOptions o;
  o.captures |= {Capture::Reference};
  Renderer renderer(test::device(), spec, scene, o);
  const auto names = renderer.referenceShaders();
  auto has = [&](const std::string& prefix) {
    for (const auto& n : names)
      if (n.rfind(prefix, 0) == 0) return true;
    return false;
  };
  std::string all;
  for (const auto& n : names) all += n + " ";
  EXPECT_TRUE(has("reference_accumulate.comp")) << all;
  EXPECT_TRUE(has("gbuffer.")) << all;
  EXPECT_TRUE(has("shadow_depth.")) << all;
  EXPECT_FALSE(has("taa_resolve")) << all;
  EXPECT_FALSE(has("sharpen")) << all;
  RenderOptions none;
  EXPECT_TRUE(Renderer(test::device(), spec, scene, none).referenceShaders().empty());
}

}  // namespace
}  // namespace taa
