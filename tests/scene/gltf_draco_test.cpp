// KHR_draco_mesh_compression: a grid written here with libdraco's own encoder (every
// attribute the loader reads, quantised) loads, as .gltf and .glb, to the source data
// within the quantisation error with its triangles and winding intact; a truncated stream
// and a stream whose vertex count disagrees with its accessors are refused by name.
#include <draco/compression/encode.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <glm/geometric.hpp>
#include <map>
#include <nlohmann/json.hpp>

#include "scene/gltf_loader.h"
#include "scene/scene_error.h"
#include "scene_test_util.h"

namespace taa::scene {
namespace {

namespace fs = std::filesystem;

// A bumpy 6x6 grid with every attribute the loader reads, all different per vertex.
struct DracoGrid {
  static constexpr int kSide = 6, kVertices = kSide * kSide;
  std::vector<float> positions, normals, uvs, colors, weights;
  std::vector<uint16_t> joints;
  std::vector<uint32_t> indices;
  DracoGrid() {
    for (int y = 0; y < kSide; ++y)
      for (int x = 0; x < kSide; ++x) {
        positions.insert(positions.end(), {x * 0.2f, y * 0.2f, 0.05f * float((x * y) % 3)});
        const glm::vec3 n = glm::normalize(glm::vec3(0.1f * float(x - 2), 0.1f * float(y - 3), 1));
        normals.insert(normals.end(), {n.x, n.y, n.z});
        uvs.insert(uvs.end(), {float(x) / 5.0f, 1.0f - float(y) / 5.0f});
        colors.insert(colors.end(), {float(x) / 5.0f, float(y) / 5.0f, 0.5f, 1.0f});
        const float w = float(x + y) / 10.0f;
        weights.insert(weights.end(), {w, 1.0f - w, 0.0f, 0.0f});
        joints.insert(joints.end(), {uint16_t(y % 2), uint16_t(1 - y % 2), 0, 0});
      }
    for (uint32_t y = 0; y + 1 < kSide; ++y)
      for (uint32_t x = 0; x + 1 < kSide; ++x) {
        const uint32_t a = y * kSide + x;
        indices.insert(indices.end(), {a, a + 1, a + kSide + 1, a, a + kSide + 1, a + kSide});
      }
  }
  glm::vec3 position(size_t i) const {
    return {positions[3 * i], positions[3 * i + 1], positions[3 * i + 2]};
  }
};

struct DracoEncoded {
  std::vector<uint8_t> bytes;
  std::map<std::string, int> ids;  // glTF attribute name -> Draco unique id
};

DracoEncoded encodeDracoGrid(const DracoGrid& g) {
  draco::Mesh mesh;
  mesh.set_num_points(DracoGrid::kVertices);
  DracoEncoded out;
  auto add = [&](const char* name, draco::GeometryAttribute::Type type, int comps,
                 draco::DataType dt, size_t bytes, const void* data) {
    draco::GeometryAttribute ga;
    ga.Init(type, nullptr, int8_t(comps), dt, false, int64_t(bytes) * comps, 0);
    const int id = mesh.AddAttribute(ga, true, DracoGrid::kVertices);
    for (int i = 0; i < DracoGrid::kVertices; ++i)
      mesh.attribute(id)->SetAttributeValue(
          draco::AttributeValueIndex(i),
          static_cast<const uint8_t*>(data) + size_t(i) * bytes * size_t(comps));
    out.ids[name] = int(mesh.attribute(id)->unique_id());
  };
  add("POSITION", draco::GeometryAttribute::POSITION, 3, draco::DT_FLOAT32, 4, g.positions.data());
  add("NORMAL", draco::GeometryAttribute::NORMAL, 3, draco::DT_FLOAT32, 4, g.normals.data());
  add("TEXCOORD_0", draco::GeometryAttribute::TEX_COORD, 2, draco::DT_FLOAT32, 4, g.uvs.data());
  add("COLOR_0", draco::GeometryAttribute::COLOR, 4, draco::DT_FLOAT32, 4, g.colors.data());
  add("JOINTS_0", draco::GeometryAttribute::GENERIC, 4, draco::DT_UINT16, 2, g.joints.data());
  add("WEIGHTS_0", draco::GeometryAttribute::GENERIC, 4, draco::DT_FLOAT32, 4, g.weights.data());
  for (size_t t = 0; t < g.indices.size(); t += 3)
    mesh.AddFace({draco::PointIndex(g.indices[t]), draco::PointIndex(g.indices[t + 1]),
                  draco::PointIndex(g.indices[t + 2])});
  draco::Encoder encoder;
  encoder.SetAttributeQuantization(draco::GeometryAttribute::POSITION, 14);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::NORMAL, 10);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::TEX_COORD, 12);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::COLOR, 10);
  encoder.SetAttributeQuantization(draco::GeometryAttribute::GENERIC, 12);
  draco::EncoderBuffer buffer;
  const draco::Status status = encoder.EncodeMeshToBuffer(mesh, &buffer);
  EXPECT_TRUE(status.ok()) << status.error_msg_string();
  out.bytes.assign(buffer.data(), buffer.data() + buffer.size());
  return out;
}

