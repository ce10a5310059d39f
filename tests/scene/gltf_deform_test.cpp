// Skins, morph targets, vertex colours, several animations and extension checks of
// glTF files: the project's generated assets (tests/scene/assets_src/make_assets.py)
// and three Khronos sample models (cases/scenes/khronos/).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <glm/gtc/quaternion.hpp>
#include <nlohmann/json.hpp>

#include "frame/draw_list.h"
#include "invariants/invariant_support.h"
#include "passes/adaptive/trace_geometry.h"
#include "scene/build_scene.h"
#include "scene/gltf_convert.h"
#include "scene/gltf_loader.h"
#include "scene/scene_error.h"
#include "scene_test_util.h"
#include "script/frame_state.h"
#include "support/gpu.h"

namespace taa::scene {
namespace {

using testing::assetPath;

Scene loadGltfDeform(const std::string& name) {
  Scene s;
  s.models.push_back(loadGltf(assetPath(name), s));
  return s;
}

void expectNearGltfDeform(const glm::vec3& a, const glm::vec3& b, float eps = 1e-5f) {
  EXPECT_NEAR(a.x, b.x, eps);
  EXPECT_NEAR(a.y, b.y, eps);
  EXPECT_NEAR(a.z, b.z, eps);
}

// The bend quads rise by (x + 0.5) * 0.8 * t: skin and morph must give the same shape.
TEST(GltfDeform, SkinnedAndMorphedQuadsBendByTheAnalyticOffset) {
  for (const char* name : {"skinned_quad.gltf", "morphed_quad.gltf"}) {
    SCOPED_TRACE(name);
    const Scene s = loadGltfDeform(name);
    for (double t : {0.0, 0.25, 1.5}) {
      const auto draws = poseModel(s, 0, t);
      ASSERT_EQ(draws.size(), 1u);
      ASSERT_TRUE(draws[0].deformed());
      const std::vector<Vertex> v = deformVertices(s, draws[0]);
      const Mesh& mesh = s.meshes[size_t(draws[0].mesh)];
      ASSERT_EQ(v.size(), mesh.vertexCount);
      for (size_t i = 0; i < v.size(); ++i) {
        const glm::vec3 rest = s.vertices[mesh.firstVertex + i].position;
        const glm::vec3 moved = glm::vec3(draws[0].transform * glm::vec4(v[i].position, 1.0f));
        expectNearGltfDeform(moved, rest + glm::vec3(0.0f, (rest.x + 0.5f) * 0.8f * float(t), 0.0f));
      }
    }
  }
}

// Two skins over one mesh, two animations, a joint under an animated parent.
TEST(GltfDeform, SeveralSkinsEachPoseTheirOwnDraw) {
  const Scene s = loadGltfDeform("two_skins.gltf");
  ASSERT_EQ(s.models[0].skins.size(), 2u);
  const double t = 0.5;
  const auto draws = poseModel(s, 0, t);
  ASSERT_EQ(draws.size(), 2u);
  const Mesh& mesh = s.meshes[0];
  const std::vector<Vertex> first = deformVertices(s, draws[0]),
                            second = deformVertices(s, draws[1]);
  for (size_t i = 0; i < mesh.vertexCount; ++i) {
    const glm::vec3 rest = s.vertices[mesh.firstVertex + i].position;
    const float bend = rest.x + 0.5f;
    expectNearGltfDeform(first[i].position, rest + glm::vec3(0.0f, bend * 0.8f * float(t), 0.0f));
    // The second skin's joints both ride the slider (x += t); the lifter sinks 0.4 t.
    expectNearGltfDeform(second[i].position, rest + glm::vec3(float(t), -bend * 0.4f * float(t), 0.0f));
  }
}

// A fuzzer's find: JOINTS_0 as signed bytes gave a joint index of -64, converted to an unsigned
// index (undefined). Joint indices must be unsigned bytes or shorts, not normalized.
TEST(GltfDeform, JointIndicesOfAnotherTypeAreRefusedByName) {
  std::ifstream in(assetPath("skinned_quad.gltf"));
  const nlohmann::json original = nlohmann::json::parse(in);
  const int joints = original["meshes"][0]["primitives"][0]["attributes"]["JOINTS_0"];
  for (const auto& [type, normalized] : {std::pair{5120, false}, {5121, true}}) {
    nlohmann::json g = original;
    g["accessors"][size_t(joints)]["componentType"] = type;
    if (normalized) g["accessors"][size_t(joints)]["normalized"] = true;
    const auto file = std::filesystem::path(TAA_TEST_OUT) / "gltf-joints" /
                      ("joints_" + std::to_string(type) + (normalized ? "_normalized" : "") + ".gltf");
    std::filesystem::create_directories(file.parent_path());
    std::ofstream(file) << g.dump();
    Scene s;
    try {
      loadGltf(file, s);
      ADD_FAILURE() << file << " loaded";
    } catch (const SceneError& e) {
      const std::string msg = e.what();
      EXPECT_NE(msg.find("JOINTS_0 (accessors[" + std::to_string(joints) + "]) has componentType " +
                         std::to_string(type)),
                std::string::npos)
          << msg;
      EXPECT_EQ(msg.find("normalized;") != std::string::npos, normalized) << msg;
    }
  }
}

// CesiumMan's 210 vertices with weights summing to 0.18-0.999 collapsed towards the origin:
// weights are normalised as engines do, a vertex without any keeps its bind pose, and the
// run log says which mesh and how many.
TEST(GltfDeform, SkinWeightsNotSummingToOneAreNormalisedAndNoted) {
  const Scene twin = loadGltfDeform("skinned_quad.gltf");
  const Mesh& twinMesh = twin.meshes[0];
  std::ifstream in(assetPath("skinned_quad.gltf"));
  nlohmann::json g = nlohmann::json::parse(in);
  // The weights scaled by 0.18 to 0.99 (in a buffer of their own), one vertex's zeroed.
  const size_t n = twinMesh.skin.size(), zeroed = n / 2;
  ASSERT_GT(n, 2u);
  std::vector<float> scaled;
  for (size_t i = 0; i < n; ++i) {
    const float k = i == zeroed ? 0.0f : 0.18f + 0.81f * float(i) / float(n - 1);
    for (int c = 0; c < 4; ++c) scaled.push_back(twinMesh.skin[i].weights[c] * k);
  }
  const auto dir = std::filesystem::path(TAA_TEST_OUT) / "gltf-weights";
  std::filesystem::create_directories(dir);
  std::ofstream(dir / "weights.bin", std::ios::binary)
      .write(reinterpret_cast<const char*>(scaled.data()), std::streamsize(scaled.size() * 4));
  g["buffers"].push_back({{"uri", "weights.bin"}, {"byteLength", scaled.size() * 4}});
  g["bufferViews"].push_back(
      {{"buffer", g["buffers"].size() - 1}, {"byteLength", scaled.size() * 4}});
  const int weights = g["meshes"][0]["primitives"][0]["attributes"]["WEIGHTS_0"];
  g["accessors"][size_t(weights)]["bufferView"] = g["bufferViews"].size() - 1;
  g["accessors"][size_t(weights)].erase("byteOffset");
  std::ofstream(dir / "scaled.gltf") << g.dump();
  Scene s;
  s.models.push_back(loadGltf(dir / "scaled.gltf", s));

  ASSERT_EQ(s.notes.size(), 1u);
  EXPECT_EQ(s.notes[0], "scaled.gltf: mesh 'skinned_quad' (meshes[0]): " + std::to_string(n - 1) +
                            " vertices have skin weights summing to 0.18 to 0.99, not one: "
                            "normalised, as engines do; 1 vertices have no skin weight and keep "
                            "their bind pose");
  EXPECT_TRUE(twin.notes.empty());  // a well-formed file's weights are left alone
  const double t = 1.5;
  const auto draws = poseModel(s, 0, t), twinDraws = poseModel(twin, 0, t);
  ASSERT_EQ(draws.size(), 1u);
  const std::vector<Vertex> v = deformVertices(s, draws[0]), w = deformVertices(twin, twinDraws[0]);
  ASSERT_EQ(v.size(), w.size());
  for (size_t i = 0; i < v.size(); ++i) {
    SCOPED_TRACE(i);
    if (i == zeroed)
      expectNearGltfDeform(v[i].position, s.vertices[s.meshes[0].firstVertex + i].position);
    else
      expectNearGltfDeform(v[i].position, w[i].position);
  }
  // The pure function: within the tolerance untouched to the bit, a negative sum unweighted.
  // A quantised file's rounding is scaled without a note.
  std::vector<float> bits = {0.25f, 0.25f, 0.25f, 0.2500001f, 0.5f, -0.75f,
                             0.0f,  0.0f,  0.5f,  0.4996f,    0.0f, 0.0f};
  const std::vector<float> before = bits;
  const SkinWeightFixes f = normaliseSkinWeights(bits);
  EXPECT_EQ(f.scaled, 0u);
  EXPECT_EQ(f.unweighted, 1u);
  EXPECT_EQ(std::vector<float>(bits.begin(), bits.begin() + 4),
            std::vector<float>(before.begin(), before.begin() + 4));
  EXPECT_EQ(std::vector<float>(bits.begin() + 4, bits.begin() + 8), std::vector<float>(4, 0.0f));
  EXPECT_NEAR(bits[8] + bits[9], 1.0f, 1e-6f);
}

TEST(GltfDeform, NodeWeightsOverrideTheMeshDefault) {
  const Scene s = loadGltfDeform("node_weights.gltf");
  const auto draws = poseModel(s, 0, 0.0);
  ASSERT_EQ(draws.size(), 2u);
  EXPECT_EQ(draws[0].weights, std::vector<float>{0.75f});
  EXPECT_EQ(draws[1].weights, std::vector<float>{0.25f});
  const Mesh& mesh = s.meshes[0];
  const std::vector<Vertex> a = deformVertices(s, draws[0]), b = deformVertices(s, draws[1]);
  for (size_t i = 0; i < mesh.vertexCount; ++i) {
    const glm::vec3 rest = s.vertices[mesh.firstVertex + i].position;
    expectNearGltfDeform(a[i].position, rest + glm::vec3(0.0f, 0.75f, 0.0f));
    expectNearGltfDeform(b[i].position, rest + glm::vec3(0.0f, 0.25f, 0.0f));
  }
}

TEST(GltfDeform, VertexColoursAreRead) {
  const Scene s = loadGltfDeform("morphed_quad.gltf");
  int red = 0, blue = 0;
  for (const Vertex& v : s.vertices) {
    red += v.color == glm::vec4(1, 0, 0, 1);
    blue += v.color == glm::vec4(0, 0, 1, 1);
  }
  EXPECT_EQ(red, 3);
  EXPECT_EQ(blue, 3);
  EXPECT_TRUE(s.meshes[0].vertexColors);
  // Files without COLOR_0 stay white.
  const Scene plain = loadGltfDeform("skinned_quad.gltf");
  EXPECT_FALSE(plain.meshes[0].vertexColors);
  for (const Vertex& v : plain.vertices) EXPECT_EQ(v.color, glm::vec4(1.0f));
}

// SimpleMorph: default weights [0.5, 0.5] shape the triangle even at rest.
TEST(GltfKhronos, SimpleMorphRestsAtItsDefaultWeights) {
  const Scene s = loadGltfDeform("khronos/SimpleMorph.gltf");
  const Mesh& mesh = s.meshes[0];
  ASSERT_EQ(mesh.targets.size(), 2u);
  EXPECT_EQ(mesh.weights, (std::vector<float>{0.5f, 0.5f}));
  MeshDraw rest = poseModel(s, 0, 0.0)[0];
  // At time 0 the weights animation holds [0, 0]; the default weights apply without it.
  Scene still = s;
  still.models[0].animations.clear();
  rest = poseModel(still, 0, 0.0)[0];
  ASSERT_EQ(rest.weights, (std::vector<float>{0.5f, 0.5f}));
  const std::vector<Vertex> v = deformVertices(still, rest);
  for (size_t i = 0; i < v.size(); ++i)
    expectNearGltfDeform(v[i].position, s.vertices[i].position + 0.5f * mesh.targets[0].position[i] +
                                  0.5f * mesh.targets[1].position[i]);
  // The weights animation (keys (0, 0), (0, 1), (1, 1), (1, 0), (0, 0) at 0..4 s).
  const MeshDraw at1 = poseModel(s, 0, 1.0)[0], at25 = poseModel(s, 0, 2.5)[0];
  EXPECT_NEAR(at1.weights[0], 0.0f, 1e-6f);
  EXPECT_NEAR(at1.weights[1], 1.0f, 1e-6f);
  EXPECT_NEAR(at25.weights[0], 1.0f, 1e-6f);
  EXPECT_NEAR(at25.weights[1], 0.5f, 1e-6f);
}

// SimpleSkin: joint 1 rotates about Z, bending the top of the strip sideways.
TEST(GltfKhronos, SimpleSkinBendsWithItsJointAnimation) {
  const Scene s = loadGltfDeform("khronos/SimpleSkin.gltf");
  ASSERT_EQ(s.models[0].skins.size(), 1u);
  const auto at = [&](double t) { return deformVertices(s, poseModel(s, 0, t)[0]); };
  const std::vector<Vertex> rest = at(0.0), bent = at(1.5);
  float topShift = 0.0f, bottomShift = 0.0f;
  for (size_t i = 0; i < rest.size(); ++i) {
    expectNearGltfDeform(rest[i].position, s.vertices[i].position);  // the first key is the bind pose
    const float dx = std::fabs(bent[i].position.x - rest[i].position.x);
    if (rest[i].position.y >= 1.99f) topShift = std::max(topShift, dx);
    if (rest[i].position.y <= 0.01f) bottomShift = std::max(bottomShift, dx);
  }
  EXPECT_GT(topShift, 0.3f) << "the top of the strip bends";
  EXPECT_EQ(bottomShift, 0.0f) << "the bottom row follows the static joint only";
}

// BoxAnimated: two animations play together; the inner box rises (animation 1) while
// it turns (animation 0).
TEST(GltfKhronos, BoxAnimatedPlaysBothAnimations) {
  Scene s = loadGltfDeform("khronos/BoxAnimated.gltf");
  ASSERT_EQ(s.models[0].animations.size(), 2u);
  auto inner = [&](double t) {
    for (const MeshDraw& d : poseModel(s, 0, t))
      if (s.meshes[size_t(d.mesh)].name == "inner_box") return d.transform;
    return glm::mat4(0.0f);
  };
  EXPECT_GT(inner(2.0)[3].y, 1.0f) << "the translation animation lifts the inner box";
  EXPECT_NE(inner(1.8)[1], inner(1.3)[1]) << "the rotation animation turns it about X";
  s.models[0].playing = {0};  // only the rotation: the box stays down
  EXPECT_NEAR(inner(2.0)[3].y, 0.0f, 1e-5f);
}

// The world's own animation plays by frame index, and the adaptive tracer's triangles
// (rebuilt per frame for moving geometry) are the deformed ones.
TEST(GltfDeform, WorldAnimationPlaysPerFrameAndTheTracerSeesTheDeformedTriangles) {
  const auto spec = test::caseFromJson(
      R"({"scene": {"gltf": "scenes/skinned_quad.gltf", "animation_offset_s": 0.5},
          "script": {"fps": 10}})",
      "deform_trace");
  const Scene scene = buildScene(spec);
  auto corner = [&](int frame) {  // the top right corner (x = y = 0.5) among the moving triangles
    const DrawList draws = buildDrawList(scene, script::frameState(spec, frame));
    EXPECT_EQ(draws.dynamic, std::vector<uint8_t>{1});
    std::vector<Triangle> still, moving;
    collectTriangles(scene, draws, false, still, nullptr, nullptr);
    collectTriangles(scene, draws, true, moving, nullptr, nullptr);
    EXPECT_TRUE(still.empty());
    float top = -1e9f;
    for (const Triangle& t : moving)
      for (const glm::vec3& v : {t.v0, t.v1, t.v2})
        if (v.x > 0.49f) top = std::max(top, v.y);
    return top;
  };
  // Frame n plays 0.5 + n / 10 s; the right edge rises 0.8 units per second from y = 0.5.
  EXPECT_NEAR(corner(0), 0.5f + 0.8f * 0.5f, 1e-5f);
  EXPECT_NEAR(corner(5), 0.5f + 0.8f * 1.0f, 1e-5f);
}

