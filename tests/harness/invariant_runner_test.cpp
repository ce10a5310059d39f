// Invariants driven by run::runCase on a rendered case, as `taa-harness run` drives a user's
// case: which frames each invariant judges (checks.from_frame, and finite judging warm-up
// frames too) is decided by the runner alone.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "case/case_loader.h"
#include "run/case_runner.h"
#include "support/gpu.h"

using namespace taa;

namespace {

run::CaseResult runCaseJson(const std::string& json, const std::string& name) {
  const auto dir = std::filesystem::path(TAA_TEST_OUT) / "invariant_runner";
  const auto loaded = cases::parseCase(json, dir / "cases" / (name + ".json"));
  run::RunOptions options;
  options.outDir = dir / "out";
  options.writeImages = false;
  return run::runCase(test::device(), loaded, options);
}

const run::InvariantResult* invariantNamed(const run::CaseResult& r, const std::string& name) {
  for (const auto& i : r.invariants)
    if (i.name == name) return &i;
  return nullptr;
}

double valueNamed(const run::InvariantResult& r, const std::string& name) {
  for (const auto& [k, v] : r.values)
    if (k == name) return v;
  ADD_FAILURE() << "no value " << name << " in " << r.name;
  return -1.0;
}

// A NaN written into frame NAN_FRAME's colour (1 by default) reaches the output with the
// resolve off (frame 0 is a history reset, which energy skips).
const char* kWarmUpNan = R"({
  "scene": {"builtin": "checkerboard"}, "render": {"width": 32, "height": 18},
  "taa": {"mode": "off"}, "script": {"frames": 4}, "output": {"frames": [3]},
  "reference": {"samples": 4},
  "inject": {"frames": [NAN_FRAME], "pixels": [[5, 5]], "value": "nan"},
  "checks": {"golden": false, "from_frame": FROM, "invariants": ["finite", "energy"],
             "energy": {"epsilon": 0.5}}})";

std::string withFromFrame(int from, int nanFrame = 1) {
  std::string json = kWarmUpNan;
  json.replace(json.find("FROM"), 4, std::to_string(from));
  json.replace(json.find("NAN_FRAME"), 9, std::to_string(nanFrame));
  return json;
}

}  // namespace

TEST(InvariantRunner, FiniteJudgesWarmUpFramesWhileEnergyStartsAtFromFrame) {
  const auto r = runCaseJson(withFromFrame(2), "warm_up_nan");
  const auto* finite = invariantNamed(r, "finite");
  const auto* energy = invariantNamed(r, "energy");
  ASSERT_NE(finite, nullptr);
  ASSERT_NE(energy, nullptr);
  EXPECT_FALSE(finite->passed) << finite->detail;
  EXPECT_NE(finite->detail.find("first at frame 1 (5, 5)"), std::string::npos) << finite->detail;
  EXPECT_EQ(valueNamed(*finite, "frames"), 4.0);  // warm-up included
  EXPECT_TRUE(energy->passed) << energy->detail;  // frame 1's NaN is before from_frame
  EXPECT_EQ(valueNamed(*energy, "frames"), 2.0);
  EXPECT_EQ(r.status, run::CaseStatus::Fail);
}

// The smallest from_frame that leaves a warm-up frame: frame 0 is still read back for finite.
TEST(InvariantRunner, FromFrameOneLeavesFrameZeroToFinite) {
  const auto r = runCaseJson(withFromFrame(1, 0), "warm_up_nan_frame_0");
  const auto* finite = invariantNamed(r, "finite");
  ASSERT_NE(finite, nullptr);
  EXPECT_FALSE(finite->passed) << finite->detail;
  EXPECT_NE(finite->detail.find("first at frame 0 (5, 5)"), std::string::npos) << finite->detail;
  EXPECT_EQ(valueNamed(*finite, "frames"), 4.0);
}

TEST(InvariantRunner, FromFrameZeroLetsEveryInvariantSeeTheDefect) {
  const auto r = runCaseJson(withFromFrame(0), "warm_up_nan_judged");
  const auto* energy = invariantNamed(r, "energy");
  ASSERT_NE(energy, nullptr);
  EXPECT_FALSE(energy->passed) << energy->detail;  // the NaN's frame is judged now
}
