// Section-11 keys (shadows, LOD matching, still images, debug channels, FXAA debug border):
// each accepted only where it acts.
#include <gtest/gtest.h>

#include "case/case_error.h"
#include "case/case_loader.h"

namespace {

std::vector<std::string> lightingProblems(const std::string& json) {
  try {
    // In the source tree's cases/ folder, whatever the test's working folder: the case's hash
    // reads the files it names (debug.image), which must exist there.
    taa::cases::parseCase(json, std::string(TAA_SOURCE_DIR) + "/cases/t.json");
  } catch (const taa::cases::CaseError& e) {
    return e.problems();
  }
  return {};
}

TEST(LightingValidation, ShadowsAreOffByDefaultWithThreeCascades) {
  const auto loaded = taa::cases::parseCase("{}", "cases/d.json");
  EXPECT_FALSE(loaded.spec.lighting.shadows);
  EXPECT_EQ(loaded.spec.lighting.cascades, 3);
  const auto on =
      taa::cases::parseCase(R"({"lighting": {"shadows": true, "cascades": 4}})", "cases/s.json");
  EXPECT_TRUE(on.spec.lighting.shadows);
  EXPECT_EQ(on.spec.lighting.cascades, 4);
}

TEST(LightingValidation, CascadesWithoutShadowsAreRefused) {
  const auto p = lightingProblems(R"({"lighting": {"cascades": 2}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(
      p[0].find(
          "cases/t.json: lighting.cascades: counts shadow cascades but lighting.shadows is off"),
      std::string::npos)
      << p[0];
}

TEST(LightingValidation, CascadeCountIsBounded) {
  const auto p = lightingProblems(R"({"lighting": {"shadows": true, "cascades": 5}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("lighting.cascades: 5 is out of range; allowed [1, 4]"), std::string::npos)
      << p[0];
}

TEST(LightingValidation, ShadowsAreRefusedWhereTheTracerWouldShadeWithoutThem) {
  const auto p =
      lightingProblems(R"({"lighting": {"shadows": true}, "taa": {"mode": "adaptive"}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(
      p[0].find("lighting.shadows: adaptive ray tracing shades its traced pixels without shadows"),
      std::string::npos)
      << p[0];
}

}  // namespace

namespace {

TEST(LodValidation, Lod0RefusesWhatItOverrides) {
  auto p = lightingProblems(R"({"render": {"lod0": true}, "material": {"lod_bias": -1}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("material.lod_bias: render.lod0 samples mip 0"), std::string::npos) << p[0];
  p = lightingProblems(R"({"render": {"lod0": true, "lod0_alpha_test": true}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("render.lod0_alpha_test: render.lod0 already"), std::string::npos) << p[0];
  p = lightingProblems(
      R"({"render": {"lod0": true}, "taa": {"mode": "adaptive"}, "adaptive": {"ray_lod": true}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("adaptive.ray_lod: render.lod0"), std::string::npos) << p[0];
}

// The adaptive passes trace and segment at output size, pixel for pixel against the G-buffer:
// a render at another size (upsampled, or a dynamic resolution) would pair other pixels.
TEST(AdaptiveValidation, ARenderAtAnotherSizeThanTheOutputIsRefused) {
  for (const char* render :
       {R"({"upsample": 2})",
        R"({"scale_schedule": [{"frame": 0, "scale": 1.0}, {"frame": 2, "scale": 0.5}]})"}) {
    SCOPED_TRACE(render);
    const auto p =
        lightingProblems(std::string(R"({"taa": {"mode": "adaptive"}, "render": )") + render + "}");
    ASSERT_EQ(p.size(), 1u);
    EXPECT_NE(p[0].find("taa.mode: adaptive traces and segments at output size against the "
                        "G-buffer; remove render.upsample and render.scale_schedule"),
              std::string::npos)
        << p[0];
  }
  EXPECT_TRUE(
      lightingProblems(R"({"taa": {"mode": "adaptive"}, "render": {"upsample": 1}})").empty());
}

TEST(LodValidation, AnisoNeedsTheRayDifferentialLod) {
  auto p = lightingProblems(
      R"({"taa": {"mode": "adaptive"}, "adaptive": {"ray_lod": false, "aniso": 4}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("adaptive.aniso: shapes the ray-differential LOD"), std::string::npos)
      << p[0];
  EXPECT_TRUE(
      lightingProblems(R"({"taa": {"mode": "adaptive"}, "adaptive": {"aniso": 4}})").empty());
  EXPECT_FALSE(lightingProblems(R"({"adaptive": {"aniso": 4}})").empty())
      << "adaptive.* needs taa.mode adaptive";
}

}  // namespace

namespace {

TEST(StillImageValidation, NeedsAStillCameraAndTheRasterPath) {
  auto p = lightingProblems(R"({"debug": {"image_sampling": "nearest"}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("debug.image_sampling: samples debug.image, which is not set"),
            std::string::npos)
      << p[0];
  p = lightingProblems(
      R"({"debug": {"image": "scenes/still_zone_plate.png"}, "camera": {"strafe": {"speed": 1}}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("debug.image: upsamples a still image, but the camera moves"),
            std::string::npos)
      << p[0];
  p = lightingProblems(
      R"({"debug": {"image": "scenes/still_zone_plate.png"}, "taa": {"mode": "tscmaa"}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("debug.image: replaces the raster's colour only"), std::string::npos) << p[0];
  p = lightingProblems(R"({"debug": {"image": "../outside.png"}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("debug.image: '../outside.png' leaves the case's folder"), std::string::npos)
      << p[0];
  EXPECT_TRUE(lightingProblems(R"({"debug": {"image": "scenes/still_zone_plate.png"}})").empty());
}

TEST(DebugChannelsValidation, NeedADebugViewAndAChannel) {
  auto p = lightingProblems(R"({"debug": {"channels": ["r"]}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("debug.channels: picks channels of a debug view, but debug.output is none"),
            std::string::npos)
      << p[0];
  p = lightingProblems(R"({"debug": {"output": "velocity", "channels": []}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("debug.channels: is empty"), std::string::npos) << p[0];
  EXPECT_TRUE(lightingProblems(R"({"debug": {"output": "velocity", "channels": ["g"]}})").empty());
}

TEST(FxaaBorderValidation, NeedsFxaaOutOfHistory) {
  auto p = lightingProblems(
      R"({"taa": {"mode": "adaptive"}, "adaptive": {"fxaa_out_of_history": false, "fxaa_debug_border": 8}})");
  ASSERT_EQ(p.size(), 1u);
  EXPECT_NE(p[0].find("adaptive.fxaa_debug_border: marks pixels for FXAA"), std::string::npos)
      << p[0];
  EXPECT_TRUE(
      lightingProblems(R"({"taa": {"mode": "adaptive"}, "adaptive": {"fxaa_debug_border": 8}})")
          .empty());
}

}  // namespace
