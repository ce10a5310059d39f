// EXT_meshopt_compression: files written here with libmeshoptimizer's own encoder load
// to the same geometry as the uncompressed data, as .gltf and .glb, and a truncated stream
// is refused naming the buffer view.
#include <gtest/gtest.h>
#include <meshoptimizer.h>

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "scene/gltf_loader.h"
#include "scene/scene_error.h"
#include "scene_test_util.h"

namespace taa::scene {
namespace {

namespace fs = std::filesystem;

// A 6x6 grid of vertices (positions and normals) and its triangles.
struct Grid {
  std::vector<float> positions, normals;
  std::vector<uint16_t> indices;
  Grid() {
    for (int y = 0; y < 6; ++y)
      for (int x = 0; x < 6; ++x) {
        positions.insert(positions.end(), {x * 0.2f, y * 0.2f, 0.05f * float((x * y) % 3)});
        normals.insert(normals.end(), {0.0f, 0.0f, 1.0f});
      }
    for (uint16_t y = 0; y < 5; ++y)
      for (uint16_t x = 0; x < 5; ++x) {
        const uint16_t a = uint16_t(y * 6 + x);
        indices.insert(indices.end(),
                       {a, uint16_t(a + 1), uint16_t(a + 7), a, uint16_t(a + 7), uint16_t(a + 6)});
      }
  }
};

// Writes the grid with every view meshopt-compressed into buffer 0 and a uri-less
// fallback buffer 1; `glb` puts buffer 0 in the BIN chunk. `damage` truncates a stream.
fs::path writeCompressed(const std::string& name, bool glb, bool damage) {
  const Grid g;
  std::vector<uint8_t> packed;
  nlohmann::json views = nlohmann::json::array();
  size_t fallback = 0;
  auto add = [&](const void* data, size_t count, size_t stride, const char* mode) {
    std::vector<uint8_t> enc;
    if (std::strcmp(mode, "TRIANGLES") == 0) {
      const std::vector<unsigned> idx(g.indices.begin(), g.indices.end());
      enc.resize(meshopt_encodeIndexBufferBound(count, 36));
      enc.resize(meshopt_encodeIndexBuffer(enc.data(), enc.size(), idx.data(), count));
    } else {
      enc.resize(meshopt_encodeVertexBufferBound(count, stride));
      enc.resize(meshopt_encodeVertexBuffer(enc.data(), enc.size(), data, count, stride));
    }
    while (packed.size() % 4) packed.push_back(0);
    nlohmann::json v = {{"buffer", 1}, {"byteOffset", fallback}, {"byteLength", count * stride}};
    if (std::strcmp(mode, "ATTRIBUTES") == 0) v["byteStride"] = stride;
    v["extensions"]["EXT_meshopt_compression"] = {{"buffer", 0},
                                                  {"byteOffset", packed.size()},
                                                  {"byteLength", enc.size()},
                                                  {"byteStride", stride},
                                                  {"count", count},
                                                  {"mode", mode}};
    packed.insert(packed.end(), enc.begin(), enc.end());
    fallback += (count * stride + 3) / 4 * 4;
    views.push_back(v);
  };
  add(g.positions.data(), 36, 12, "ATTRIBUTES");
  add(g.normals.data(), 36, 12, "ATTRIBUTES");
  add(nullptr, g.indices.size(), 2, "TRIANGLES");
  // A truncated stream: the positions' compressed data is cut in half.
  if (damage)
    views[0]["extensions"]["EXT_meshopt_compression"]["byteLength"] =
        views[0]["extensions"]["EXT_meshopt_compression"]["byteLength"].get<size_t>() / 2;
  nlohmann::json doc = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"EXT_meshopt_compression"}},
      {"extensionsRequired", {"EXT_meshopt_compression"}},
      {"scenes", {{{"nodes", {0}}}}},
      {"nodes", {{{"mesh", 0}}}},
      {"meshes",
       {{{"primitives", {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}}}}}}},
      {"bufferViews", views},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 36}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5126}, {"count", 36}, {"type", "VEC3"}},
        {{"bufferView", 2},
         {"componentType", 5123},
         {"count", g.indices.size()},
         {"type", "SCALAR"}}}},
      {"buffers",
       {{{"byteLength", packed.size()}},
        {{"byteLength", fallback},
         {"extensions", {{"EXT_meshopt_compression", {{"fallback", true}}}}}}}}};
  const fs::path dir = fs::path(TAA_TEST_OUT) / "gltf_meshopt";
  fs::create_directories(dir);
  const fs::path file = dir / name;
  std::ofstream out(file, std::ios::binary);
  if (!glb) {
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + testing::base64(packed);
    out << doc.dump();
    return file;
  }
  std::string json = doc.dump();
  while (json.size() % 4) json += ' ';
  while (packed.size() % 4) packed.push_back(0);
  auto u32 = [&](uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); };
  out.write("glTF", 4);
  u32(2);
  u32(uint32_t(12 + 8 + json.size() + 8 + packed.size()));
  u32(uint32_t(json.size()));
  u32(0x4E4F534Au);
  out.write(json.data(), std::streamsize(json.size()));
  u32(uint32_t(packed.size()));
  u32(0x004E4942u);
  out.write(reinterpret_cast<const char*>(packed.data()), std::streamsize(packed.size()));
  return file;
}

TEST(GltfMeshopt, CompressedGltfAndGlbLoadTheEncodedGeometry) {
  const Grid g;
  for (const bool glb : {false, true}) {
    SCOPED_TRACE(glb ? "glb" : "gltf");
    Scene s;
    loadGltf(writeCompressed(glb ? "grid.glb" : "grid.gltf", glb, false), s);
    ASSERT_EQ(s.vertices.size(), 36u);
    for (size_t i = 0; i < 36; ++i) {
      EXPECT_EQ(s.vertices[i].position,
                glm::vec3(g.positions[3 * i], g.positions[3 * i + 1], g.positions[3 * i + 2]))
          << i;
      EXPECT_EQ(s.vertices[i].normal, glm::vec3(0.0f, 0.0f, 1.0f)) << i;
    }
    ASSERT_EQ(s.indices.size(), g.indices.size());
    // The index codec may rotate a triangle's corners (keeping its winding).
    for (size_t t = 0; t < g.indices.size(); t += 3) {
      bool same = false;
      for (size_t r = 0; r < 3; ++r)
        same = same || (s.indices[t] == g.indices[t + r] &&
                        s.indices[t + 1] == g.indices[t + (r + 1) % 3] &&
                        s.indices[t + 2] == g.indices[t + (r + 2) % 3]);
      EXPECT_TRUE(same) << "triangle " << t / 3;
    }
    EXPECT_TRUE(s.notes.empty()) << "EXT_meshopt_compression is supported";
  }
}

TEST(GltfMeshopt, ADamagedStreamIsRefusedNamingTheView) {
  Scene s;
  const fs::path file = writeCompressed("damaged.gltf", false, true);
  try {
    loadGltf(file, s);
    ADD_FAILURE() << "a damaged stream loaded";
  } catch (const SceneError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find(file.string()), std::string::npos) << m;
    EXPECT_NE(m.find("bufferViews["), std::string::npos) << m;
    EXPECT_NE(m.find("does not decode"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace taa::scene
