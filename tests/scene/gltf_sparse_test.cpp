// Sparse accessors (glTF 2.0, 3.6.2.3): substitutions over a buffer view, over zeros when
// there is none, in morph targets, with unsigned byte, short and int indices; and the
// refusals of a corrupt substitution list. Before issue 25 every sparse accessor was refused.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstring>
#include <fstream>

#include "scene/gltf_loader.h"
#include "scene/scene_error.h"
#include "scene_test_util.h"

namespace taa::scene {
namespace {

namespace fs = std::filesystem;

std::vector<glm::vec3> meshPositions(const Scene& s, int mesh) {
  const Mesh& m = s.meshes[size_t(mesh)];
  std::vector<glm::vec3> out;
  for (uint32_t v = 0; v < m.vertexCount; ++v) out.push_back(s.vertices[m.firstVertex + v].position);
  return out;
}

bool contains(const std::vector<glm::vec3>& ps, const glm::vec3& p) {
  return std::any_of(ps.begin(), ps.end(), [&](const glm::vec3& q) { return q == p; });
}

TEST(GltfSparse, SubstitutionsOverAViewOverZerosAndInAMorphTarget) {
  Scene s;
  s.models.push_back(loadGltf(testing::assetPath("sparse.gltf"), s));
  ASSERT_EQ(s.meshes.size(), 3u);
  // The grid: nine flat vertices, the centre raised to 0.35 and the corner (0.5, 0.5) to 0.2
  // (uint8 indices); every other vertex stays at z 0.
  const auto grid = meshPositions(s, 0);
  EXPECT_TRUE(contains(grid, {0.0f, 0.0f, 0.35f}));
  EXPECT_TRUE(contains(grid, {0.5f, 0.5f, 0.2f}));
  EXPECT_FALSE(contains(grid, {0.0f, 0.0f, 0.0f})) << "the centre's flat value is replaced";
  for (const glm::vec3& p : grid) {
    if (!(p.x == 0.0f && p.y == 0.0f) && !(p.x == 0.5f && p.y == 0.5f)) {
      EXPECT_EQ(p.z, 0.0f);
    }
  }
  // The triangle: no buffer view, all three values sparse (uint16 indices).
  const auto tri = meshPositions(s, 1);
  ASSERT_EQ(tri.size(), 3u);
  EXPECT_EQ(tri[0], glm::vec3(-0.4f, -0.4f, 0.0f));
  EXPECT_EQ(tri[1], glm::vec3(0.4f, -0.4f, 0.0f));
  EXPECT_EQ(tri[2], glm::vec3(0.0f, 0.4f, 0.0f));
  // The morph target: zeros but for vertices 2 and 3 (uint32 indices), which rise 0.4.
  const Mesh& quad = s.meshes[2];
  ASSERT_EQ(quad.targets.size(), 1u);
  const std::vector<glm::vec3>& d = quad.targets[0].position;
  ASSERT_EQ(d.size(), 4u);
  EXPECT_EQ(d[0], glm::vec3(0.0f));
  EXPECT_EQ(d[1], glm::vec3(0.0f));
  EXPECT_EQ(d[2], glm::vec3(0.0f, 0.4f, 0.0f));
  EXPECT_EQ(d[3], glm::vec3(0.0f, 0.4f, 0.0f));
}

TEST(GltfSparse, KhronosSimpleSparseAccessorRaisesItsPeaks) {
  // A flat strip y 0..1 of 14 vertices; the sparse accessor moves vertices 8, 10 and 12 to
  // (1, 2), (3, 3) and (5, 4) (its README's "substitution of the values").
  Scene s;
  s.models.push_back(
      loadGltf(testing::assetPath("khronos/SimpleSparseAccessor/SimpleSparseAccessor.gltf"), s));
  const auto p = meshPositions(s, 0);
  for (const glm::vec3& peak : {glm::vec3(1, 2, 0), glm::vec3(3, 3, 0), glm::vec3(5, 4, 0)})
    EXPECT_TRUE(contains(p, peak)) << peak.x << ", " << peak.y;
  EXPECT_FALSE(contains(p, {3.0f, 1.0f, 0.0f})) << "vertex 10's flat value is replaced";
  EXPECT_TRUE(contains(p, {2.0f, 1.0f, 0.0f})) << "vertex 9 keeps its own";
}

// sparse.gltf with accessor `index`'s sparse object edited; the loader must refuse it by key.
fs::path corrupted(const std::string& name, int index, const std::string& key, int value) {
  // Read by size: istreambuf_iterator trips GCC 12's -Wnull-dereference.
  std::ifstream in(testing::assetPath("sparse.gltf"), std::ios::ate);
  std::string text(size_t(in.tellg()), '\0');
  in.seekg(0);
  in.read(text.data(), std::streamsize(text.size()));
  // The generator writes sorted keys: "sparse": {"count": N, "indices": {...}, ...}.
  const size_t at = [&] {
    size_t pos = 0;
    for (int k = 0; k <= index; ++k) pos = text.find("\"sparse\"", pos + 1);
    return pos;
  }();
  const size_t k = text.find("\"" + key + "\"", at);
  const size_t colon = text.find(':', k), end = text.find_first_of(",\n}", colon);
  text.replace(colon + 1, end - colon - 1, " " + std::to_string(value));
  const fs::path dir = fs::path(TAA_TEST_OUT) / "gltf_sparse";
  fs::create_directories(dir);
  std::ofstream(dir / name) << text;
  return dir / name;
}

TEST(GltfSparse, CorruptSubstitutionsAreRefusedNamingTheAccessor) {
  const struct {
    const char* name;
    int sparse;  // which sparse object (file order)
    const char* key;
    int value;
    const char* says;
  } cases[] = {
      {"count_over.gltf", 0, "count", 99, "sparse.count 99"},
      // Refused before decoding by the document check, which names the JSON path.
      {"count_zero.gltf", 1, "count", 0, "accessors[1].sparse.count is 0"},
      {"index_type.gltf", 0, "componentType", 5126, "accessors[0].sparse.indices.componentType is 5126"},
  };
  for (const auto& c : cases) {
    SCOPED_TRACE(c.name);
    const fs::path file = corrupted(c.name, c.sparse, c.key, c.value);
    Scene s;
    try {
      loadGltf(file, s);
      ADD_FAILURE() << "loaded";
    } catch (const SceneError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(file.string()), std::string::npos) << m;
      EXPECT_NE(m.find(c.says), std::string::npos) << m;
      // The accessor is named: by the attribute it feeds, or by its index.
      EXPECT_TRUE(m.find("POSITION") != std::string::npos || m.find("accessors[") != std::string::npos) << m;
    }
  }
}

}  // namespace
}  // namespace taa::scene
