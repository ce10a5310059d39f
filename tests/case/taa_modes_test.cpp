// The mode table (renderer/spec/taa_modes.h) and the declared settings
// (shaders/common/taa_settings.h): what each mode runs, and that a setting outside its modes or
// rule is refused, not silently ignored.
#include "spec/taa_modes.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "case/case_error.h"
#include "support/gpu.h"

namespace taa {
namespace {

std::vector<std::string> taaModeProblems(const std::string& taa) {
  try {
    test::caseFromJson(R"({"scene": {"builtin": "checkerboard"}, "taa": )" + taa + "}",
                       "taa_modes");
  } catch (const cases::CaseError& e) {
    return e.problems();
  }
  return {};
}

bool taaModeMentions(const std::vector<std::string>& problems, const std::string& key,
                     const std::string& text) {
  for (const auto& p : problems)
    if (p.find(key) != std::string::npos && p.find(text) != std::string::npos) return true;
  return false;
}

TEST(TaaModes, AKeyOutsideItsModesIsRefusedWithTheModesInWords) {
  // Accumulation fixes the tone weighting to none: setting it used to be accepted and ignored.
  auto p = taaModeProblems(R"({"mode": "accumulate", "tonemap_weighting": "karis"})");
  EXPECT_TRUE(taaModeMentions(p, "taa.tonemap_weighting", "taa.mode is basic, full or adaptive"))
      << p.size();
  p = taaModeProblems(R"({"mode": "basic", "depth_threshold": 0.1})");
  EXPECT_TRUE(taaModeMentions(p, "taa.depth_threshold", "taa.mode is full or adaptive"))
      << p.size();
  // pass_through keeps no history, so its precision was accepted and ignored there (the
  // settings audit's finding).
  for (const char* mode : {"off", "pass_through"}) {
    p = taaModeProblems(std::string(R"({"mode": ")") + mode + R"(", "history_format": "rgba32f"})");
    EXPECT_TRUE(
        taaModeMentions(p, "taa.history_format", "taa.mode is basic, full, accumulate or adaptive"))
        << mode;
  }
  // Inside its modes, a setting's rule decides.
  p = taaModeProblems(R"({"variance_gamma": 2.0})");
  EXPECT_TRUE(taaModeMentions(p, "taa.variance_gamma", "taa.variance_clip is true")) << p.size();
  p = taaModeProblems(
      R"({"variance_clip": true, "motion_adaptive_gamma": true, "variance_gamma": 2.0})");
  EXPECT_TRUE(taaModeMentions(p, "taa.variance_gamma", "taa.motion_adaptive_gamma is false"))
      << p.size();
  // Accumulation turns consistency on, so its tolerances mean something there.
  EXPECT_TRUE(taaModeProblems(R"({"mode": "accumulate", "consistency_depth": 0.1})").empty());
  EXPECT_TRUE(taaModeProblems(R"({"variance_clip": true, "variance_gamma": 2.0})").empty());
}

TEST(TaaModes, EachModeRunsWhatItsRuleSays) {
  using spec::TaaMode;
  EXPECT_FALSE(spec::modeRule(TaaMode::Off).resolve);
  EXPECT_FALSE(spec::modeRule(TaaMode::Tscmaa).resolve);
  EXPECT_TRUE(spec::modeRule(TaaMode::Tscmaa).tscmaa);
  EXPECT_EQ(spec::modeRule(TaaMode::PassThrough).path, spec::Resolve::PassThrough);
  EXPECT_EQ(spec::modeRule(TaaMode::Basic).path, spec::Resolve::Basic);
  for (TaaMode m : {TaaMode::Full, TaaMode::Accumulate, TaaMode::Adaptive})
    EXPECT_EQ(spec::modeRule(m).path, spec::Resolve::Full) << spec::enumToString(m);
  EXPECT_TRUE(spec::modeRule(TaaMode::Adaptive).adaptive);
  // Accumulation's published alpha is its default.
  EXPECT_FLOAT_EQ(
      test::caseFromJson(R"({"scene": {"builtin": "checkerboard"}, "taa": {"mode": "accumulate"}})")
          .taa.alpha,
      0.2f);
}

TEST(TaaModes, AccumulateRunsTheFullResolveWithConsistencyAndNoColourTechniques) {
  spec::TaaSpec user;
  user.mode = spec::TaaMode::Accumulate;
  user.tonemap_weighting = spec::ToneWeight::Karis;  // set programmatically, past validation
  user.variance_clip = true;
  user.alpha = 0.3f;
  const spec::TaaSpec e = spec::effectiveTaa(user);
  EXPECT_TRUE(e.consistency);
  EXPECT_EQ(e.rectify, spec::Rectify::None);
  EXPECT_EQ(e.tonemap_weighting, spec::ToneWeight::None);
  EXPECT_FALSE(e.variance_clip);
  EXPECT_EQ(e.color_space, spec::TaaSpec{}.color_space);
  EXPECT_FLOAT_EQ(e.alpha, 0.3f);  // blending settings stay the case's
  // The full mode keeps everything the case set.
  user.mode = spec::TaaMode::Full;
  EXPECT_EQ(spec::effectiveTaa(user).tonemap_weighting, spec::ToneWeight::Karis);
  EXPECT_FALSE(spec::effectiveTaa(user).consistency);
}

}  // namespace
}  // namespace taa