TEST(GltfPick, CaseChoosesAnimationsByNameOrIndexAndRefusesUnknownOnes) {
  auto build = [](const std::string& picks) {
    return buildScene(test::caseFromJson(
        R"({"scene": {"gltf": "scenes/khronos/BoxAnimated.gltf", "animations": )" + picks + "}}",
        "pick"));
  };
  EXPECT_EQ(build(R"(["1"])").models[0].playing, std::vector<int>{1});
  EXPECT_TRUE(build("[]").models[0].playing.empty()) << "empty: all play";
  try {
    build(R"(["walk"])");
    ADD_FAILURE() << "an unknown animation was accepted";
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("scene.animations[0]"), std::string::npos) << m;
    EXPECT_NE(m.find("'walk'"), std::string::npos) << m;
  }
}

// Invariants that need a still scene know that an animated glTF world moves.
TEST(GltfPick, AnAnimatedGltfSceneMovesForTheInvariants) {
  auto moves = [](const std::string& scene) {
    return invariants::whatMoves(test::caseFromJson(R"({"scene": )" + scene + "}", "moves"));
  };
  EXPECT_NE(moves(R"({"gltf": "scenes/khronos/BoxAnimated.gltf"})").find("scene.animation_speed"),
            std::string::npos);
  EXPECT_EQ(moves(R"({"gltf": "scenes/khronos/BoxAnimated.gltf", "animation_speed": 0})"), "");
  EXPECT_EQ(moves(R"({"gltf": "scenes/alpha_modes.gltf"})"), "") << "no animations in the file";
  EXPECT_EQ(moves(R"({"gltf": "scenes/box.glb"})"), "");
}

