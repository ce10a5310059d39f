#include <gtest/gtest.h>

#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "scene/gltf_checks.h"
#include "scene/gltf_convert.h"
#include "scene/gltf_loader.h"
#include "scene/scene_error.h"
#include "scene_test_util.h"

namespace taa::scene {
namespace {

using testing::assetPath;

struct Loaded {
  Scene scene;
  Model model;
};

Loaded load(const std::string& name) {
  Loaded l;
  l.model = loadGltf(assetPath(name), l.scene);
  l.scene.models.push_back(l.model);
  return l;
}

glm::vec3 apply(const glm::mat4& m, const glm::vec3& p) {
  return glm::vec3(m * glm::vec4(p, 1.0f));
}

void expectVecNear(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

TEST(GltfLoad, TexturedBoxWithEmbeddedPng) {
  const Loaded l = load("textured_box.gltf");
  ASSERT_EQ(l.model.nodes.size(), 4u);
  EXPECT_EQ(l.model.name, "textured_box");
  EXPECT_EQ(l.model.nodes[0].name, "root");
  EXPECT_EQ(l.model.nodes[1].parent, 0);
  EXPECT_EQ(l.model.nodes[2].parent, 0);
  EXPECT_EQ(l.model.nodes[3].parent, 2);
  EXPECT_EQ(l.model.nodes[1].mesh, l.model.nodes[3].mesh) << "a shared mesh is loaded once";
  ASSERT_EQ(l.scene.meshes.size(), 1u);
  ASSERT_EQ(l.scene.meshes[0].primitives.size(), 1u);
  EXPECT_EQ(l.scene.meshes[0].primitives[0].indexCount, 36u);
  EXPECT_EQ(l.scene.vertices.size(), 24u);
  expectVecNear(l.scene.meshes[0].boundsMin, glm::vec3(-0.5f));
  expectVecNear(l.scene.meshes[0].boundsMax, glm::vec3(0.5f));
  ASSERT_EQ(l.scene.materials.size(), 1u);
  const Material& m = l.scene.materials[0];
  EXPECT_EQ(m.baseColorFactor, glm::vec4(1.0f, 0.5f, 0.5f, 1.0f));
  EXPECT_EQ(m.alphaMode, AlphaMode::Opaque);
  EXPECT_FALSE(m.doubleSided);
  ASSERT_EQ(m.baseColorTexture, 0);
  const Texture& t = l.scene.textures[0];
  EXPECT_EQ(t.sampler.wrapS, Wrap::ClampToEdge) << "sampler clamps both axes";
  EXPECT_EQ(t.sampler.wrapT, Wrap::ClampToEdge);
  ASSERT_EQ(t.levels.size(), 5u);
  EXPECT_EQ(t.levels[0].width, 16);
  EXPECT_EQ(t.levels[4].width, 1);
  EXPECT_EQ(t.levels[0].rgba[0], 240);          // first cell: light
  EXPECT_EQ(t.levels[0].rgba[4 * 4 + 2], 200);  // texel (4, 0): blue
}

TEST(GltfLoad, HierarchyTransformsComposeParentFirst) {
  const Loaded l = load("textured_box.gltf");
  const auto draws = poseModel(l.scene, 0, 0.0);
  ASSERT_EQ(draws.size(), 2u);
  EXPECT_EQ(draws[0].node, 1);
  EXPECT_EQ(draws[1].node, 3);
  // box: T(1,0,0) S(2) Ry(90): +x goes to -z.
  expectVecNear(apply(draws[0].transform, {1, 0, 0}), {1, 0, -2});
  // box2: root * (T(0,3,0) Rx(90)) * T(0,0,1): origin -> (0,-1,0) + (0,3,0) -> x2 +(1,0,0).
  expectVecNear(apply(draws[1].transform, {0, 0, 0}), {1, 4, 0});
  // The matrix node decomposes to TRS.
  const Node& lifted = l.model.nodes[2];
  expectVecNear(lifted.translation, {0, 3, 0});
  expectVecNear(lifted.scale, {1, 1, 1});
  const glm::quat rx = glm::angleAxis(glm::radians(90.0f), glm::vec3(1, 0, 0));
  EXPECT_NEAR(std::fabs(glm::dot(lifted.rotation, rx)), 1.0f, 1e-5f);
  glm::vec3 lo, hi;
  modelBounds(l.scene, 0, lo, hi);
  expectVecNear(lo, {0, -1, -1});
  expectVecNear(hi, {2, 5, 1});
}

TEST(GltfLoad, DecomposeHandlesScaleAndMirroring) {
  const glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(1, 2, 3)) *
                      glm::mat4_cast(glm::angleAxis(0.7f, glm::normalize(glm::vec3(1, 2, 3)))) *
                      glm::scale(glm::mat4(1.0f), glm::vec3(-2, 3, 4));
  glm::vec3 t, s;
  glm::quat r;
  decomposeTrs(m, t, r, s);
  const glm::mat4 back =
      glm::translate(glm::mat4(1.0f), t) * glm::mat4_cast(r) * glm::scale(glm::mat4(1.0f), s);
  for (int c = 0; c < 4; ++c)
    for (int k = 0; k < 4; ++k) EXPECT_NEAR(back[c][k], m[c][k], 1e-5f);
}

// The loader reads the node array itself (tinygltf never sees it): every field as the file
// gives it, a matrix decomposed, and the array gone from the document handed on.
TEST(GltfLoad, NodeListReadsEveryFieldAndTakesTheArray) {
  nlohmann::json doc = nlohmann::json::parse(R"({"asset": {}, "nodes": [
    {"name": "a", "children": [2, 1], "mesh": 0, "skin": 1, "camera": 2, "weights": [0.25, 1],
     "translation": [1, 2, 3], "rotation": [0, 0.6, 0, 0.8], "scale": [2, 3, 4]},
    {"matrix": [2, 0, 0, 0, 0, 2, 0, 0, 0, 0, 2, 0, 5, 6, 7, 1]},
    {"extensions": {"EXT_mesh_gpu_instancing": {"attributes": {"TRANSLATION": 3}}}}]})");
  const std::vector<GltfNode> n = takeGltfNodes(doc);
  EXPECT_FALSE(doc.contains("nodes"));
  EXPECT_TRUE(doc.contains("asset"));
  ASSERT_EQ(n.size(), 3u);
  EXPECT_EQ(n[0].name, "a");
  EXPECT_EQ(n[0].children, (std::vector<int>{2, 1}));
  EXPECT_EQ(n[0].mesh, 0);
  EXPECT_EQ(n[0].skin, 1);
  EXPECT_EQ(n[0].camera, 2);
  EXPECT_EQ(n[0].weights, (std::vector<float>{0.25f, 1.0f}));
  expectVecNear(n[0].translation, {1, 2, 3});
  EXPECT_EQ(n[0].rotation, glm::quat(0.8f, 0.0f, 0.6f, 0.0f));  // glTF's order is x, y, z, w
  expectVecNear(n[0].scale, {2, 3, 4});
  EXPECT_TRUE(n[0].instancing.is_null());
  EXPECT_EQ(n[1].name, "");
  EXPECT_EQ(n[1].mesh, -1);
  expectVecNear(n[1].translation, {5, 6, 7});
  expectVecNear(n[1].scale, {2, 2, 2});
  EXPECT_EQ(n[2].instancing["attributes"]["TRANSLATION"], 3);
}

