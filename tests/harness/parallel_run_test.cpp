// `run -j N` and `merge`: whatever the worker count or the sharding, every output that is not a
// timing is the same bytes as one worker's unsharded run: console lines, results.json, JUnit,
// the report and the images.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "api/device.h"
#include "core/cache_folder.h"
#include "harness/cli_fixture.h"
#include "report/html_report.h"
#include "run/results.h"
#include "run/results_seal.h"

namespace taa {
namespace {

namespace fs = std::filesystem;
using test::HarnessCli;

// Repo cases of different kinds: a reference two of them share (clamp_rgb and
// velocity_longest3x3), a still scene, a camera cut on every frame, report.ab, a post-process-only
// technique (FXAA), MSAA-free fast ones. (TSCMAA's stereo case and camera_cut rendered 16-sample
// references for 2.3 s of the test's 7 s; every case's frames under the main job's two workers
// are held by its goldens.)
const std::vector<std::string> kRepoCases = {
    "clamp_rgb",        "jitter_legacy2", "velocity_longest3x3", "stress_teleport_every_frame",
    "alpha_low_static", "report_ab_zoom", "fxaa_only",           "history_bilinear"};
// Fast ones for the merge, which joins results and folders whatever the cases render: none
// renders a reference (the merge reads the shards' results, not how they were made).
const std::vector<std::string> kMergeCases = {
    "reset_history_scripted", "jitter_legacy2",   "stress_teleport_every_frame",
    "jitter_halton16_locked", "history_bilinear", "debug_velocity"};

// The case files, and the repo's goldens.
std::string repoCases(const std::vector<std::string>& names) {
  std::string s;
  for (const auto& c : names) s += (fs::path(TAA_SOURCE_DIR) / "cases" / (c + ".json")).string() + " ";
  return s + "--goldens " + (fs::path(TAA_SOURCE_DIR) / "goldens").string() + " ";
}

std::string readFile(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// What a run wrote, less what measures time: per-case seconds, GPU milliseconds and the pass
// timings (JSON), the JUnit time attributes, and the console's summary times and run line.
struct RunOutput {
  std::string console, results, junit, report;
  std::vector<std::pair<std::string, std::string>> images;  // relative path, bytes
};

nlohmann::json withoutTimings(nlohmann::json j) {
  for (auto& c : j["cases"])
    for (const char* k : {"seconds", "frame_ms", "timings"}) c.erase(k);
  return j;
}

RunOutput readRun(const fs::path& dir, const std::string& console) {
  RunOutput o;
  std::istringstream lines(console);
  for (std::string line; std::getline(lines, line);) {
    if (line.rfind("run: ", 0) == 0 || line.rfind("merge: ", 0) == 0 || line.rfind("report: ", 0) == 0)
      continue;
    o.console += std::regex_replace(line, std::regex("; [0-9.]+ s"), "; T s") + "\n";
  }
  const auto results = nlohmann::json::parse(readFile(dir / "results.json"));
  o.results = withoutTimings(results).dump(1);
  o.junit = std::regex_replace(readFile(dir / "junit.xml"), std::regex(" time=\"[0-9.]+\""), "");
  // The report is a function of the results: the written one is the results' rendering, and
  // with the timings zeroed two runs' renderings must agree.
  auto r = run::runResultsFromJson(results);
  EXPECT_EQ(readFile(dir / "report.html"), report::renderHtmlReport(r, dir)) << dir;
  for (auto& c : r.cases) {
    c.seconds = 0.0;
    c.frameMs.clear();
    c.timings.clear();
  }
  o.report = report::renderHtmlReport(r, dir);
  for (const auto& e : fs::recursive_directory_iterator(dir)) {
    const auto rel = fs::relative(e.path(), dir).string();
    if (e.is_regular_file() && rel.find('/') != std::string::npos)
      o.images.emplace_back(rel, readFile(e.path()));
  }
  std::sort(o.images.begin(), o.images.end());
  return o;
}

void expectSame(const RunOutput& a, const RunOutput& b, const std::string& what) {
  EXPECT_EQ(a.console, b.console) << what;
  EXPECT_EQ(a.results, b.results) << what;
  EXPECT_EQ(a.junit, b.junit) << what;
  EXPECT_EQ(a.report, b.report) << what;
  ASSERT_EQ(a.images.size(), b.images.size()) << what;
  for (size_t i = 0; i < a.images.size(); ++i) {
    EXPECT_EQ(a.images[i].first, b.images[i].first) << what;
    EXPECT_TRUE(a.images[i].second == b.images[i].second) << what << ": " << a.images[i].first;
  }
}

class ParallelRun : public HarnessCli {
 protected:
  RunOutput runInto(const std::string& name, const std::string& args, int expectExit = 0) {
    const auto r = harness("run " + args + " --out " + (root_ / name).string());
    EXPECT_EQ(r.exitCode, expectExit) << r.output;
    return readRun(root_ / name, r.output);
  }
};

TEST_F(ParallelRun, EveryOutputIsTheSameForAnyWorkerCount) {
  // One worker rendering every reference, against three sharing them: neither the worker
  // count nor the reference cache may change a result (the cache is shared by the workers).
  const RunOutput one = runInto("j1", repoCases(kRepoCases) + "-j 1 --no-reference-cache");
  EXPECT_NE(one.console.find("PASS clamp_rgb invariant no_ghosting"), std::string::npos) << one.console;
  expectSame(one, runInto("j3", repoCases(kRepoCases) + "-j3"), "-j 3 sharing references against -j 1");
}

TEST_F(ParallelRun, FailFastStopsAtTheSameCaseForAnyWorkerCount) {
  // a_small passes, b_strict fails (energy with epsilon 0); c_small, d_small and the fixture's
  // small come after it in case order, and with four workers some of them have started.
  writeCase("a_small", test::kSmallCase);
  writeCase("b_strict", R"({"scene": {"builtin": "checkerboard"}, "render": {"width": 48, "height": 27},
    "script": {"frames": 4}, "checks": {"golden": false, "invariants": ["energy"], "energy": {"epsilon": 0}}})");
  writeCase("c_small", test::kSmallCase);
  writeCase("d_small", test::kSmallCase);
  const std::string cases = (root_ / "cases").string() + " --fail-fast ";
  const RunOutput one = runInto("ff1", cases + "-j 1", 1);
  const auto listed = nlohmann::json::parse(one.results);
  ASSERT_EQ(listed["cases"].size(), 2u);  // a_small, b_strict, then stop
  EXPECT_EQ(listed["cases"][1]["name"], "b_strict");
  EXPECT_EQ(listed["not_run"], 3);
  expectSame(one, runInto("ff4", cases + "-j 4", 1), "--fail-fast -j 4 against -j 1");
}

TEST_F(ParallelRun, BadJobCountsAreRefused) {
  for (const char* bad : {"0", "x", "2x", "-1"}) {
    const auto r = run("small", std::string("--jobs ") + bad);
    EXPECT_EQ(r.exitCode, 2) << bad << "\n" << r.output;
    EXPECT_NE(r.output.find("--jobs"), std::string::npos) << r.output;
  }
}

// Seals `results` as `run` would (the user's key, which the harness the tests start shares):
// a test that edits one field and reseals sees that field's check, not the seal's.
void reseal(const fs::path& results) {
  const std::string key = readFile(userCacheFolder("results-seal.key"));
  ASSERT_EQ(key.size(), 32u);
  std::ofstream(run::sealPathOf(results)) << run::hmacSha256Hex(key, readFile(results)) + "\n";
}

// ctest's case.NAME after its shard, and the shard after the main job (tests/CMakeLists.txt):
// the verdict is the earlier run's only when that run was made by this build (executable,
// SPIR-V, CPU level, CI setting) from the same case inputs and goldens; otherwise the case
// renders.
TEST_F(ParallelRun, VerdictFromAnEarlierRunOnlyForTheSameInputs) {
  writeCase("b_strict", R"({"scene": {"builtin": "checkerboard"}, "render": {"width": 48, "height": 27},
    "script": {"frames": 4}, "checks": {"golden": false, "invariants": ["energy"], "energy": {"epsilon": 0}}})");
  const auto shard = harness("run " + (root_ / "cases").string() + " -j 2 --out " + (root_ / "shard").string());
  ASSERT_EQ(shard.exitCode, 1) << shard.output;
  const std::string from = " --verdict-from " + (root_ / "shard" / "results.json").string();
  auto lineOf = [](const std::string& output, const std::string& name) {
    std::istringstream lines(output);
    for (std::string line; std::getline(lines, line);)
      if (line.find(" " + name) != std::string::npos && line.rfind("run: ", 0) != 0) return line;
    return std::string();
  };
  for (const auto& [name, exitCode] : {std::pair<std::string, int>{"small", 0}, {"b_strict", 1}}) {
    const auto r = run(name, from);
    EXPECT_EQ(r.exitCode, exitCode) << r.output;
    EXPECT_NE(r.output.find("verdict: from"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("run: "), std::string::npos) << r.output;  // nothing rendered
    EXPECT_EQ(lineOf(r.output, name), lineOf(shard.output, name)) << r.output;
  }
  auto rendered = [&](const std::string& name, const std::string& why) {
    const auto r = run(name, from);
    EXPECT_EQ(r.output.find("verdict: from"), std::string::npos) << why << "\n" << r.output;
    EXPECT_NE(r.output.find("run: "), std::string::npos) << why << "\n" << r.output;
    return r;
  };
  // The case a shard never ran, and the same name with other inputs, render.
  writeCase("e_other", test::kSmallCase);
  rendered("e_other", "a case the earlier run did not hold");
  writeCase("b_strict", R"({"scene": {"builtin": "checkerboard"}, "render": {"width": 48, "height": 27},
    "script": {"frames": 4}, "checks": {"golden": false, "invariants": ["energy"]}})");
  EXPECT_EQ(rendered("b_strict", "the case file changed since").exitCode, 0);
  // A run that took its verdict holds it in its own results.json, for the next to take.
  const auto relayed = harness("run " + casePath("small") + from + " --out " + (root_ / "relay").string());
  ASSERT_NE(relayed.output.find("verdict: from"), std::string::npos) << relayed.output;
  const auto chained = run("small", " --verdict-from " + (root_ / "relay" / "results.json").string());
  EXPECT_NE(chained.output.find("verdict: from"), std::string::npos) << chained.output;
  EXPECT_EQ(lineOf(chained.output, "small"), lineOf(shard.output, "small")) << chained.output;
  // Goldens that appeared since, another CI setting or another SPIR-V folder render.
  fs::create_directories(root_ / "goldens" / "small");
  std::ofstream(root_ / "goldens" / "small" / "manifest.json") << "{}";
  rendered("small", "the case's goldens changed since");
  fs::remove_all(root_ / "goldens");
  EXPECT_EQ(test::runHarness("run " + casePath("small") + from + " --out " + (root_ / "out").string() + " ",
                             "CI=true ").output.find("verdict: from"),
            std::string::npos)
      << "a missing golden fails under CI=true, so CI's verdict is not the local run's";
  const fs::path shaders = root_ / "shaders";
  fs::copy(shaderFolder(), shaders, fs::copy_options::recursive);
  std::ofstream(shaders / "extra.spv") << "not loaded, but another folder's digest";
  EXPECT_EQ(test::runHarness("run " + casePath("small") + from + " --out " + (root_ / "out").string() + " ",
                             "CI=false TAA_SHADER_DIR=" + shaders.string() + " ")
                .output.find("verdict: from"),
            std::string::npos)
      << "another SPIR-V folder is another build";
  // A rebuilt shader keeps its file's size (one constant changed): the digest reads the bytes.
  fs::remove(shaders / "extra.spv");
  std::string spirv = readFile(shaders / "taa_resolve.comp.spv");
  spirv[8] = char(spirv[8] ^ 0x01);  // the generator word: the same size, other bytes
  std::ofstream(shaders / "taa_resolve.comp.spv", std::ios::binary | std::ios::trunc) << spirv;
  EXPECT_EQ(test::runHarness("run " + casePath("small") + from + " --out " + (root_ / "out").string() + " ",
                             "CI=false TAA_SHADER_DIR=" + shaders.string() + " ")
                .output.find("verdict: from"),
            std::string::npos)
      << "a SPIR-V file rewritten at the same size is another build";
  // Another build's or commit's results, or none, render too; a file that is not results is
  // refused.
  const fs::path results = root_ / "shard" / "results.json";
  auto j = nlohmann::json::parse(readFile(results));
  j["build"] = "build-id 0123456789abcdef | spirv 0 | x86-64 | device default | missing goldens skip";
  std::ofstream(results) << j.dump(1);
  reseal(results);
  EXPECT_NE(rendered("small", "an earlier run of another build")
                .output.find("not reused (made by another build"),
            std::string::npos);
  j = nlohmann::json::parse(readFile(results));
  j["build"] = nlohmann::json::parse(readFile(root_ / "relay" / "results.json"))["build"];
  j["commit"] = "0123456789abcdef";
  std::ofstream(results) << j.dump(1);
  reseal(results);
  EXPECT_NE(rendered("small", "an earlier run of another commit")
                .output.find("not reused (made at commit 0123456789abcdef"),
            std::string::npos);
  fs::remove(results);
  rendered("small", "no earlier run");
  std::ofstream(results) << "[1, 2";
  const auto bad = run("small", from);
  EXPECT_EQ(bad.exitCode, 2) << bad.output;
  EXPECT_NE(bad.output.find("results.json"), std::string::npos) << bad.output;
}

// A reused verdict needs the earlier run's environment and an unforged file: results.json is
// sealed (run/results_seal.h), so a status turned from fail to pass, or a fingerprint edited to
// match, renders the case instead of passing it (issue 43).
TEST_F(ParallelRun, VerdictFromAnEarlierRunNeedsItsSealAndEnvironment) {
  writeCase("b_strict",
            R"({"scene": {"builtin": "checkerboard"}, "render": {"width": 48, "height": 27},
    "script": {"frames": 4}, "checks": {"golden": false, "invariants": ["energy"], "energy": {"epsilon": 0}}})");
  const fs::path results = root_ / "shard" / "results.json";
  ASSERT_EQ(
      harness("run " + casePath("b_strict") + " --out " + (root_ / "shard").string()).exitCode, 1);
  ASSERT_TRUE(fs::exists(run::sealPathOf(results)));
  const std::string from = " --verdict-from " + results.string();
  const auto reused = run("b_strict", from);
  EXPECT_EQ(reused.exitCode, 1) << reused.output;
  ASSERT_NE(reused.output.find("verdict: from"), std::string::npos) << reused.output;
  const std::string sealed = readFile(results);
  auto edit = [&](const std::function<void(nlohmann::json&)>& change) {
    auto j = nlohmann::json::parse(sealed);
    change(j);
    std::ofstream(results) << j.dump(1) << "\n";
  };
  auto rendersWithNote = [&](const std::string& why) {
    const auto r = run("b_strict", from);
    EXPECT_EQ(r.exitCode, 1) << why << "\n" << r.output;  // the render's own verdict
    EXPECT_EQ(r.output.find("verdict: from"), std::string::npos) << why << "\n" << r.output;
    EXPECT_NE(r.output.find("note: --verdict-from " + results.string() + ": not reused"),
              std::string::npos)
        << why << "\n"
        << r.output;
  };
  edit([](auto& j) {
    j["cases"][0]["status"] = "pass";
    j["cases"][0]["invariants"][0]["passed"] = true;
  });
  rendersWithNote("a status edited from fail to pass");
  edit([](auto& j) { j["fingerprint"] = "llvmpipe (LLVM 99) | Mesa 99 | vulkan 1.3 | x86-64-v9"; });
  rendersWithNote("a fingerprint edited");
  std::ofstream(results) << sealed;
  fs::remove(run::sealPathOf(results));
  rendersWithNote("no seal");
  // Sealed, but from another environment (another driver or Mesa): renders, and the note says
  // why in words no seal problem uses.
  edit([](auto& j) {
    j["fingerprint"] = "llvmpipe (LLVM 99) | Mesa 99 | vulkan 1.3 | x86-64-v9";
    for (auto& c : j["cases"]) c["fingerprint"] = j["fingerprint"];
  });
  reseal(results);
  const auto other = run("b_strict", from);
  EXPECT_EQ(other.output.find("verdict: from"), std::string::npos) << other.output;
  EXPECT_NE(
      other.output.find("not reused (made on another driver or environment: llvmpipe (LLVM 99)"),
      std::string::npos)
      << other.output;
  // The file as written, sealed again, is reused again: the checks above refused for cause.
  std::ofstream(results) << sealed;
  reseal(results);
  EXPECT_NE(run("b_strict", from).output.find("verdict: from"), std::string::npos);
}