TEST(GltfExtensions, RequiredButUnsupportedIsRefusedByName) {
  const struct {
    const char* file;
    const char* ext;
    const char* fix;
  } cases[] = {
      {"refused/requires_basisu.gltf", "KHR_texture_basisu", "re-export with PNG or JPEG"},
      {"refused/requires_specgloss.gltf", "KHR_materials_pbrSpecularGlossiness",
       "metallic-roughness"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.file);
    Scene s;
    try {
      loadGltf(assetPath(c.file), s);
      ADD_FAILURE() << "loaded";
    } catch (const SceneError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(assetPath(c.file).string()), std::string::npos) << m;
      EXPECT_NE(m.find(std::string("extensionsRequired lists ") + c.ext), std::string::npos) << m;
      EXPECT_NE(m.find(c.fix), std::string::npos) << m;
    }
  }
}

TEST(GltfExtensions, UsedButUnsupportedIsNotedOncePerFile) {
  Scene s;
  loadGltf(assetPath("uses_unsupported.gltf"), s);
  loadGltf(assetPath("uses_unsupported.gltf"), s);  // the same file as a second model
  loadGltf(assetPath("textured_box.gltf"), s);
  ASSERT_EQ(s.notes.size(), 1u);
  EXPECT_NE(s.notes[0].find("KHR_lights_punctual, KHR_materials_clearcoat"), std::string::npos)
      << s.notes[0];
  EXPECT_EQ(s.notes[0].find("KHR_mesh_quantization"), std::string::npos)
      << "a supported extension is not reported";
}