TEST(GltfLoad, GlbWithoutNormalsGetsFlatNormals) {
  const Loaded l = load("box.glb");
  ASSERT_EQ(l.model.nodes.size(), 1u);
  ASSERT_EQ(l.scene.meshes.size(), 1u);
  EXPECT_EQ(l.scene.vertices.size(), 36u) << "flat shading gives every triangle its own vertices";
  for (size_t i = 0; i < l.scene.vertices.size(); i += 3) {
    const glm::vec3 n = l.scene.vertices[i].normal;
    EXPECT_NEAR(std::fabs(n.x) + std::fabs(n.y) + std::fabs(n.z), 1.0f, 1e-6f);
    EXPECT_EQ(n, l.scene.vertices[i + 1].normal);
    // Outward: the normal points the same way as the face's position.
    EXPECT_GT(glm::dot(n, l.scene.vertices[i].position), 0.0f);
  }
  ASSERT_EQ(l.scene.textures.size(), 1u);
  const Texture& t = l.scene.textures[0];
  ASSERT_EQ(t.levels.size(), 3u);
  EXPECT_EQ(t.levels[0].width, 5);
  EXPECT_EQ(t.levels[0].height, 3);
  EXPECT_EQ(t.levels[1].width, 2);
  EXPECT_EQ(t.levels[1].height, 1);
  EXPECT_EQ(t.levels[0].rgba[0], 255);  // (0, 0) red
  EXPECT_EQ(t.levels[0].rgba[6], 255);  // (1, 0) blue
  EXPECT_EQ(t.sampler.wrapS, Wrap::Repeat) << "no sampler: repeat, linear, linear mips";
  EXPECT_EQ(t.sampler.wrapT, Wrap::Repeat);
  EXPECT_EQ(t.sampler.mag, Filter::Linear);
  EXPECT_EQ(t.sampler.mip, MipFilter::Linear);
}