// The grid, Draco-compressed, skinned to two joints. The accessors have no bufferView,
// as Draco exporters write them. `damage`: "truncate" halves the stream, "count" makes
// the position accessor's count disagree with the stream.
fs::path writeDracoGrid(const std::string& name, bool glb, const std::string& damage = "") {
  const DracoGrid g;
  DracoEncoded enc = encodeDracoGrid(g);
  const size_t length = damage == "truncate" ? enc.bytes.size() / 2 : enc.bytes.size();
  nlohmann::json attributes, accessors = nlohmann::json::array();
  const std::pair<const char*, std::pair<int, const char*>> kinds[] = {
      {"POSITION", {5126, "VEC3"}}, {"NORMAL", {5126, "VEC3"}},   {"TEXCOORD_0", {5126, "VEC2"}},
      {"COLOR_0", {5126, "VEC4"}},  {"JOINTS_0", {5123, "VEC4"}}, {"WEIGHTS_0", {5126, "VEC4"}}};
  for (const auto& [attr, kind] : kinds) {
    attributes[attr] = accessors.size();
    accessors.push_back(
        {{"componentType", kind.first}, {"count", DracoGrid::kVertices}, {"type", kind.second}});
  }
  if (damage == "count") accessors[0]["count"] = DracoGrid::kVertices + 1;
  accessors.push_back({{"componentType", 5123}, {"count", g.indices.size()}, {"type", "SCALAR"}});
  nlohmann::json ids;
  for (const auto& [attr, id] : enc.ids) ids[attr] = id;
  nlohmann::json doc = {
      {"asset", {{"version", "2.0"}}},
      {"extensionsUsed", {"KHR_draco_mesh_compression"}},
      {"extensionsRequired", {"KHR_draco_mesh_compression"}},
      {"scenes", {{{"nodes", {0, 1, 2}}}}},
      {"nodes",
       {{{"mesh", 0}, {"skin", 0}}, {{"name", "root"}}, {{"translation", {0.0, 1.0, 0.0}}}}},
      {"skins", {{{"joints", {1, 2}}}}},
      {"meshes",
       {{{"primitives",
          {{{"attributes", attributes},
            {"indices", accessors.size() - 1},
            {"extensions",
             {{"KHR_draco_mesh_compression", {{"bufferView", 0}, {"attributes", ids}}}}}}}}}}},
      {"bufferViews", {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", length}}}},
      {"accessors", accessors},
      {"buffers", {{{"byteLength", enc.bytes.size()}}}}};
  const fs::path dir = fs::path(TAA_TEST_OUT) / "gltf_draco";
  fs::create_directories(dir);
  const fs::path file = dir / name;
  std::ofstream out(file, std::ios::binary);
  if (!glb) {
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + testing::base64(enc.bytes);
    out << doc.dump();
    return file;
  }
  std::string json = doc.dump();
  while (json.size() % 4) json += ' ';
  while (enc.bytes.size() % 4) enc.bytes.push_back(0);
  auto u32 = [&](uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); };
  out.write("glTF", 4);
  u32(2);
  u32(uint32_t(12 + 8 + json.size() + 8 + enc.bytes.size()));
  u32(uint32_t(json.size()));
  u32(0x4E4F534Au);
  out.write(json.data(), std::streamsize(json.size()));
  u32(uint32_t(enc.bytes.size()));
  u32(0x004E4942u);
  out.write(reinterpret_cast<const char*>(enc.bytes.data()), std::streamsize(enc.bytes.size()));
  return file;
}

TEST(GltfDraco, CompressedGltfAndGlbLoadTheSourceWithinQuantisation) {
  const DracoGrid g;
  for (const bool glb : {false, true}) {
    SCOPED_TRACE(glb ? "glb" : "gltf");
    Scene s;
    loadGltf(writeDracoGrid(glb ? "grid.glb" : "grid.gltf", glb), s);
    EXPECT_TRUE(s.notes.empty()) << "KHR_draco_mesh_compression is supported";
    ASSERT_EQ(s.vertices.size(), size_t(DracoGrid::kVertices));
    ASSERT_EQ(s.meshes.size(), 1u);
    ASSERT_EQ(s.meshes[0].skin.size(), size_t(DracoGrid::kVertices));
    // Draco reorders vertices: match each loaded vertex to its source by position (the
    // grid spacing, 0.2, is far above the 14-bit quantisation step, 1.2e-4 over 1.0).
    std::vector<int> source(s.vertices.size(), -1);
    std::vector<int> seen(size_t(DracoGrid::kVertices), 0);
    for (size_t i = 0; i < s.vertices.size(); ++i) {
      const Vertex& v = s.vertices[i];
      for (size_t k = 0; k < size_t(DracoGrid::kVertices); ++k)
        if (glm::length(v.position - g.position(k)) < 1e-3f) source[i] = int(k);
      ASSERT_GE(source[i], 0) << "vertex " << i << " matches no source vertex";
      const size_t k = size_t(source[i]);
      ++seen[k];
      EXPECT_LT(glm::length(v.normal - glm::vec3(g.normals[3 * k], g.normals[3 * k + 1],
                                                 g.normals[3 * k + 2])),
                5e-3f)
          << i;  // 10-bit octahedral normals
      EXPECT_LT(glm::length(v.uv - glm::vec2(g.uvs[2 * k], g.uvs[2 * k + 1])), 1e-3f) << i;
      EXPECT_LT(glm::length(v.color - glm::vec4(g.colors[4 * k], g.colors[4 * k + 1],
                                                g.colors[4 * k + 2], g.colors[4 * k + 3])),
                2e-3f)
          << i;
      const SkinWeights& w = s.meshes[0].skin[i];
      EXPECT_EQ(w.joints, glm::uvec4(g.joints[4 * k], g.joints[4 * k + 1], g.joints[4 * k + 2],
                                     g.joints[4 * k + 3]))
          << i;
      // Weights within their 12-bit quantisation.
      EXPECT_LT(glm::length(w.weights - glm::vec4(g.weights[4 * k], g.weights[4 * k + 1],
                                                  g.weights[4 * k + 2], g.weights[4 * k + 3])),
                1e-3f)
          << i;
    }
    for (int k = 0; k < DracoGrid::kVertices; ++k) EXPECT_EQ(seen[size_t(k)], 1) << k;
    // Every source triangle comes back once, with its winding (a rotation of its corners).
    ASSERT_EQ(s.indices.size(), g.indices.size());
    std::vector<int> found(g.indices.size() / 3, 0);
    for (size_t t = 0; t < s.indices.size(); t += 3) {
      const uint32_t a = uint32_t(source[s.indices[t]]), b = uint32_t(source[s.indices[t + 1]]),
                     c = uint32_t(source[s.indices[t + 2]]);
      for (size_t u = 0; u < g.indices.size(); u += 3)
        for (size_t r = 0; r < 3; ++r)
          if (g.indices[u + r] == a && g.indices[u + (r + 1) % 3] == b &&
              g.indices[u + (r + 2) % 3] == c)
            ++found[u / 3];
    }
    for (size_t t = 0; t < found.size(); ++t) EXPECT_EQ(found[t], 1) << "triangle " << t;
  }
}

// A file written by someone else: Draco's own test data has the Khronos Box twice, plain
// and compressed (cases/scenes/khronos/PROVENANCE.md). Both load to the same triangles.
TEST(GltfDraco, KhronosBoxMatchesItsUncompressedTwin) {
  Scene plain, packed;
  loadGltf(testing::assetPath("khronos/Box.glb"), plain);
  loadGltf(testing::assetPath("khronos/Box_Draco.glb"), packed);
  ASSERT_EQ(plain.vertices.size(), 24u);
  ASSERT_EQ(packed.vertices.size(), plain.vertices.size());
  ASSERT_EQ(packed.indices.size(), 36u);
  // Each compressed triangle equals one plain triangle corner for corner (a rotation),
  // positions within the quantisation error and flat normals equal.
  auto corner = [](const Scene& s, size_t i) { return s.vertices[s.indices[i]]; };
  auto near = [](const Vertex& a, const Vertex& b) {
    return glm::length(a.position - b.position) < 1e-3f && glm::length(a.normal - b.normal) < 1e-2f;
  };
  std::vector<int> found(12, 0);
  for (size_t t = 0; t < 36; t += 3)
    for (size_t u = 0; u < 36; u += 3)
      for (size_t r = 0; r < 3; ++r)
        if (near(corner(packed, t), corner(plain, u + r)) &&
            near(corner(packed, t + 1), corner(plain, u + (r + 1) % 3)) &&
            near(corner(packed, t + 2), corner(plain, u + (r + 2) % 3)))
          ++found[u / 3];
  for (size_t t = 0; t < found.size(); ++t) EXPECT_EQ(found[t], 1) << "triangle " << t;
}

std::string dracoRefusal(const fs::path& file) {
  Scene s;
  try {
    loadGltf(file, s);
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

TEST(GltfDraco, ATruncatedStreamIsRefusedNamingTheFileAndExtension) {
  for (const bool glb : {false, true}) {
    const fs::path file = writeDracoGrid(glb ? "truncated.glb" : "truncated.gltf", glb, "truncate");
    const std::string m = dracoRefusal(file);
    ASSERT_FALSE(m.empty()) << "a truncated Draco stream loaded";
    EXPECT_NE(m.find(file.string()), std::string::npos) << m;
    EXPECT_NE(m.find("meshes[0].primitives[0].extensions.KHR_draco_mesh_compression"),
              std::string::npos)
        << m;
    EXPECT_NE(m.find("does not decode"), std::string::npos) << m;
  }
}

TEST(GltfDraco, AVertexCountThatDisagreesWithTheStreamIsRefused) {
  const fs::path file = writeDracoGrid("count.gltf", false, "count");
  const std::string m = dracoRefusal(file);
  EXPECT_NE(m.find("KHR_draco_mesh_compression.attributes.POSITION"), std::string::npos) << m;
  EXPECT_NE(m.find("36 vertices"), std::string::npos) << m;
  EXPECT_NE(m.find("declares 37"), std::string::npos) << m;
}

}  // namespace
}  // namespace taa::scene
