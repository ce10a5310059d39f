// A material's emission: emissiveFactor times KHR_materials_emissive_strength (1 without
// it), checked values, and the emissive texture that multiplies it.
#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <nlohmann/json.hpp>

#include "scene/gltf_loader.h"
#include "scene/scene_error.h"
#include "scene_test_util.h"

namespace taa::scene {
namespace {

namespace fs = std::filesystem;

// cases/scenes/emissive.gltf with `change` applied, written to the test output folder.
fs::path emissiveVariant(const std::string& name,
                         const std::function<void(nlohmann::json&)>& change) {
  std::ifstream in(testing::assetPath("emissive.gltf"));
  nlohmann::json doc = nlohmann::json::parse(in);
  change(doc);
  const fs::path dir = fs::path(TAA_TEST_OUT) / "gltf_emissive";
  fs::create_directories(dir);
  std::ofstream(dir / name) << doc.dump();
  return dir / name;
}

TEST(GltfEmissive, FactorTimesStrength) {
  Scene s;
  loadGltf(testing::assetPath("emissive.gltf"), s);
  ASSERT_EQ(s.materials.size(), 4u);
  EXPECT_EQ(s.materials[0].emissive, glm::vec3(4.0f, 2.0f, 0.5f));
  EXPECT_EQ(s.materials[1].emissive, glm::vec3(0.25f, 0.5f, 1.0f)) << "no strength: 1";
  EXPECT_EQ(s.materials[2].emissive, glm::vec3(0.0f));
  EXPECT_EQ(s.materials[3].emissive, glm::vec3(0.0f));
  EXPECT_TRUE(s.notes.empty()) << "KHR_materials_emissive_strength is supported";
}

TEST(GltfEmissive, BadValuesAreRefusedByKey) {
  const struct {
    const char* name;
    std::function<void(nlohmann::json&)> change;
    const char* key;
  } cases[] = {
      {"negative_strength.gltf",
       [](nlohmann::json& d) {
         d["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] =
             -1;
       },
       "materials[0].extensions.KHR_materials_emissive_strength.emissiveStrength"},
      {"text_strength.gltf",
       [](nlohmann::json& d) {
         d["materials"][0]["extensions"]["KHR_materials_emissive_strength"]["emissiveStrength"] =
             "4";
       },
       "materials[0].extensions.KHR_materials_emissive_strength.emissiveStrength"},
      {"bright_factor.gltf",
       [](nlohmann::json& d) { d["materials"][1]["emissiveFactor"][2] = 2.0; },
       "materials[1].emissiveFactor[2]"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path file = emissiveVariant(c.name, c.change);
    Scene s;
    try {
      loadGltf(file, s);
      ADD_FAILURE() << "loaded";
    } catch (const SceneError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(file.string()), std::string::npos) << m;
      EXPECT_NE(m.find(c.key), std::string::npos) << m;
    }
  }
}

TEST(GltfEmissive, AnEmissiveTextureIsKeptAndNeedsAFactor) {
  // Before issue 25 the texture was dropped with a note and the material left unlit.
  const fs::path file = emissiveVariant("textured.gltf", [](nlohmann::json& d) {
    d["materials"][0]["emissiveTexture"] = {{"index", 0}};
    d["materials"][2]["emissiveTexture"] = {{"index", 0}};  // factor 0: multiplies nothing
    d["textures"] = {{{"source", 0}}};
    // A 1x1 white PNG.
    d["images"] = {
        {{"uri",
          "data:image/png;base64,iVBORw0KGgoAAAANSUhEUgAAAAEAAAABCAYAAAAfFcSJAAAAC0lEQVR4"
          "nGP4DwQACfsD/fteaysAAAAASUVORK5CYII="}}};
  });
  Scene s;
  loadGltf(file, s);
  EXPECT_EQ(s.materials[0].emissive, glm::vec3(4.0f, 2.0f, 0.5f));
  EXPECT_GE(s.materials[0].emissiveTexture, 0);
  EXPECT_FALSE(s.textures[size_t(s.materials[0].emissiveTexture)].linear) << "sRGB colour";
  EXPECT_EQ(s.materials[2].emissiveTexture, -1);
  EXPECT_TRUE(s.notes.empty()) << s.notes[0];
}

}  // namespace
}  // namespace taa::scene
