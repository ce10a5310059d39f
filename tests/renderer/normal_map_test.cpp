// material.normal_strength and glTF normal textures on the GPU, with
// cases/scenes/normal_tilt.gltf: two flat quads whose normal maps tilt every normal 30
// degrees, the left towards +u (+x in the world), the right towards the image's top (-v,
// -z in the world). A light from the tilt's side brightens a quad, from the other side
// darkens it; strength 0 is the flat quad; forward and deferred agree.
#include <gtest/gtest.h>

#include <cmath>

#include "scene/build_scene.h"
#include "scene/scene_error.h"
#include "scene/textures.h"
#include "support/gpu.h"

namespace taa {
namespace {

spec::CaseSpec tiltCase(float strength, const std::string& lightTravel,
                        const std::string& path = "forward") {
  return test::caseFromJson(R"({
    "scene": {"gltf": "scenes/normal_tilt.gltf"},
    "material": {"normal_strength": )" +
                                std::to_string(strength) + R"(},
    "lighting": {"direction": )" +
                                lightTravel + R"(, "specular": 0, "ambient": [0, 0, 0]},
    "render": {"path": ")" + path +
                                R"(", "width": 160, "height": 90},
    "camera": {"position": [0, 2.2, 1.2], "target": [0, 0, 0]},
    "jitter": {"pattern": "none"},
    "taa": {"mode": "off"},
    "script": {"frames": 1},
    "output": {"frames": [0]}
  })",
                            "normal_tilt");
}

// Sum of luminance over the quad pixels (not sky, by the ids target) of the left (quad A)
// or right (quad B) half of the frame.
double halfLuma(const spec::CaseSpec& spec, bool right) {
  RenderOptions o;
  o.captures |= {Capture::Ids};
  const auto records = test::renderCaseWith(spec, o, {0});
  const Image& im = records[0].color;
  const Image& ids = test::capturedImage(records[0], Capture::Ids);  // channel 1: material, -1 sky
  double sum = 0.0;
  for (int y = 0; y < im.height; ++y)
    for (int x = right ? im.width / 2 : 0; x < (right ? im.width : im.width / 2); ++x)
      if (ids.at(x, y, 1) >= 0.0f)
        sum += 0.2126 * im.at(x, y, 0) + 0.7152 * im.at(x, y, 1) + 0.0722 * im.at(x, y, 2);
  return sum;
}

constexpr const char* kFromPlusX = "[-1, -1, 0]";  // travels towards -x: lights faces tilted to +x
constexpr const char* kFromMinusX = "[1, -1, 0]";
constexpr const char* kFromMinusZ = "[0, -1, 1]";  // lights faces tilted to -z (the image's top)
constexpr const char* kFromPlusZ = "[0, -1, -1]";

TEST(NormalMap, ATiltTowardsPlusUFacesALightFromPlusX) {
  const double flat = halfLuma(tiltCase(0.0f, kFromPlusX), false);
  const double lit = halfLuma(tiltCase(1.0f, kFromPlusX), false);
  const double away = halfLuma(tiltCase(1.0f, kFromMinusX), false);
  const double flatAway = halfLuma(tiltCase(0.0f, kFromMinusX), false);
  // Flat: n.l = cos 45 either way. Tilted 30 degrees: cos 15 towards, cos 75 away.
  EXPECT_NEAR(flat, flatAway, 1e-3 * flat);
  EXPECT_NEAR(lit / flat, std::cos(0.2618) / std::cos(0.7854), 0.03);
  EXPECT_NEAR(away / flat, std::cos(1.309) / std::cos(0.7854), 0.03);
}

TEST(NormalMap, ATiltTowardsTheImageTopFacesMinusZWhereVDecreases) {
  const double flat = halfLuma(tiltCase(0.0f, kFromMinusZ), true);
  const double lit = halfLuma(tiltCase(1.0f, kFromMinusZ), true);
  const double away = halfLuma(tiltCase(1.0f, kFromPlusZ), true);
  EXPECT_NEAR(lit / flat, std::cos(0.2618) / std::cos(0.7854), 0.03);
  EXPECT_NEAR(away / flat, std::cos(1.309) / std::cos(0.7854), 0.03);
}

TEST(NormalMap, StrengthScalesTheTilt) {
  // Strength 2 doubles the map's x: (2 sin 30, cos 30) normalised leans 49 degrees, so a
  // light 45 degrees off on the far side grazes it (n.l = cos 94, clamped to 0).
  const double flat = halfLuma(tiltCase(0.0f, kFromMinusX), false);
  const double one = halfLuma(tiltCase(1.0f, kFromMinusX), false);
  const double two = halfLuma(tiltCase(2.0f, kFromMinusX), false);
  EXPECT_LT(two, one);
  EXPECT_LT(one, flat);
  EXPECT_LT(two, 0.02 * flat);
}