TEST(GltfLoad, AnimatedModelWithExternalBuffer) {
  const Loaded l = load("animated.gltf");
  ASSERT_EQ(l.model.nodes.size(), 2u);
  ASSERT_EQ(l.model.animations.size(), 1u);
  const Animation& a = l.model.animations[0];
  EXPECT_EQ(a.name, "move");
  EXPECT_FLOAT_EQ(a.duration, 2.0f);
  ASSERT_EQ(a.channels.size(), 4u);
  EXPECT_EQ(a.channels[0].interpolation, Interpolation::Linear);
  EXPECT_EQ(a.channels[1].path, AnimPath::Rotation);
  EXPECT_EQ(a.channels[2].interpolation, Interpolation::Step);
  EXPECT_EQ(a.channels[3].interpolation, Interpolation::CubicSpline);
  EXPECT_EQ(a.channels[3].values.size(), 6u);
  EXPECT_EQ(a.channels[3].node, 1);
}

TEST(GltfLoad, AlphaModesCutoffAndDoubleSided) {
  const Loaded l = load("alpha_modes.gltf");
  ASSERT_EQ(l.scene.materials.size(), 3u);
  const Material& leaf = l.scene.materials[0];
  EXPECT_EQ(leaf.alphaMode, AlphaMode::Mask);
  EXPECT_FLOAT_EQ(leaf.alphaCutoff, 0.3f);
  EXPECT_TRUE(leaf.doubleSided);
  ASSERT_GE(leaf.baseColorTexture, 0);
  const Texture& t = l.scene.textures[size_t(leaf.baseColorTexture)];
  EXPECT_EQ(t.levels[0].width, 8);
  EXPECT_EQ(t.levels[0].rgba[3], 0);                      // corner transparent
  EXPECT_EQ(t.levels[0].rgba[(4 * 8 + 4) * 4 + 3], 255);  // centre opaque
  const Material& pane = l.scene.materials[1];
  EXPECT_EQ(pane.alphaMode, AlphaMode::Blend);
  EXPECT_FLOAT_EQ(pane.baseColorFactor.a, 0.5f);
  EXPECT_EQ(l.scene.materials[2].alphaMode, AlphaMode::Opaque);
  EXPECT_FLOAT_EQ(l.scene.materials[2].alphaCutoff, 0.5f) << "glTF default cutoff";
}

// Each refused file must fail before anything outside its folder is read, naming the
// file and the offending uri.
struct Refusal {
  const char* file;
  const char* uri;
  const char* why;
};

TEST(GltfRefuse, EachInputClassNamesFileAndUri) {
  const Refusal cases[] = {
      {"refused/external_http.gltf", "http://example.com/quad.bin", "external URI"},
      {"refused/file_scheme.gltf", "file:///etc/hostname", "external URI"},
      {"refused/absolute_path.gltf", "/etc/hostname", "absolute path"},
      {"refused/parent_dir.gltf", "../alpha_leaf.png", "leaves the glTF's folder"},
      {"refused/encoded_parent.gltf", "sub/%2E%2E/%2e%2e/animated.bin", "leaves the glTF's folder"},
      {"refused/external_buffer.glb", "https://example.com/payload.bin", "external URI"},
      {"refused/missing_image.gltf", "not_here.png", "could not be read"},
  };
  for (const Refusal& c : cases) {
    SCOPED_TRACE(c.file);
    Scene s;
    try {
      loadGltf(assetPath(c.file), s);
      ADD_FAILURE() << "loaded";
    } catch (const SceneError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find(assetPath(c.file).string()), std::string::npos) << msg;
      EXPECT_NE(msg.find(c.uri), std::string::npos) << msg;
      EXPECT_NE(msg.find(c.why), std::string::npos) << msg;
    }
  }
}

