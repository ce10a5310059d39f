#include "scene/procedural.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>

#include "scene/scene_error.h"
#include "scene/textures.h"
#include "scene_test_util.h"

namespace taa::scene {
namespace {

using spec::BuiltinScene;
using testing::DefaultCamera;

const BuiltinScene kAll[] = {
    BuiltinScene::Checkerboard, BuiltinScene::Wires,    BuiltinScene::Fence, BuiltinScene::Foliage,
    BuiltinScene::RoughFloor,   BuiltinScene::OpenArea, BuiltinScene::Quad};

Scene build(BuiltinScene which) {
  Scene s;
  s.models.push_back(buildProceduralScene(which, s));
  return s;
}

std::string nameOf(BuiltinScene b) {
  return spec::enumToString(b);
}

TEST(ProceduralScenes, WellFormedWithinBudget) {
  for (BuiltinScene which : kAll) {
    SCOPED_TRACE(nameOf(which));
    const Scene s = build(which);
    ASSERT_EQ(s.models.size(), 1u);
    ASSERT_FALSE(s.models[0].nodes.empty());
    size_t triangles = 0;
    for (size_t m = 0; m < s.meshes.size(); ++m) {
      const Mesh& mesh = s.meshes[m];
      ASSERT_FALSE(mesh.primitives.empty()) << mesh.name;
      triangles += triangleCount(s, int(m));
      for (const Primitive& p : mesh.primitives) {
        ASSERT_GT(p.indexCount, 0u);
        ASSERT_EQ(p.indexCount % 3, 0u);
        ASSERT_LE(size_t(p.firstIndex) + p.indexCount, s.indices.size());
        ASSERT_GE(p.material, 0);
        ASSERT_LT(size_t(p.material), s.materials.size());
        for (uint32_t i = 0; i < p.indexCount; ++i) {
          const size_t v = size_t(s.indices[p.firstIndex + i]) + size_t(p.vertexOffset);
          ASSERT_LT(v, s.vertices.size());
          const Vertex& vx = s.vertices[v];
          // Bounds hold every vertex; normals are unit length.
          ASSERT_TRUE(glm::all(glm::greaterThanEqual(vx.position, mesh.boundsMin - 1e-5f)))
              << mesh.name;
          ASSERT_TRUE(glm::all(glm::lessThanEqual(vx.position, mesh.boundsMax + 1e-5f)))
              << mesh.name;
          ASSERT_NEAR(glm::length(vx.normal), 1.0f, 1e-4f) << mesh.name;
        }
      }
      EXPECT_LT(glm::length(mesh.boundsMax - mesh.boundsMin), 1000.0f) << mesh.name;
    }
    for (const Material& m : s.materials) ASSERT_LT(m.baseColorTexture, int(s.textures.size()));
    EXPECT_GT(triangles, 0u);
    EXPECT_LE(triangles, 4000u) << "lavapipe budget";
    glm::vec3 lo, hi;
    modelBounds(s, 0, lo, hi);
    EXPECT_GT(hi.x - lo.x, 0.5f);
    EXPECT_GT(hi.y - lo.y, 0.2f);
  }
}

TEST(ProceduralScenes, FrontFacesAreCounterClockwiseAndAgreeWithNormals) {
  for (BuiltinScene which : kAll) {
    SCOPED_TRACE(nameOf(which));
    const Scene s = build(which);
    for (const Mesh& mesh : s.meshes)
      for (const Primitive& p : mesh.primitives)
        for (uint32_t i = 0; i < p.indexCount; i += 3) {
          const Vertex* v[3];
          for (uint32_t k = 0; k < 3; ++k)
            v[k] = &s.vertices[s.indices[p.firstIndex + i + k] + uint32_t(p.vertexOffset)];
          const glm::vec3 n =
              glm::cross(v[1]->position - v[0]->position, v[2]->position - v[0]->position);
          if (glm::length(n) < 1e-9f) continue;
          ASSERT_GT(glm::dot(n, v[0]->normal + v[1]->normal + v[2]->normal), 0.0f)
              << mesh.name << " triangle " << i / 3;
        }
  }
}

TEST(ProceduralScenes, TwoBuildsAreByteIdentical) {
  for (BuiltinScene which : kAll) {
    SCOPED_TRACE(nameOf(which));
    const Scene a = build(which), b = build(which);
    ASSERT_EQ(a.vertices.size(), b.vertices.size());
    EXPECT_EQ(std::memcmp(a.vertices.data(), b.vertices.data(), a.vertices.size() * sizeof(Vertex)),
              0);
    EXPECT_EQ(a.indices, b.indices);
    ASSERT_EQ(a.textures.size(), b.textures.size());
    for (size_t t = 0; t < a.textures.size(); ++t)
      for (size_t l = 0; l < a.textures[t].levels.size(); ++l)
        EXPECT_EQ(a.textures[t].levels[l].rgba, b.textures[t].levels[l].rgba);
  }
}

// Casts a 32 x 18 grid of rays from the default camera; the frame must be mostly covered.
TEST(ProceduralScenes, FillTheDefaultView) {
  const DefaultCamera cam;
  for (BuiltinScene which : kAll) {
    SCOPED_TRACE(nameOf(which));
    const auto triangles = testing::posedTriangles(build(which), 0);
    int hits = 0, total = 0;
    for (int y = 0; y < 18; ++y)
      for (int x = 0; x < 32; ++x, ++total)
        hits += testing::castRay(triangles, cam.eye,
                                 cam.ray((float(x) + 0.5f) * 10.0f, (float(y) + 0.5f) * 10.0f))
                    .has_value();
    const double coverage = double(hits) / double(total);
    if (which == BuiltinScene::Quad) {
      // One unit quad six units away: about 30 x 30 pixels in the middle of the frame.
      EXPECT_TRUE(testing::castRay(triangles, cam.eye, cam.ray(160.0f, 90.0f)).has_value());
      EXPECT_GT(coverage, 0.005);
    } else {
      EXPECT_GT(coverage, 0.55) << "too much empty sky";
    }
  }
}

TEST(ProceduralWires, SubPixelAt320x180FromDefaultCamera) {
  const DefaultCamera cam;
  const std::vector<Cable> cables = wireCables();
  ASSERT_GE(cables.size(), 6u);
  int visible = 0;
  float widest = 0.0f, thinnest = 1e9f;
  for (const Cable& c : cables)
    for (const glm::vec3& p : c.points) {
      if (!cam.inView(p, 8.0f)) continue;
      ++visible;
      // A sphere of the cable's circumradius holds any cross-section. Seen at distance D
      // and angle theta off the axis, its image is widest radially:
      // f * (tan(theta + alpha) - tan(theta - alpha)) with sin(alpha) = r / D.
      const glm::vec3 d = p - cam.eye;
      const float dist = glm::length(d);
      const float theta = std::acos(glm::dot(d, cam.forward) / dist);
      const float alpha = std::asin(c.radius / dist);
      const float width = cam.focal() * (std::tan(theta + alpha) - std::tan(theta - alpha));
      widest = std::max(widest, width);
      thinnest = std::min(thinnest, width);
    }
  EXPECT_GT(visible, 40) << "the wires must be in view";
  EXPECT_LT(widest, 1.0f) << "a wire is a pixel or wider";
  EXPECT_GT(thinnest, 0.05f) << "wires so thin they never cover a sample are pointless";
}

TEST(ProceduralWires, MeshCrossSectionsProjectBelowAPixel) {
  // Same check on the built geometry: each ring of 4 vertices spans under a pixel.
  const DefaultCamera cam;
  Scene s = build(BuiltinScene::Wires);
  const Mesh* wires = nullptr;
  for (const Mesh& m : s.meshes)
    if (m.name == "wires") wires = &m;
  ASSERT_NE(wires, nullptr);
  const Primitive& p = wires->primitives.at(0);
  const size_t first = size_t(p.vertexOffset);
  size_t last = first;
  for (uint32_t i = 0; i < p.indexCount; ++i)
    last = std::max(last, first + s.indices[p.firstIndex + i]);
  ASSERT_EQ((last + 1 - first) % 4, 0u);
  int rings = 0;
  for (size_t r = first; r <= last; r += 4) {
    bool in = true;
    for (size_t k = 0; k < 4; ++k) in = in && cam.inView(s.vertices[r + k].position);
    if (!in) continue;
    ++rings;
    float span = 0.0f;
    for (size_t a = 0; a < 4; ++a)
      for (size_t b = a + 1; b < 4; ++b)
        span = std::max(span, glm::length(cam.project(s.vertices[r + a].position) -
                                          cam.project(s.vertices[r + b].position)));
    EXPECT_LT(span, 1.0f) << "ring at vertex " << r;
  }
  EXPECT_GT(rings, 40);
}

TEST(ProceduralFence, RecedesAtAGrazingAngle) {
  const Scene s = build(BuiltinScene::Fence);
  const Mesh& fence = s.meshes.at(1);
  ASSERT_EQ(fence.name, "fence");
  EXPECT_GT(fence.boundsMax.z - fence.boundsMin.z, 40.0f);
  // The left fence's slats, 0.25 apart, fall below a pixel apart at 320x180 within the
  // fence's length: that is what makes it alias.
  const DefaultCamera cam;
  const glm::vec3 a(-1.3f, 0.5f, -30.0f), b(-1.3f, 0.5f, -30.25f);
  EXPECT_LT(glm::length(cam.project(a) - cam.project(b)), 1.0f);
}

TEST(ProceduralFoliage, AlphaTestedDoubleSidedCards) {
  const Scene s = build(BuiltinScene::Foliage);
  int masked = 0;
  for (const Material& m : s.materials)
    if (m.alphaMode == AlphaMode::Mask) {
      ++masked;
      EXPECT_TRUE(m.doubleSided);
      ASSERT_GE(m.baseColorTexture, 0);
      EXPECT_TRUE(hasTranslucentTexels(s.textures[size_t(m.baseColorTexture)]));
    }
  EXPECT_EQ(masked, 1);
}

TEST(ProceduralRoughFloor, IsBumpy) {
  const Scene s = build(BuiltinScene::RoughFloor);
  EXPECT_GT(s.meshes[0].boundsMax.y - s.meshes[0].boundsMin.y, 0.2f);
  EXPECT_LT(s.meshes[0].boundsMax.y - s.meshes[0].boundsMin.y, 1.0f);
}

TEST(ProceduralMovers, ClosedShapesFaceOutwards) {
  for (spec::MoverShape shape : {spec::MoverShape::Cube, spec::MoverShape::Sphere}) {
    Scene s;
    s.models.push_back(buildMoverShape(shape, {0.1f, 0.2f, 0.3f}, s));
    ASSERT_EQ(s.meshes.size(), 1u);
    EXPECT_EQ(s.materials.at(0).baseColorFactor, glm::vec4(0.1f, 0.2f, 0.3f, 1.0f));
    EXPECT_NEAR(s.meshes[0].boundsMax.x, 0.5f, 1e-5f);
    EXPECT_NEAR(s.meshes[0].boundsMin.y, -0.5f, 1e-5f);
    const Primitive& p = s.meshes[0].primitives[0];
    for (uint32_t i = 0; i < p.indexCount; i += 3) {
      const glm::vec3 a = s.vertices[s.indices[i]].position,
                      b = s.vertices[s.indices[i + 1]].position,
                      c = s.vertices[s.indices[i + 2]].position;
      EXPECT_GT(glm::dot(glm::cross(b - a, c - a), a + b + c), 0.0f);
    }
  }
  Scene s;
  EXPECT_THROW(buildMoverShape(spec::MoverShape::Gltf, {}, s), SceneError);
  EXPECT_THROW(buildProceduralScene(BuiltinScene::None, s), SceneError);
}

}  // namespace
}  // namespace taa::scene