// The unsharded run and its three shards, made once for the suite (each test copies them).
class Merge : public ParallelRun {
 protected:
  static fs::path runs() { return fs::path(TAA_TEST_OUT) / "merge-runs"; }
  static void SetUpTestSuite() {
    fs::remove_all(runs());
    auto runTo = [](const std::string& name, const std::string& args) {
      const auto r = test::runHarness("run " + repoCases(kMergeCases) + args + " --out " + (runs() / name).string() + " ",
                                      "CI=false ");
      ASSERT_EQ(r.exitCode, 0) << r.output;
      std::ofstream(runs() / (name + ".console")) << r.output;
    };
    runTo("whole", "-j 2");
    for (int i = 1; i <= 3; ++i) runTo("shard" + std::to_string(i), "--shard " + std::to_string(i) + "/3");
  }
  void SetUp() override {
    ParallelRun::SetUp();
    for (int i = 1; i <= 3; ++i)
      fs::copy(runs() / ("shard" + std::to_string(i)), shard(i), fs::copy_options::recursive);
  }
  test::ProcessResult merge(const std::string& dirs) {
    return harness("merge " + dirs + " --out " + (root_ / "merged").string());
  }
  std::string shard(int i) const { return (root_ / ("shard" + std::to_string(i))).string(); }
  void editResults(int i, const std::function<void(nlohmann::json&)>& edit) {
    const fs::path p = fs::path(shard(i)) / "results.json";
    auto j = nlohmann::json::parse(readFile(p));
    edit(j);
    std::ofstream(p) << j.dump(1);
  }
};