// KHR_mesh_quantization: integer attributes, normalised or not, at 4-byte strides.
TEST(GltfExtensions, QuantizedAttributesLoad) {
  const Scene s = loadGltfDeform("quantized_quad.gltf");
  ASSERT_EQ(s.vertices.size(), 4u);
  EXPECT_EQ(s.vertices[0].position, glm::vec3(-500.0f, -500.0f, 0.0f));
  EXPECT_EQ(s.vertices[2].position, glm::vec3(500.0f, 500.0f, 0.0f));
  for (const Vertex& v : s.vertices) EXPECT_EQ(v.normal, glm::vec3(0.0f, 0.0f, 1.0f));
  EXPECT_EQ(s.vertices[0].uv, glm::vec2(0.0f, 1.0f));
  EXPECT_EQ(s.vertices[2].uv, glm::vec2(1.0f, 0.0f));
  const glm::mat4 m = poseModel(s, 0, 0.0)[0].transform;  // the node's 0.001 scale
  expectNearGltfDeform(glm::vec3(m * glm::vec4(s.vertices[2].position, 1.0f)), glm::vec3(0.5f, 0.5f, 0.0f));
  EXPECT_TRUE(s.notes.empty());
}

// The extension's own example: uv (u, v) samples (0.5 v, 1 - 0.5 u), the lower left
// quadrant of the image turned a quarter.
TEST(GltfExtensions, TextureTransformIsBakedIntoTheUvs) {
  const Scene s = loadGltfDeform("texture_transform.gltf");
  ASSERT_EQ(s.vertices.size(), 4u);
  const glm::vec2 authored[4] = {{0, 1}, {1, 1}, {1, 0}, {0, 0}};  // make_assets.quad_geometry
  for (size_t i = 0; i < 4; ++i) {
    const glm::vec2 want(0.5f * authored[i].y, 1.0f - 0.5f * authored[i].x);
    EXPECT_NEAR(s.vertices[i].uv.x, want.x, 1e-6f) << i;
    EXPECT_NEAR(s.vertices[i].uv.y, want.y, 1e-6f) << i;
  }
  EXPECT_TRUE(s.notes.empty()) << "KHR_texture_transform is supported, not reported";
}

}  // namespace
}  // namespace taa::scene
