// taa.moving (seed 000: "ideally one would smoothly blend parameters when switching sets"):
// the resolve's uniforms follow the camera's speed from the still set to the moving set and
// back, and a case without the object keeps today's uniforms bit for bit.
#include "passes/taa_moving.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "passes/taa_resolve.h"
#include "script/frame_state.h"
#include "spec/taa_modes.h"
#include "support/case_problems.h"
#include "support/gpu.h"

namespace taa {
namespace {

const char* const kMovingCase = "taa_moving_blend";

nlohmann::json movingCaseJson() {
  std::ifstream in(std::string(TAA_SOURCE_DIR) + "/cases/" + kMovingCase + ".json");
  std::stringstream text;
  text << in.rdbuf();
  return nlohmann::json::parse(text.str());
}

spec::CaseSpec movingCase(const nlohmann::json& j) {
  return test::caseFromJson(j.dump(), kMovingCase);
}

float movingAlphaAt(const spec::CaseSpec& spec, int frame) {
  const auto s = script::frameState(spec, frame);
  return makeTaaUniforms(spec, s, s.renderSize)
      .settings[spec::TAA_PARAM_ALPHA / 4][spec::TAA_PARAM_ALPHA % 4];
}

std::vector<std::string> movingProblems(const std::string& taa) {
  return test::caseProblems(R"({"script": {"frames": 2}, "taa": )" + taa + "}");
}

TEST(TaaMoving, AlphaIsStillAtRestMovingAtSpeedAndBetweenOnTheRamp) {
  const auto spec = movingCase(movingCaseJson());
  ASSERT_TRUE(spec.taa.moving.active);
  const auto& m = spec.taa.moving;
  int rest = 0, full = 0, ramp = 0;
  float previous = 0.1f;
  for (int f = 0; f < spec.script.frames; ++f) {
    const float speed = cameraSpeedPx(script::frameState(spec, f), m.depth);
    const float alpha = movingAlphaAt(spec, f);
    if (speed <= m.from_px) {
      EXPECT_EQ(alpha, 0.1f) << "frame " << f << " speed " << speed;
      ++rest;
    } else if (speed >= m.to_px) {
      EXPECT_FLOAT_EQ(alpha, 0.25f) << "frame " << f << " speed " << speed;
      ++full;
    } else {
      EXPECT_GT(alpha, 0.1f) << "frame " << f << " speed " << speed;
      EXPECT_LT(alpha, 0.25f) << "frame " << f << " speed " << speed;
      ++ramp;
    }
    // Smooth: the path eases in and out, so no frame jumps more than half way between the sets.
    EXPECT_LT(std::abs(alpha - previous), 0.075f) << "frame " << f;
    previous = alpha;
  }
  // The case has all three: rest at the start and after the stop, full speed, and ramps.
  EXPECT_GE(rest, 10);
  EXPECT_GE(full, 4);
  EXPECT_GE(ramp, 2);
  // The last frames stand still: the still set is back.
  EXPECT_EQ(movingAlphaAt(spec, spec.script.frames - 1), 0.1f);
}

TEST(TaaMoving, WithoutTheObjectUniformsAreTheStillOnes) {
  auto j = movingCaseJson();
  j["taa"].erase("moving");
  const auto plain = movingCase(j);
  const auto moving = movingCase(movingCaseJson());
  EXPECT_FALSE(plain.taa.moving.active);
  int differing = 0;
  for (int f = 0; f < plain.script.frames; ++f) {
    const auto s = script::frameState(plain, f);
    const auto a = makeTaaUniforms(plain, s, s.renderSize);
    // Today's uniforms: effectiveTaa's floats, untouched by the camera's motion.
    const spec::TaaSpec t = spec::effectiveTaa(plain.taa);
    EXPECT_EQ(a.settings[spec::TAA_PARAM_ALPHA / 4][spec::TAA_PARAM_ALPHA % 4], t.alpha);
    EXPECT_EQ(a.settings[spec::TAA_PARAM_VARIANCE_GAMMA / 4][spec::TAA_PARAM_VARIANCE_GAMMA % 4],
              t.variance_gamma);
    const auto b = makeTaaUniforms(moving, s, s.renderSize);
    if (std::memcmp(&a.settings, &b.settings, sizeof a.settings) != 0) ++differing;
  }
  EXPECT_GE(differing, 6);
}

TEST(TaaMoving, KeysLeftOutKeepTheStillValue) {
  // taa.alpha 0.05 with a moving variance gamma only: alpha stays 0.05 at full speed.
  auto j = movingCaseJson();
  j["taa"] = {{"alpha", 0.05},
              {"variance_clip", true},
              {"moving", {{"variance_gamma", 0.5}, {"depth", 6.0}}}};
  const auto spec = movingCase(j);
  EXPECT_EQ(spec.taa.moving.alpha, 0.05f);
  bool sawFull = false;
  for (int f = 0; f < spec.script.frames; ++f) {
    const auto s = script::frameState(spec, f);
    if (movingWeight(spec.taa.moving, s) < 1.0f) continue;
    sawFull = true;
    const auto u = makeTaaUniforms(spec, s, s.renderSize);
    EXPECT_EQ(u.settings[spec::TAA_PARAM_ALPHA / 4][spec::TAA_PARAM_ALPHA % 4], 0.05f);
    EXPECT_EQ(u.settings[spec::TAA_PARAM_VARIANCE_GAMMA / 4][spec::TAA_PARAM_VARIANCE_GAMMA % 4],
              0.5f);
  }
  EXPECT_TRUE(sawFull);
}

TEST(TaaMoving, ValidationRefusesWhatCannotBlend) {
  auto has = [](const std::vector<std::string>& p, const std::string& text) {
    for (const auto& line : p)
      if (line.find(text) != std::string::npos) return true;
    return false;
  };
  EXPECT_TRUE(movingProblems(R"({"moving": {"alpha": 0.3}})").empty());
  // Modes whose resolve reads no uniforms.
  for (const char* mode : {"off", "pass_through", "tscmaa"})
    EXPECT_TRUE(
        has(movingProblems(std::string(R"({"mode": ")") + mode + R"(", "moving": {"alpha": 0.3}})"),
            "taa.moving: has no effect unless taa.mode is"))
        << mode;
  // A switch or enum would need another pipeline: not a key of the object.
  EXPECT_TRUE(
      has(movingProblems(R"({"moving": {"rectify": "none"}})"), "taa.moving.rectify: unknown key"));
  // A float outside its own modes, a range, and an empty ramp.
  EXPECT_TRUE(has(movingProblems(R"({"mode": "basic", "moving": {"variance_gamma": 0.5}})"),
                  "taa.moving.variance_gamma: has no effect unless taa.mode is"));
  EXPECT_TRUE(
      has(movingProblems(R"({"moving": {"alpha": 2}})"), "taa.moving.alpha: 2 is out of range"));
  EXPECT_TRUE(has(movingProblems(R"({"moving": {"from_px": 3, "to_px": 3}})"),
                  "taa.moving.to_px: must be above taa.moving.from_px"));
}

TEST(TaaMoving, OutputDiffersWhileMovingAndConvergesBackAtRest) {
  auto j = movingCaseJson();
  j["taa"].erase("moving");
  const auto plain = movingCase(j);
  const auto moving = movingCase(movingCaseJson());
  const auto a = test::renderCase(plain, {12, 39});
  const auto b = test::renderCase(moving, {12, 39});
  double during = 0.0, after = 0.0;
  const Image &a12 = a[12].color, &b12 = b[12].color, &a39 = a[39].color, &b39 = b[39].color;
  ASSERT_EQ(a12.data.size(), b12.data.size());
  for (size_t i = 0; i < a12.data.size(); ++i) {
    during += std::abs(a12.data[i] - b12.data[i]);
    after += std::abs(a39.data[i] - b39.data[i]);
  }
  during /= double(a12.data.size());
  after /= double(a12.data.size());
  // Alpha 0.25 instead of 0.1 under motion changes the picture; at rest the same alpha runs
  // again and the two histories converge towards each other.
  EXPECT_GT(during, 1e-3) << "mean abs difference at frame 12";
  EXPECT_LT(after, during) << "mean abs difference at frame 39";
}

}  // namespace
}  // namespace taa