TEST_F(Merge, ThreeShardsMergeIntoTheUnshardedRun) {
  const RunOutput whole = readRun(runs() / "whole", readFile(runs() / "whole.console"));
  const auto r = merge(shard(2) + " " + shard(3) + " " + shard(1));  // any order
  ASSERT_EQ(r.exitCode, 0) << r.output;
  expectSame(whole, readRun(root_ / "merged", r.output), "three shards merged");
}

TEST_F(Merge, RefusesShardsThatDoNotMakeOneRun) {
  auto refused = [&](const std::string& dirs, const std::string& why) {
    const auto r = merge(dirs);
    EXPECT_EQ(r.exitCode, 2) << r.output;
    EXPECT_NE(r.output.find(why), std::string::npos) << r.output;
  };
  refused(shard(1) + " " + shard(3), "shard 2/3 is missing (its cases: jitter_legacy2, history_bilinear)");
  refused(shard(1) + " " + shard(2) + " " + shard(2) + " " + shard(3), "are both shard 2/3");
  refused((root_ / "nowhere").string(), "nowhere/results.json");
  // A shard of another case set: the same cases and one more.
  harness("run " + repoCases(kMergeCases) + " --shard 2/3 --out " + (root_ / "other").string() + " " +
          (fs::path(TAA_SOURCE_DIR) / "cases" / "fxaa_only.json").string());
  refused(shard(1) + " " + (root_ / "other").string() + " " + shard(3), "ran another case set");
  // A shard of another build, as a rebuilt shader folder makes it: the same cases, commit and
  // device, and results that are its own, not edited. The merge must not pass it off as the
  // first shard's build.
  const fs::path shaders = root_ / "shaders";
  fs::copy(shaderFolder(), shaders, fs::copy_options::recursive);
  std::ofstream(shaders / "extra.spv") << "not loaded, but another folder's digest";
  ASSERT_EQ(harness("run " + repoCases(kMergeCases) + " --shard 2/3 --out " + (root_ / "rebuilt").string(),
                    "CI=false TAA_SHADER_DIR=" + shaders.string())
                .exitCode,
            0);
  refused(shard(1) + " " + (root_ / "rebuilt").string() + " " + shard(3), "merge shards of one build");
  editResults(2, [](auto& j) { j["commit"] = "0123456789abcdef"; });
  refused(shard(1) + " " + shard(2) + " " + shard(3), "was run at commit 0123456789abcdef");
  editResults(2, [&](auto& j) {
    j["commit"] = nlohmann::json::parse(readFile(fs::path(shard(1)) / "results.json"))["commit"];
    j["fingerprint"] = "llvmpipe (LLVM 15.0.6, 128 bits) | Mesa | vulkan 1.3 | override:sse4.1";
  });
  refused(shard(1) + " " + shard(2) + " " + shard(3), "merge shards of one driver and CPU level");
  editResults(2, [&](auto& j) {
    j["fingerprint"] = nlohmann::json::parse(readFile(fs::path(shard(1)) / "results.json"))["fingerprint"];
    j["not_run"] = 1;
  });
  refused(shard(1) + " " + shard(2) + " " + shard(3), "stopped at its first failure (--fail-fast)");
  EXPECT_FALSE(fs::exists(root_ / "merged" / "results.json"));  // nothing written when refused
}

