// Keys the settings audit (docs/settings-audit.md) found accepted and ignored: each is now
// refused with exit 2 where it cannot act, naming what it needs, and accepted where it acts.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "case/case_error.h"
#include "case/case_loader.h"

namespace {

std::vector<std::string> inertCaseProblems(const std::string& json) {
  try {
    taa::cases::parseCase(json, "cases/inert.json");
  } catch (const taa::cases::CaseError& e) {
    return e.problems();
  }
  return {};
}

// Refused with a message naming the key and the setting it needs; accepted once that is set.
void expectNeeds(const std::string& alone, const std::string& enabled, const std::string& key,
                 const std::string& needs) {
  const auto p = inertCaseProblems(alone);
  ASSERT_EQ(p.size(), 1u) << alone;
  EXPECT_NE(p[0].find("cases/inert.json: " + key + ": has no effect unless " + needs),
            std::string::npos)
      << p[0];
  EXPECT_TRUE(inertCaseProblems(enabled).empty()) << enabled;
}

const char* kInertPoints = R"("points": [[0, 1, 6], [1, 1, 5], [2, 1, 4], [3, 1, 3]])";

TEST(InertKeys, CameraPathShapeNeedsPoints) {
  for (const std::string k :
       {R"("type": "bezier")", R"("duration_s": 2)", R"("constant_speed": false)",
        R"("look": "fixed")", R"("cyclic": true)"}) {
    const std::string key = "camera.path." + k.substr(1, k.find('"', 1) - 1);
    expectNeeds(R"({"camera": {"path": {)" + k + "}}}",
                R"({"camera": {"path": {)" + k + ", " + kInertPoints + "}}}", key,
                "camera.path.points is set");
  }
}

TEST(InertKeys, BobFrequencyNeedsAmplitudeAndStrafeDistanceNeedsSpeed) {
  expectNeeds(R"({"camera": {"bob": {"frequency_hz": 2}}})",
              R"({"camera": {"bob": {"frequency_hz": 2, "amplitude": 0.1}}})",
              "camera.bob.frequency_hz", "camera.bob.amplitude is above 0");
  expectNeeds(R"({"camera": {"strafe": {"distance": 2}}})",
              R"({"camera": {"strafe": {"distance": 2, "speed": 1}}})", "camera.strafe.distance",
              "camera.strafe.speed is above 0");
}

TEST(InertKeys, MoverRotationAxisNeedsARotation) {
  for (const std::string k : {R"("rotation_axis": [1, 0, 0])", R"("continuous_rotation": false)"}) {
    const std::string key = "movers[0]." + k.substr(1, k.find('"', 1) - 1);
    expectNeeds(R"({"movers": [{"shape": "cube", )" + k + "}]}",
                R"({"movers": [{"shape": "cube", "rotation_speed_deg": 45, )" + k + "}]}", key,
                "movers[0].rotation_speed_deg is not 0");
  }
}

TEST(InertKeys, HistoryResetNeedsAHistory) {
  for (const char* mode : {"off", "pass_through"}) {
    const auto p = inertCaseProblems(std::string(R"({"taa": {"mode": ")") + mode +
                                     R"("}, "script": {"reset_history_at": [3]}})");
    ASSERT_EQ(p.size(), 1u) << mode;
    EXPECT_NE(p[0].find("script.reset_history_at: resets the temporal history, which taa.mode " +
                        std::string(mode) + " does not keep"),
              std::string::npos)
        << p[0];
  }
  for (const char* mode : {"basic", "full", "accumulate", "tscmaa", "adaptive"})
    EXPECT_TRUE(inertCaseProblems(std::string(R"({"taa": {"mode": ")") + mode +
                                  R"("}, "script": {"reset_history_at": [3]}})")
                    .empty())
        << mode;
}

TEST(InertKeys, LodBiasTaaOnlyDecidesOnlyWithoutATemporalResolve) {
  expectNeeds(
      R"({"material": {"lod_bias": 1, "lod_bias_taa_only": false}})",
      R"({"taa": {"mode": "off"}, "material": {"lod_bias": 1, "lod_bias_taa_only": false}})",
      "material.lod_bias_taa_only", "material.lod_bias is not 0 and taa.mode is off");
  EXPECT_FALSE(
      inertCaseProblems(R"({"taa": {"mode": "off"}, "material": {"lod_bias_taa_only": false}})")
          .empty());
}

TEST(InertKeys, AlphaCutoffNeedsMask) {
  expectNeeds(R"({"material": {"alpha_cutoff": 0.3}})",
              R"({"material": {"alpha_cutoff": 0.3, "alpha_mode": "mask"}})",
              "material.alpha_cutoff", "material.alpha_mode is mask");
}

TEST(InertKeys, HistoryFormatNeedsABlendingMode) {
  const auto p =
      inertCaseProblems(R"({"taa": {"mode": "pass_through", "history_format": "rgba32f"}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("taa.history_format: has no effect unless taa.mode is basic, full, "
                      "accumulate or adaptive"),
            std::string::npos)
      << p[0];
  EXPECT_TRUE(
      inertCaseProblems(R"({"taa": {"mode": "basic", "history_format": "rgba32f"}})").empty());
}

// A moving twin is read only in the modes its still setting is: variance_gamma in full only.
TEST(InertKeys, TaaMovingFloatNeedsAModeThatReadsIt) {
  const auto p = inertCaseProblems(R"({"taa": {"mode": "basic", "moving": {"variance_gamma": 2}}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("taa.moving.variance_gamma: has no effect unless taa.mode is full"), std::string::npos)
      << p[0];
  EXPECT_TRUE(inertCaseProblems(
                  R"({"taa": {"mode": "full", "variance_clip": true, "moving": {"variance_gamma": 2}}})")
                  .empty());
}

TEST(InertKeys, TaaMovingRampNeedsAMovingFloat) {
  for (const std::string k : {R"("from_px": 1)", R"("to_px": 6)", R"("depth": 6)"}) {
    const std::string key = "taa.moving." + k.substr(1, k.find('"', 1) - 1);
    expectNeeds(R"({"taa": {"moving": {)" + k + "}}}",
                R"({"taa": {"moving": {"alpha": 0.3, )" + k + "}}}", key,
                "taa.moving.alpha or another float setting of taa.moving is set");
  }
}

}  // namespace
