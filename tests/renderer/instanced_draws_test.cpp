// Instanced draws (issue 25): sibling nodes sharing a mesh are one draw with an instance
// each, not one draw per node (which cost lavapipe memory and time per node). The draws
// join only where they are consecutive, so a scene renders exactly, byte for byte, what the
// same scene gives drawn one draw per node (each node its own copy of the mesh, which no
// draw can share).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "case/case_loader.h"
#include "frame/draw_list.h"
#include "passes/adaptive/trace_geometry.h"
#include "scene/build_scene.h"
#include "script/frame_state.h"
#include "support/gpu.h"

namespace taa {
namespace {

namespace fs = std::filesystem;

constexpr int kNodes = 24;
constexpr int kMirrored = 9;   // scale x -1: its front faces wind the other way
constexpr int kTwinOf = 5;     // node kTwin sits exactly where node kTwinOf does
constexpr int kTwin = 6;

// A unit box (the buffer below) on N sibling nodes: node kMirrored is mirrored, node kTwin
// coincides with node kTwinOf (equal depths: which one shows is the raster order's), the
// rest on a ring. `ownMeshes`: each node its own mesh (same accessors and material).
std::string siblingsGltf(bool ownMeshes) {
  std::string nodes, meshes;
  for (int i = 0; i < kNodes; ++i) {
    const int k = i == kTwin ? kTwinOf : i;
    const double a = k * 6.283185307179586 / kNodes;
    char node[256];
    std::snprintf(node, sizeof(node), R"(%s{"mesh": %d, "translation": [%.4f, 0.5, %.4f]%s})",
                  i ? "," : "", ownMeshes ? i : 0, 2.0 * std::cos(a), 2.0 * std::sin(a),
                  i == kMirrored ? R"(, "scale": [-1, 1, 1])" : "");
    nodes += node;
    if (i == 0 || ownMeshes)
      meshes += std::string(i ? "," : "") +
                R"({"primitives": [{"attributes": {"POSITION": 0, "NORMAL": 1}, "indices": 2, "material": 0}]})";
  }
  // 24 vertices (4 per face), 36 indices, little-endian, base64.
  std::vector<uint8_t> bytes;
  auto put = [&bytes](const void* p, size_t n) {
    bytes.insert(bytes.end(), static_cast<const uint8_t*>(p), static_cast<const uint8_t*>(p) + n);
  };
  std::vector<float> positions, normals;
  std::vector<uint16_t> indices;
  for (int axis = 0; axis < 3; ++axis)
    for (float sign : {-1.0f, 1.0f}) {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      const auto base = uint16_t(positions.size() / 3);
      const float corners[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
      for (const auto& c : corners) {
        float p[3], n[3] = {0, 0, 0};
        p[axis] = 0.3f * sign;
        p[u] = 0.3f * c[0];
        p[v] = 0.3f * c[1];
        n[axis] = sign;
        positions.insert(positions.end(), p, p + 3);
        normals.insert(normals.end(), n, n + 3);
      }
      const int quad[2][6] = {{0, 2, 1, 0, 3, 2}, {0, 1, 2, 0, 2, 3}};
      for (int q : quad[sign > 0 ? 1 : 0]) indices.push_back(uint16_t(base + q));
    }
  put(positions.data(), positions.size() * 4);
  put(normals.data(), normals.size() * 4);
  put(indices.data(), indices.size() * 2);
  static const char* b64 = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string data;
  for (size_t i = 0; i < bytes.size(); i += 3) {
    const uint32_t n = uint32_t(bytes[i]) << 16 |
                       (i + 1 < bytes.size() ? uint32_t(bytes[i + 1]) << 8 : 0u) |
                       (i + 2 < bytes.size() ? uint32_t(bytes[i + 2]) : 0u);
    for (size_t k = 0; k < 4; ++k)
      data += i + k <= bytes.size() ? b64[(n >> (18 - 6 * k)) & 63u] : '=';
  }
  return R"({"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [)" + [] {
    std::string s;
    for (int i = 0; i < kNodes; ++i) s += (i ? "," : "") + std::to_string(i);
    return s;
  }() + R"(]}], "nodes": [)" + nodes + R"(], "meshes": [)" + meshes +
         R"(], "materials": [{"pbrMetallicRoughness": {"baseColorFactor": [0.8, 0.5, 0.3, 1]}, "doubleSided": false}],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 24, "type": "VEC3", "min": [-0.3, -0.3, -0.3], "max": [0.3, 0.3, 0.3]},
    {"bufferView": 1, "componentType": 5126, "count": 24, "type": "VEC3"},
    {"bufferView": 2, "componentType": 5123, "count": 36, "type": "SCALAR"}],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 288},
                  {"buffer": 0, "byteOffset": 288, "byteLength": 288},
                  {"buffer": 0, "byteOffset": 576, "byteLength": 72}],
  "buffers": [{"byteLength": )" +
         std::to_string(bytes.size()) + R"(, "uri": "data:application/octet-stream;base64,)" + data +
         R"("}]})";
}