// A shard's folder is another run's output: every path in it is checked before merge reads or
// copies it (core/contained_file.h), and its results' fields are checked before they are
// trusted (issue 43).
TEST_F(Merge, RefusesForgedPathsLinksFifosAndForeignShards) {
  const std::string all = shard(1) + " " + shard(2) + " " + shard(3);
  auto refused = [&](const std::string& why, const std::string& dirs = "") {
    const auto r = merge(dirs.empty() ? all : dirs);
    EXPECT_EQ(r.exitCode, 2) << why << "\n" << r.output;
    EXPECT_NE(r.output.find(why), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("passwd:"), std::string::npos) << r.output;
  };
  const fs::path results1 = fs::path(shard(1)) / "results.json";
  const std::string original = readFile(results1);
  const auto first = nlohmann::json::parse(original)["cases"][0];
  const std::string caseName = first["name"];
  ASSERT_FALSE(first["frames"].empty()) << "a case with frame images";
  editResults(
      1, [](auto& j) { j["cases"][0]["frames"][0]["images"]["actual"] = "../../../etc/passwd"; });
  refused("is not inside the case's folder");
  editResults(1, [&](auto& j) {
    j["cases"][0]["frames"][0]["images"]["actual"] = caseName + "/../../../../etc/passwd";
  });
  refused("is not inside the case's folder");
  // The first differing frame's image is a path of the results too.
  std::ofstream(results1) << original;
  editResults(1, [](auto& j) {
    j["cases"][0]["first_difference"] = {{"frame", 1},
                                         {"detail", "forged"},
                                         {"actual_sha256", ""},
                                         {"golden_sha256", ""},
                                         {"actual", "../../../etc/passwd"},
                                         {"golden_neighbours", nlohmann::json::array()}};
  });
  refused("is not inside the case's folder");
  std::ofstream(results1) << original;
  const fs::path caseDir = fs::path(shard(1)) / caseName;
  fs::create_symlink("/etc/passwd", caseDir / "extra.png");
  refused("leads outside");
  fs::remove(caseDir / "extra.png");
  ASSERT_EQ(::mkfifo((caseDir / "fifo.png").c_str(), 0600), 0);
  refused("a FIFO");
  fs::remove(caseDir / "fifo.png");
  fs::rename(caseDir, fs::path(shard(1)) / "elsewhere");
  fs::create_symlink("elsewhere", caseDir);
  refused("is a symbolic link");
  fs::remove(caseDir);
  fs::rename(fs::path(shard(1)) / "elsewhere", caseDir);
  // Shard indices as run --shard takes them: no wrap-around, no fractions.
  for (const char* shard : {"[2, 4294967298]", "[2.5, 2]", "[0, 3]", "[4, 3]"}) {
    editResults(1, [&](auto& j) { j["suite"]["shard"] = nlohmann::json::parse(shard); });
    refused("suite.shard: expected");  // run/results_format.h's bounds
  }
  std::ofstream(results1) << original;
  editResults(1,
              [](auto& j) { j["build"] = "build-id 00 | spirv 00 | x86-64-v2 | device default"; });
  refused("merge shards of one build");
  std::ofstream(results1) << original;
  editResults(1, [](auto& j) { j["device"] = "another device"; });
  refused("merge shards of one device");
  std::ofstream(results1) << original;
  const auto inside = harness("merge " + all + " --out " + shard(2) + "/merged");
  EXPECT_EQ(inside.exitCode, 2) << inside.output;
  EXPECT_NE(inside.output.find("inside the shard output"), std::string::npos) << inside.output;
  EXPECT_FALSE(fs::exists(root_ / "merged" / "results.json"));  // nothing written when refused
  // The shards as run wrote them merge, sealed; with one edited (and so unsealed), the merged
  // results are not sealed either.
  reseal(results1);
  ASSERT_EQ(merge(all).exitCode, 0);
  EXPECT_TRUE(fs::exists(run::sealPathOf(root_ / "merged" / "results.json")));
  std::ofstream(results1) << original << " ";
  const auto unsealed = merge(all);
  EXPECT_EQ(unsealed.exitCode, 0) << unsealed.output;
  EXPECT_NE(unsealed.output.find("is not sealed"), std::string::npos) << unsealed.output;
  EXPECT_FALSE(fs::exists(run::sealPathOf(root_ / "merged" / "results.json")));
}

}  // namespace
}  // namespace taa
