// `run --fail-fast` stops at the first failing case: what ci/mutate.py relies on to make a
// caught mutant cheap. Cases run in file-name order, so "a_strict" fails before "b_small".
#include <gtest/gtest.h>

#include <string>

#include "harness/cli_fixture.h"

namespace taa {
namespace {

using test::HarnessCli;
using test::kSmallCase;

// energy with epsilon 0 on a moving checkerboard: an invariant that always fails.
const char* kFailFastStrictCase = R"({
  "scene": {"builtin": "checkerboard"}, "render": {"width": 48, "height": 27},
  "script": {"frames": 4}, "checks": {"invariants": ["energy"], "energy": {"epsilon": 0}}
})";

class FailFast : public HarnessCli {
 protected:
  test::ProcessResult runFolder(const std::string& extra) {
    return harness("run " + (root_ / "cases").string() + " --out " + (root_ / "out").string() +
                   " " + extra);
  }
};

TEST_F(FailFast, StopsAtTheFirstFailingCase) {
  writeCase("a_strict", kFailFastStrictCase);
  writeCase("b_small", kSmallCase);
  const auto r = runFolder("--fail-fast");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_NE(r.output.find("FAIL a_strict"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("stopped at the first failing case, 2 of 3 cases not run"),
            std::string::npos)
      << r.output;
  const auto cases = results()["cases"];
  ASSERT_EQ(cases.size(), 1u);
  EXPECT_EQ(cases[0]["name"], "a_strict");
}

TEST_F(FailFast, WithoutTheFlagEveryCaseRuns) {
  writeCase("a_strict", kFailFastStrictCase);
  writeCase("b_small", kSmallCase);
  const auto r = runFolder("");
  EXPECT_EQ(r.exitCode, 1) << r.output;
  EXPECT_EQ(r.output.find("cases not run"), std::string::npos) << r.output;
  EXPECT_EQ(results()["cases"].size(), 3u);
}

TEST_F(FailFast, PassingCasesAllRunAndExitZero) {
  writeCase("b_small", kSmallCase);
  const auto r = runFolder("--fail-fast");
  EXPECT_EQ(r.exitCode, 0) << r.output;  // no goldens: a skip locally, not a failure
  EXPECT_EQ(results()["cases"].size(), 2u);
  EXPECT_EQ(r.output.find("cases not run"), std::string::npos) << r.output;
}

}  // namespace
}  // namespace taa