// The case over one of the two files, with shadows (the shadow pass draws the same list).
spec::CaseSpec siblingsCase(bool ownMeshes, const std::string& extra = "") {
  const fs::path dir = fs::path(TAA_TEST_OUT) / "instanced_draws";
  fs::create_directories(dir);
  const std::string name = ownMeshes ? "own_meshes" : "shared_mesh";
  std::ofstream(dir / (name + ".gltf")) << siblingsGltf(ownMeshes);
  const std::string json = R"({"scene": {"gltf": ")" + name + R"(.gltf"},
    "camera": {"position": [0.5, 2.5, 4.5], "target": [0, 0.3, 0], "strafe": {"speed": 0.8, "distance": 0.5}},
    "lighting": {"shadows": true}, "script": {"frames": 4},
    "output": {"frames": [3], "aux": ["depth", "velocity", "material_id"]})" + extra + "}";
  return cases::parseCase(json, dir / (name + ".json")).spec;
}

TEST(InstancedDraws, SiblingsSharingAMeshAreOneDrawPerRunOfInstances) {
  const auto spec = siblingsCase(false);
  const scene::Scene scene = scene::buildScene(spec);
  const DrawList draws = buildDrawList(scene, script::frameState(spec, 0));
  ASSERT_EQ(draws.instances.size(), size_t(kNodes));
  // The mirrored node winds the other way: its own draw, between two runs.
  ASSERT_EQ(draws.opaque.size(), 3u);
  EXPECT_EQ(draws.opaque[0].instance, 0u);
  EXPECT_EQ(draws.opaque[0].instanceCount, uint32_t(kMirrored));
  EXPECT_FALSE(draws.opaque[0].mirrored);
  EXPECT_EQ(draws.opaque[1].instance, uint32_t(kMirrored));
  EXPECT_EQ(draws.opaque[1].instanceCount, 1u);
  EXPECT_TRUE(draws.opaque[1].mirrored);
  EXPECT_EQ(draws.opaque[2].instance, uint32_t(kMirrored + 1));
  EXPECT_EQ(draws.opaque[2].instanceCount, uint32_t(kNodes - kMirrored - 1));

  // One instance each, in order: what the tracer and the reference key read.
  const std::vector<Draw> single = singleInstanceDraws(draws.opaque);
  ASSERT_EQ(single.size(), size_t(kNodes));
  for (int i = 0; i < kNodes; ++i) {
    EXPECT_EQ(single[size_t(i)].instance, uint32_t(i));
    EXPECT_EQ(single[size_t(i)].instanceCount, 1u);
    EXPECT_EQ(single[size_t(i)].mirrored, i == kMirrored);
  }

  // Each node its own mesh: nothing can join.
  const auto own = siblingsCase(true);
  const scene::Scene ownScene = scene::buildScene(own);
  const DrawList ownDraws = buildDrawList(ownScene, script::frameState(own, 0));
  EXPECT_EQ(ownDraws.opaque.size(), size_t(kNodes));
  // The tracer's triangles are the same either way, in the same order.
  std::vector<scene::Triangle> a, b;
  collectTriangles(scene, draws, false, a, nullptr, nullptr);
  collectTriangles(ownScene, ownDraws, false, b, nullptr, nullptr);
  ASSERT_EQ(a.size(), size_t(kNodes) * 12);
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(std::memcmp(a.data(), b.data(), a.size() * sizeof(scene::Triangle)), 0);
}

// Compares every image of two renders bit for bit.
void expectSameImages(const FrameRecord& a, const FrameRecord& b, const std::string& what) {
  EXPECT_EQ(a.colorSha256, b.colorSha256) << what;
  ASSERT_EQ(a.aux.size(), b.aux.size()) << what;
  for (size_t i = 0; i < a.aux.size(); ++i) {
    const Image& x = a.aux[i].image;
    const Image& y = b.aux[i].image;
    EXPECT_TRUE(sameBits(x, y)) << what << " " << a.aux[i].name << " differs";
  }
}

TEST(InstancedDraws, RenderByteForByteWhatOneDrawPerNodeRenders) {
  for (const char* extra : {"", R"(, "render": {"path": "deferred"})"}) {
    const auto shared = test::renderCase(siblingsCase(false, extra));
    const auto own = test::renderCase(siblingsCase(true, extra));
    ASSERT_EQ(shared.size(), own.size());
    const FrameRecord& a = shared.back();
    const FrameRecord& b = own.back();
    ASSERT_TRUE(a.hasImages && b.hasImages);
    expectSameImages(a, b, *extra ? "deferred" : "forward");
    // The boxes are in view (else any two renders would agree): most of the ids are boxes.
    const Image& ids = test::auxImage(a, "material_id");
    int boxes = 0;
    for (int y = 0; y < ids.height; ++y)
      for (int x = 0; x < ids.width; ++x) boxes += ids.at(x, y, 1) == 0.0f ? 1 : 0;
    EXPECT_GT(boxes, ids.width * ids.height / 50);
  }
}

}  // namespace
}  // namespace taa