TEST(GltfRefuse, UriRules) {
  const std::filesystem::path f = "x.gltf";
  auto check = [&](const std::string& json) { checkGltfUris(f, parseGltfJson(f, json)); };
  EXPECT_NO_THROW(check(R"({"buffers":[{"uri":"data:application/octet-stream;base64,AAAA"}]})"));
  EXPECT_NO_THROW(check(R"({"images":[{"uri":"textures/a%20b.png"}],"buffers":[{}]})"));
  for (const char* bad : {"HTTPS://x/y.bin", "ftp:x", "C:/x.bin", "..\\\\x.bin", "a/../../b.bin",
                          "%2e%2e/b.bin", "%2E%2E/b.bin", "\\\\\\\\server\\\\share\\\\b.bin", "a.bin%00.png",
                          "a%0a.bin"}) {
    const std::string json = std::string(R"({"images":[{"uri":")") + bad + R"("}]})";
    EXPECT_THROW(check(json), SceneError) << bad;
  }
  EXPECT_THROW(check("{not json"), SceneError);
  // Escapes decode in either case: %5F and %5f are both '_'.
  EXPECT_EQ(gltfFileUris(parseGltfJson(f, R"({"images":[{"uri":"a%5Fb%5fc.png"}]})")),
            std::vector<std::string>{"a_b_c.png"});
}

// An embedded buffer tinygltf would refuse as "File not found" (not base64) or with the whole
// URI quoted (a byteLength its data does not give): named here, with the numbers, in one line.
TEST(GltfRefuse, ADataUriBufferSaysWhatIsWrongWithIt) {
  const std::filesystem::path f = "x.gltf";
  auto error = [&](const std::string& uri, const std::string& length) {
    try {
      checkGltfUris(f, parseGltfJson(f, R"({"buffers":[{"uri":")" + uri + R"(","byteLength":)" +
                                            length + "}]}"));
    } catch (const SceneError& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  EXPECT_EQ(error("data:application/octet-stream;base64,AAAA", "3"), "");
  EXPECT_EQ(error("data:application/gltf-buffer;base64,AAA=", "2"), "");
  EXPECT_NE(error("data:application/gltf-buffer,1111", "4")
                .find("buffers[0].uri is a data URI that is not base64"),
            std::string::npos);
  const std::string big = "data:application/octet-stream;base64," + std::string(266664, 'A');
  const std::string msg = error(big, "4400");
  EXPECT_NE(msg.find("buffers[0].byteLength is 4400, but its data URI holds 199998 bytes"),
            std::string::npos)
      << msg.substr(0, 300);
  EXPECT_LT(msg.size(), 300u);
}

// A corrupt index names itself, its accessor and the vertex count it passed.
TEST(GltfRefuse, AnIndexPastTheVerticesIsNamed) {
  const std::filesystem::path dir = std::filesystem::path(TAA_TEST_OUT) / "gltf_bad_index";
  std::filesystem::create_directories(dir);
  // Three vertices (36 bytes), then the indices 0, 1, 5 as uint16 and two bytes of padding.
  std::ofstream(dir / "t.gltf") << R"({"asset": {"version": "2.0"}, "scene": 0,
    "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
    "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
    "buffers": [{"byteLength": 44, "uri":
      "data:application/octet-stream;base64,AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAABAAUAAAA="}],
    "bufferViews": [{"buffer": 0, "byteLength": 36}, {"buffer": 0, "byteOffset": 36, "byteLength": 6}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3",
                   "min": [0, 0, 0], "max": [1, 1, 0]},
                  {"bufferView": 1, "componentType": 5123, "count": 3, "type": "SCALAR"}]})";
  Scene s;
  try {
    loadGltf(dir / "t.gltf", s);
    ADD_FAILURE() << "loaded";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("has index 5 (accessor 1), past its 3 vertices"),
              std::string::npos)
        << e.what();
  }
}

TEST(GltfRefuse, SymlinkOutOfTheFolderIsRefusedByTheFileJail) {
  // The uri is a harmless relative name, but it is a symlink leading outside: only the
  // file-system callbacks can catch that.
  const std::filesystem::path dir = std::filesystem::path(TAA_TEST_OUT) / "gltf_jail";
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir / "inner");
  std::filesystem::copy_file(assetPath("animated.bin"), dir / "outside.bin");
  std::filesystem::create_symlink("../outside.bin", dir / "inner" / "animated.bin");
  std::filesystem::copy_file(assetPath("animated.gltf"), dir / "inner" / "animated.gltf");
  Scene s;
  try {
    loadGltf(dir / "inner" / "animated.gltf", s);
    ADD_FAILURE() << "loaded through a symlink";
  } catch (const SceneError& e) {
    EXPECT_NE(std::string(e.what()).find("outside the glTF's folder"), std::string::npos)
        << e.what();
  }
}

TEST(GltfRefuse, MissingAndCorruptFiles) {
  Scene s;
  EXPECT_THROW(loadGltf(assetPath("does_not_exist.gltf"), s), SceneError);
  const std::filesystem::path dir = std::filesystem::path(TAA_TEST_OUT) / "gltf_corrupt";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "bad.gltf") << R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 3}]})";
  std::ofstream(dir / "bad.glb") << "glTF\x02";
  for (const char* name : {"bad.gltf", "bad.glb"}) {
    try {
      loadGltf(dir / name, s);
      ADD_FAILURE() << name << " loaded";
    } catch (const SceneError& e) {
      EXPECT_NE(std::string(e.what()).find(name), std::string::npos) << e.what();
    }
  }
}

}  // namespace
}  // namespace taa::scene
