// The harness as users drive it, in a temporary tree of its own (cases/ + goldens/),
// never the repo's: shared by the CLI tests.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "support/process.h"

namespace taa::test {

namespace fs = std::filesystem;

// A small moving case for the CLI tests, which are about the harness's bookkeeping (goldens,
// verdicts, positives, folders), not a technique: without a temporal pass a run of it costs
// about half the CPU (70 ms instead of 140), the resolve's two pipelines being most of a small
// run. smallTaaCase() has the built-in resolve for the tests that need one.
inline const char* kSmallCase = R"({
  "description": "small moving case for CLI tests",
  "scene": {"builtin": "checkerboard"},
  "render": {"width": 64, "height": 36},
  "camera": {"strafe": {"speed": 0.5, "distance": 0.2}},
  "script": {"frames": 6},
  "output": {"frames": [2, 5]},
  "taa": {"mode": "off"}
})";

// kSmallCase with `members` ("key": value, ...) added after its own.
inline std::string smallCaseWith(const std::string& members) {
  std::string s = kSmallCase;
  return s.replace(s.rfind('}'), 1, ", " + members + "}");
}

// kSmallCase with the built-in temporal resolve (taa.mode full).
inline std::string smallTaaCase() {
  std::string s = kSmallCase;
  const std::string off = R"("mode": "off")";
  return s.replace(s.find(off), off.size(), R"("mode": "full")");
}

class HarnessCli : public ::testing::Test {
 protected:
  void SetUp() override {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    root_ = fs::path(TAA_TEST_OUT) / "harness-cli" / info->name();
    fs::remove_all(root_);
    fs::create_directories(root_ / "cases");
    writeCase("small", kSmallCase);
  }
  void writeCase(const std::string& name, const std::string& json) {
    std::ofstream(root_ / "cases" / (name + ".json")) << json;
  }
  std::string casePath(const std::string& name) const {
    return (root_ / "cases" / (name + ".json")).string();
  }
  // CI=false unless the test says otherwise: a case without goldens is a skip locally and a
  // failure under CI=true, and the tests must not depend on the shell they run in.
  test::ProcessResult harness(const std::string& args, const std::string& env = "") {
    return test::runHarness(args + " ", "CI=false " + env);
  }
  test::ProcessResult run(const std::string& name, const std::string& extra = "",
                          const std::string& env = "") {
    return harness("run " + casePath(name) + " --out " + (root_ / "out").string() + " " + extra,
                   env);
  }
  test::ProcessResult bless(const std::string& name, const std::string& extra = "") {
    return harness("bless " + casePath(name) + " --out " + (root_ / "bless-out").string() +
                   " --reason 'test bless' " + extra);
  }
  nlohmann::json results() const {
    std::ifstream in(root_ / "out" / "results.json");
    return nlohmann::json::parse(in);
  }
  fs::path root_;
};

}  // namespace taa::test