TEST(NormalMap, ForwardAndDeferredPerturbAlike) {
  const double forward = halfLuma(tiltCase(1.0f, kFromPlusX, "forward"), false);
  const double deferred = halfLuma(tiltCase(1.0f, kFromPlusX, "deferred"), false);
  EXPECT_NEAR(deferred, forward, 2e-3 * forward);
}

TEST(NormalMap, TheLoaderKeepsTheMapLinearAndItsScale) {
  const auto spec = tiltCase(1.0f, kFromPlusX);
  const scene::Scene s = scene::buildScene(spec);
  ASSERT_EQ(s.materials.size(), 2u);
  for (const auto& m : s.materials) {
    ASSERT_GE(m.normalTexture, 0);
    EXPECT_EQ(m.normalScale, 1.0f);
    EXPECT_TRUE(s.textures[size_t(m.normalTexture)].linear);
  }
  // Mips of a normal map average the stored values (a colour map averages in linear light).
  const std::vector<uint8_t> blackWhite = {0, 0, 0, 255, 255, 255, 255, 255};
  const auto data = scene::makeTexture(2, 1, blackWhite, {}, true);
  const auto colour = scene::makeTexture(2, 1, blackWhite, {}, false);
  EXPECT_EQ(data.levels[1].rgba[0], 128);
  EXPECT_EQ(colour.levels[1].rgba[0], scene::linearToSrgb8(0.5));
}

TEST(NormalMap, StrengthIsRefusedWhereItWouldDoNothing) {
  auto flatScene =
      test::caseFromJson(R"({"material": {"normal_strength": 0.5}})", "no_normal_maps");
  try {
    scene::buildScene(flatScene);
    FAIL() << "a scene without normal maps accepted material.normal_strength";
  } catch (const scene::SceneError& e) {
    EXPECT_NE(std::string(e.what()).find(
                  "material.normal_strength: no material of the scene has a normalTexture"),
              std::string::npos)
        << e.what();
  }
  auto adaptive = tiltCase(1.0f, kFromPlusX);
  adaptive.taa.mode = spec::TaaMode::Adaptive;
  EXPECT_THROW(scene::buildScene(adaptive), scene::SceneError);
  adaptive.material.normal_strength = 0.0f;
  EXPECT_NO_THROW(scene::buildScene(adaptive));
}

// cases/scenes/normal_half.gltf: the floor's map holds 127 and 128 in every channel, and its u is
// exactly 0.5 down the view's centre column (the camera looks straight along the floor's v),
// where lavapipe's float filter (the sampler mirrors) gives 0.5 and the tangent-space normal is
// exactly 0. Such a pixel keeps its surface normal, so it is shaded as the flat floor (strength 0)
// is; elsewhere the map's near-zero normals tilt far either way. Dividing by the zero length
// instead gives a NaN normal, which the lighting reads as facing away: ambient only.
FrameRecord halfMapFrame(const std::string& path, float strength) {
  return test::renderCase(test::caseFromJson(R"({
      "scene": {"gltf": "scenes/normal_half.gltf"},
      "material": {"normal_strength": )" + std::to_string(strength) + R"(},
      "lighting": {"direction": [0.3, -1, 0.2]},
      "render": {"path": ")" + path + R"(", "width": 160, "height": 90},
      "camera": {"position": [0, 1.6, 1.6], "target": [0, 0, 0]},
      "jitter": {"pattern": "none"},
      "taa": {"mode": "off"},
      "script": {"frames": 1},
      "output": {"frames": [0], "aux": ["depth"]}
    })",
                                             "normal_half"))[0];
}

TEST(NormalMap, AZeroTangentSpaceNormalKeepsTheSurfacesNormal) {
  for (const char* path : {"forward", "deferred"}) {
    const FrameRecord mappedRecord = halfMapFrame(path, 1.0f), flatRecord = halfMapFrame(path, 0.0f);
    const Image &mapped = mappedRecord.color, &flat = flatRecord.color;
    const Image& depth = test::auxImage(mappedRecord, "depth");
    const int x = mapped.width / 2 - 1;
    int floor = 0, asFlat = 0;
    for (int y = 0; y < mapped.height; ++y) {
      if (depth.at(x, y) == 0.0f) continue;  // sky
      ++floor;
      asFlat += flat.at(x, y, 0) == mapped.at(x, y, 0) && flat.at(x, y, 1) == mapped.at(x, y, 1) &&
                flat.at(x, y, 2) == mapped.at(x, y, 2);
    }
    EXPECT_GE(floor, 40) << path;
    EXPECT_EQ(asFlat, floor) << path << ": centre column pixels shaded as the flat floor";
  }
}

}  // namespace
}  // namespace taa
