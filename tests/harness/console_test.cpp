// The run's console lines, its summary and its hint agree: a case without goldens prints its
// frames as skipped, not failed, and a case whose invariant fails is never told to bless
// (bless refuses it).
#include "run/console.h"

#include <gtest/gtest.h>

#include <sstream>

namespace taa::run {
namespace {

CaseResult missingGoldens(bool invariantPasses) {
  CaseResult c;
  c.name = "mine";
  c.goldenStatus = CaseStatus::NoGolden;
  c.status = invariantPasses ? CaseStatus::NoGolden : CaseStatus::Fail;
  c.message = "no goldens in goldens/mine; look at the frames, then bless them";
  c.blessCommand = "taa-harness bless mine.json --reason \"<why>\"";
  FrameComparison f;
  f.frame = 23;
  f.status = FrameStatus::MissingGolden;
  c.frames.push_back(f);
  c.invariants.push_back({"finite", invariantPasses, "detail", {}});
  return c;
}

std::string printed(const CaseResult& c) {
  std::ostringstream out;
  printCase(out, c);
  RunResults r;
  r.cases.push_back(c);
  printSummary(out, r, 1.0);
  return out.str();
}

TEST(ConsoleTest, MissingGoldensAreSkippedInTheLinesAsInTheSummary) {
  const std::string out = printed(missingGoldens(true));
  EXPECT_NE(out.find("SKIP mine frame 23 golden missing"), std::string::npos) << out;
  EXPECT_EQ(out.find("FAIL"), std::string::npos) << out;
  EXPECT_NE(out.find("1 skipped (no goldens), 0 fail"), std::string::npos) << out;
  EXPECT_NE(out.find("taa-harness bless mine.json"), std::string::npos) << out;
}

TEST(ConsoleTest, AFailedInvariantNeverHintsAtABlessThatRefuses) {
  const std::string out = printed(missingGoldens(false));
  EXPECT_NE(out.find("SKIP mine frame 23 golden missing"), std::string::npos) << out;
  EXPECT_NE(out.find("FAIL mine invariant finite"), std::string::npos) << out;
  EXPECT_NE(out.find("bless would refuse"), std::string::npos) << out;
  EXPECT_EQ(out.find("taa-harness bless mine.json"), std::string::npos) << out;
  EXPECT_NE(out.find("0 skipped (no goldens), 1 fail"), std::string::npos) << out;

  // Under CI=true the missing golden fails by itself: then its line says so.
  CaseResult ci = missingGoldens(true);
  ci.goldenStatus = ci.status = CaseStatus::Fail;
  const std::string ciOut = printed(ci);
  EXPECT_NE(ciOut.find("FAIL mine frame 23 golden missing"), std::string::npos) << ciOut;
  EXPECT_NE(ciOut.find("HINT mine: if the change is intended"), std::string::npos) << ciOut;
}

// A scene's or user shader's note (an extension the loader ignores, a constant no code reads)
// is a console line too; the rest of the run log stays in results.json and the report.
TEST(ConsoleTest, SceneAndShaderNotesOfTheRunLogArePrinted) {
  CaseResult c = missingGoldens(true);
  c.log = {"scene: 12 vertices", "scene note: a.gltf: extensionsUsed lists KHR_x",
           "user shader note: `gain` is not read by the shader's code", "pass raster"};
  const std::string out = printed(c);
  EXPECT_NE(out.find("NOTE mine: scene note: a.gltf: extensionsUsed lists KHR_x\n"),
            std::string::npos)
      << out;
  EXPECT_NE(out.find("NOTE mine: user shader note: `gain` is not read"), std::string::npos) << out;
  EXPECT_EQ(out.find("pass raster"), std::string::npos) << out;
  EXPECT_EQ(out.find("12 vertices"), std::string::npos) << out;
}

}  // namespace
}  // namespace taa::run
