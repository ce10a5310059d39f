// Deformed normals are unit vectors: a morph target's normal deltas blend the rest normal
// toward another direction (their sum is shorter than 1 in between), and a joint may scale.
// The raster interpolates vertex normals across a triangle before it normalises, so a shorter
// one would weigh less. A normal that cancels to zero stays zero rather than becoming NaN.
#include <gtest/gtest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include "scene/scene.h"

namespace taa::scene::deform_normals_test {
namespace {

// One mesh of three vertices facing +z, with one morph target that turns the first to +x,
// leaves the second and cancels the third.
Scene morphScene() {
  Scene s;
  for (int i = 0; i < 3; ++i) s.vertices.push_back({glm::vec3(float(i), 0, 0), glm::vec3(0, 0, 1), {}});
  Mesh mesh;
  mesh.vertexCount = 3;
  mesh.targets.push_back({{glm::vec3(0), glm::vec3(0), glm::vec3(0)},
                          {glm::vec3(1, 0, -1), glm::vec3(0), glm::vec3(0, 0, -1)}});
  s.meshes.push_back(mesh);
  return s;
}

TEST(DeformNormals, AHalfWeightMorphGivesAUnitNormalBetweenTheTwo) {
  const Scene s = morphScene();
  MeshDraw draw;
  draw.weights = {0.5f};
  const auto v = deformVertices(s, draw);
  ASSERT_EQ(v.size(), 3u);
  EXPECT_NEAR(glm::length(v[0].normal), 1.0f, 1e-6f);
  EXPECT_NEAR(v[0].normal.x, std::sqrt(0.5f), 1e-6f);
  EXPECT_NEAR(v[0].normal.z, std::sqrt(0.5f), 1e-6f);
  EXPECT_EQ(v[1].normal, glm::vec3(0, 0, 1));
  EXPECT_NEAR(v[2].normal.z, 1.0f, 1e-6f);  // half cancelled, then unit again
  draw.weights = {1.0f};
  EXPECT_EQ(deformVertices(s, draw)[2].normal, glm::vec3(0));  // fully cancelled: no NaN
}

TEST(DeformNormals, AScalingJointKeepsNormalsUnit) {
  Scene s = morphScene();
  s.meshes[0].targets.clear();
  s.meshes[0].skin.assign(3, SkinWeights{glm::uvec4(0), glm::vec4(1, 0, 0, 0)});
  MeshDraw draw;
  draw.joints = {glm::scale(glm::mat4(1.0f), glm::vec3(3.0f))};
  for (const Vertex& v : deformVertices(s, draw)) EXPECT_NEAR(glm::length(v.normal), 1.0f, 1e-6f);
}

}  // namespace
}  // namespace taa::scene::deform_normals_test
