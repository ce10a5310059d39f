#include "scene/build_scene.h"

#include <gtest/gtest.h>

#include "scene/scene_error.h"
#include "scene_test_util.h"

namespace taa::scene {
namespace {

spec::CaseSpec caseIn(const std::string& folder) {
  spec::CaseSpec c;
  c.name = "t";
  c.file = std::filesystem::path(TAA_SOURCE_DIR) / folder / "t.json";
  return c;
}

TEST(SceneBuild, BuiltinWorldThenMoversInOrder) {
  spec::CaseSpec c = caseIn("cases");
  c.scene.builtin = spec::BuiltinScene::Checkerboard;
  c.movers.resize(2);
  c.movers[0].shape = spec::MoverShape::Sphere;
  c.movers[0].color = {0.1f, 0.9f, 0.2f};
  c.movers[1].shape = spec::MoverShape::Cube;
  const Scene s = buildScene(c);
  ASSERT_EQ(s.models.size(), 3u);
  EXPECT_EQ(s.models[0].name, "builtin:checkerboard");
  EXPECT_EQ(s.models[1].name, "mover:sphere");
  EXPECT_EQ(s.models[2].name, "mover:cube");
  const auto draws = poseModel(s, 1, 0.0);
  ASSERT_EQ(draws.size(), 1u);
  const Material& m = s.materials[size_t(s.meshes[size_t(draws[0].mesh)].primitives[0].material)];
  EXPECT_EQ(m.baseColorFactor, glm::vec4(0.1f, 0.9f, 0.2f, 1.0f));
}

TEST(SceneBuild, GltfWorldAndMoverResolveAgainstTheCaseFolder) {
  spec::CaseSpec c = caseIn("cases/scenes");
  c.scene.builtin = spec::BuiltinScene::None;
  c.scene.gltf = "alpha_modes.gltf";
  c.movers.resize(1);
  c.movers[0].shape = spec::MoverShape::Gltf;
  c.movers[0].gltf = "animated.gltf";
  const Scene s = buildScene(c);
  ASSERT_EQ(s.models.size(), 2u);
  EXPECT_EQ(s.models[0].name, "alpha_modes");
  EXPECT_EQ(s.models[1].name, "animated");
  EXPECT_EQ(s.models[1].animations.size(), 1u);
  // Mesh indices of the second model point past the first model's meshes.
  EXPECT_EQ(poseModel(s, 1, 0.0)[0].mesh, 3);
}

TEST(SceneBuild, AlphaOverrideTouchesOnlyMaterialsWithAlpha) {
  spec::CaseSpec c = caseIn("cases/scenes");
  c.scene.builtin = spec::BuiltinScene::None;
  c.scene.gltf = "alpha_modes.gltf";
  c.material.alpha_mode = spec::AlphaMode::Mask;
  c.material.alpha_cutoff = 0.7f;
  Scene s = buildScene(c);
  EXPECT_EQ(s.materials[0].alphaMode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(s.materials[0].alphaCutoff, 0.7f);
  EXPECT_EQ(s.materials[1].alphaMode, AlphaMode::Mask);  // the blended pane now alpha-tests
  EXPECT_EQ(s.materials[2].alphaMode, AlphaMode::Opaque);
  c.material.alpha_mode = spec::AlphaMode::Blend;
  s = buildScene(c);
  EXPECT_EQ(s.materials[0].alphaMode, AlphaMode::Blend);
  EXPECT_EQ(s.materials[1].alphaMode, AlphaMode::Blend);
  EXPECT_EQ(s.materials[2].alphaMode, AlphaMode::Opaque);
  c.material.alpha_mode = spec::AlphaMode::Asset;
  s = buildScene(c);
  EXPECT_EQ(s.materials[0].alphaMode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(s.materials[0].alphaCutoff, 0.3f);
  EXPECT_EQ(s.materials[1].alphaMode, AlphaMode::Blend);
}

// The settings audit found the override accepted and ignored on a scene without alpha.
TEST(SceneBuild, AlphaOverrideOnASceneWithoutAlphaIsRefused) {
  spec::CaseSpec c = caseIn("cases");
  c.scene.builtin = spec::BuiltinScene::Fence;
  for (const auto mode : {spec::AlphaMode::Mask, spec::AlphaMode::Blend}) {
    c.material.alpha_mode = mode;
    try {
      buildScene(c);
      ADD_FAILURE() << "accepted " << spec::enumToString(mode);
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(
                    "t.json: material.alpha_mode: no material of the scene has alpha"),
                std::string::npos)
          << e.what();
    }
  }
  c.material.alpha_mode = spec::AlphaMode::Asset;
  EXPECT_NO_THROW(buildScene(c));
}

TEST(SceneBuild, FoliageCanBeForcedToBlend) {
  spec::CaseSpec c = caseIn("cases");
  c.scene.builtin = spec::BuiltinScene::Foliage;
  c.material.alpha_mode = spec::AlphaMode::Blend;
  const Scene s = buildScene(c);
  int blended = 0;
  for (const Material& m : s.materials) blended += m.alphaMode == AlphaMode::Blend;
  EXPECT_EQ(blended, 1);
}

TEST(SceneBuild, ErrorsNameTheFile) {
  spec::CaseSpec c = caseIn("cases");
  c.scene.builtin = spec::BuiltinScene::None;
  try {
    buildScene(c);
    ADD_FAILURE();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("t.json"), std::string::npos) << e.what();
  }
  c = caseIn("cases/scenes");
  c.scene.builtin = spec::BuiltinScene::None;
  c.scene.gltf = "refused/external_http.gltf";
  try {
    buildScene(c);
    ADD_FAILURE();
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("external_http.gltf"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("http://example.com/quad.bin"), std::string::npos)
        << e.what();
  }
  for (const char* bad :
       {"../secret.gltf", "/etc/x.gltf", "https://example.com/x.glb", "a/../../x.gltf"}) {
    c.scene.gltf = bad;
    try {
      buildScene(c);
      ADD_FAILURE() << bad;
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(std::string("scene.gltf: '") + bad), std::string::npos)
          << e.what();
    }
  }
}

}  // namespace
}  // namespace taa::scene
