// kModeRules' columns against what each mode runs. Every row is rendered or validated here, so
// a wrong column fails, and so does a check that tests a mode by name instead of asking its
// column (a new mode is one row of renderer/spec/taa_modes.h; these tests then cover it).
#include <gtest/gtest.h>

#include <algorithm>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "api/renderer.h"
#include "scene/build_scene.h"
#include "spec/taa_modes.h"
#include "support/case_problems.h"
#include "support/effects.h"
#include "support/gpu.h"

namespace taa {
namespace {

using spec::ModeRule;
using spec::TaaMode;

// The case with taa.mode set past validation, which may refuse the mode with these keys.
spec::CaseSpec inMode(const std::string& json, TaaMode mode) {
  spec::CaseSpec s = test::caseFromJson(json, "mode_rules");
  s.taa.mode = mode;
  return s;
}

std::string withMode(const std::string& json, TaaMode mode) {
  nlohmann::json j = nlohmann::json::parse(json);
  j["taa"]["mode"] = spec::enumToString(mode);
  return j.dump();
}

// Whether validation refuses `key` in the case.
bool refuses(const std::string& json, const std::string& key) {
  const auto p = test::caseRefusal([&] { test::caseFromJson(json, "mode_rules"); });
  return std::any_of(p.begin(), p.end(),
                     [&](const std::string& s) { return s.find(key) != std::string::npos; });
}

const Image& lastFrame(const std::vector<FrameRecord>& run) {
  return run.back().color;
}

// A pan, so that reprojection, rejection and tracing all have work.
const char* kPan = R"({
  "scene": {"builtin": "checkerboard"},
  "camera": {"rotate": {"yaw_deg_per_s": 30}},
  "render": {"width": 64, "height": 36},
  "script": {"frames": 4},
  "output": {"frames": [3]}
})";

// standIn: a user's resolve or a score lane replaces the full resolve as the case sets it, so
// only a mode whose output is that resolve's, bit for bit, may be replaced.
TEST(ModeRules, AStandInReplacesOnlyTheModesThatRenderAsTheFullResolve) {
  const Image full = lastFrame(test::renderCase(inMode(kPan, TaaMode::Full)));
  for (const ModeRule& r : spec::kModeRules) {
    const char* name = spec::enumToString(r.mode);
    const Image out = lastFrame(test::renderCase(inMode(kPan, r.mode)));
    EXPECT_EQ(r.standIn, sameBits(out, full)) << name;
    // Validation asks the same column.
    const std::string user = withMode(R"({"scene": {"builtin": "checkerboard"},
                                          "taa": {"shader": "user/sample_count.comp"}})",
                                      r.mode);
    EXPECT_EQ(!r.standIn, refuses(user, "taa.mode")) << name;
  }
}

// stillImage: debug.image writes over the raster's colour, so in a mode that shows it alone
// the hidden scene changes nothing. Any image of output size shows it; a 64x64 one (the bump
// texture's pixels) keeps the fourteen renders at 4,096 pixels, not the zone plate's 57,600.
TEST(ModeRules, TheStillImageModesShowNothingOfTheHiddenScene) {
  const auto still = [](const char* scene) {
    return std::string(R"({"scene": {"builtin": ")") + scene + R"("},
      "debug": {"image": "scenes/normal_bumps.png"},
      "render": {"width": 64, "height": 64},
      "script": {"frames": 3}, "output": {"frames": [2]}})";
  };
  for (const ModeRule& r : spec::kModeRules) {
    const char* name = spec::enumToString(r.mode);
    const Image a = lastFrame(test::renderCase(inMode(still("checkerboard"), r.mode)));
    const Image b = lastFrame(test::renderCase(inMode(still("foliage"), r.mode)));
    EXPECT_EQ(r.stillImage, sameBits(a, b)) << name;
    EXPECT_EQ(!r.stillImage, refuses(withMode(still("checkerboard"), r.mode), "debug.image"))
        << name;
  }
}

// adaptive: the ray tracer runs, and what it cannot shade (shadows; normal maps, refused when
// the scene is built) is refused in exactly the modes that build it.
TEST(ModeRules, WhatTheTracerCannotShadeIsRefusedExactlyWhereItRuns) {
  for (const ModeRule& r : spec::kModeRules) {
    const char* name = spec::enumToString(r.mode);
    const spec::CaseSpec s = inMode(kPan, r.mode);
    const scene::Scene scene = scene::buildScene(s);
    const Renderer renderer(test::gpu(), s, scene);
    const auto& log = renderer.log();
    const bool traces = std::any_of(log.begin(), log.end(), [](const std::string& line) {
      return line.rfind("pass adaptive_trace", 0) == 0;
    });
    EXPECT_EQ(r.adaptive, traces) << name;
    EXPECT_EQ(traces, refuses(withMode(R"({"scene": {"builtin": "checkerboard"},
                                           "lighting": {"shadows": true}})",
                                       r.mode),
                              "lighting.shadows"))
        << name;
    spec::CaseSpec bumps = inMode(R"({"scene": {"gltf": "scenes/normal_bumps.gltf"}})", r.mode);
    EXPECT_EQ(traces, [&] {
      try {
        scene::buildScene(bumps);
      } catch (const std::exception& e) {
        return std::string(e.what()).find("material.normal_strength") != std::string::npos;
      }
      return false;
    }()) << name;
  }
}

}  // namespace
}  // namespace taa
