#include "scene/geometry.h"

#include <cassert>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <utility>

namespace taa::scene {

void MeshBuilder::setMaterial(int material) {
  for (size_t i = 0; i < batches_.size(); ++i)
    if (batches_[i].material == material) {
      current_ = int(i);
      return;
    }
  batches_.push_back({material, {}});
  current_ = int(batches_.size()) - 1;
}

uint32_t MeshBuilder::vertex(const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv) {
  vertices_.push_back({p, n, uv, glm::vec4(1.0f)});
  return uint32_t(vertices_.size() - 1);
}

void MeshBuilder::triangle(uint32_t a, uint32_t b, uint32_t c) {
  assert(current_ >= 0 && "setMaterial() before adding triangles");
  auto& idx = batches_[size_t(current_)].indices;
  idx.insert(idx.end(), {a, b, c});
}

void MeshBuilder::rect(const glm::vec3& c, const glm::vec3& right, const glm::vec3& up, float halfW,
                       float halfH, glm::vec2 uvScale) {
  const glm::vec3 n = glm::normalize(glm::cross(right, up));
  const glm::vec3 r = right * halfW, u = up * halfH;
  const uint32_t a = vertex(c - r - u, n, {0.0f, uvScale.y});
  const uint32_t b = vertex(c + r - u, n, {uvScale.x, uvScale.y});
  const uint32_t d = vertex(c + r + u, n, {uvScale.x, 0.0f});
  const uint32_t e = vertex(c - r + u, n, {0.0f, 0.0f});
  triangle(a, b, d);
  triangle(a, d, e);
}

void MeshBuilder::box(const glm::vec3& lo, const glm::vec3& hi, float uvPerUnit, bool bottom) {
  const glm::vec3 c = (lo + hi) * 0.5f, h = (hi - lo) * 0.5f;
  struct Face {
    glm::vec3 n, r, u;
  };
  // cross(r, u) == n for each face, so every face is counter-clockwise from outside.
  static const Face kFaces[] = {
      {{1, 0, 0}, {0, 0, -1}, {0, 1, 0}}, {{-1, 0, 0}, {0, 0, 1}, {0, 1, 0}},
      {{0, 0, 1}, {1, 0, 0}, {0, 1, 0}},  {{0, 0, -1}, {-1, 0, 0}, {0, 1, 0}},
      {{0, 1, 0}, {1, 0, 0}, {0, 0, -1}}, {{0, -1, 0}, {1, 0, 0}, {0, 0, 1}},
  };
  for (const Face& f : kFaces) {
    if (!bottom && f.n.y < 0.0f) continue;
    const float hw = glm::dot(glm::abs(f.r), h), hh = glm::dot(glm::abs(f.u), h);
    const glm::vec2 uv =
        uvPerUnit > 0.0f ? glm::vec2(2.0f * hw, 2.0f * hh) * uvPerUnit : glm::vec2(1.0f);
    rect(c + f.n * glm::dot(glm::abs(f.n), h), f.r, f.u, hw, hh, uv);
  }
}

void MeshBuilder::sphere(const glm::vec3& c, float radius, int segments, int rings) {
  const uint32_t base = uint32_t(vertices_.size());
  for (int i = 0; i <= rings; ++i) {
    const float theta = glm::pi<float>() * float(i) / float(rings);
    for (int j = 0; j <= segments; ++j) {
      const float phi = glm::two_pi<float>() * float(j) / float(segments);
      const glm::vec3 n(std::sin(theta) * std::sin(phi), std::cos(theta),
                        std::sin(theta) * std::cos(phi));
      vertex(c + n * radius, n, {float(j) / float(segments), float(i) / float(rings)});
    }
  }
  const uint32_t stride = uint32_t(segments + 1);
  for (int i = 0; i < rings; ++i)
    for (int j = 0; j < segments; ++j) {
      const uint32_t a = base + uint32_t(i) * stride + uint32_t(j), b = a + stride;
      // The pole rows would give zero-area triangles; skip them.
      if (i != 0) triangle(a, b, a + 1);
      if (i != rings - 1) triangle(a + 1, b, b + 1);
    }
}

void MeshBuilder::tube(const std::vector<glm::vec3>& points, float radius, int sides) {
  assert(points.size() >= 2 && sides >= 3);
  const uint32_t base = uint32_t(vertices_.size());
  float along = 0.0f;
  for (size_t k = 0; k < points.size(); ++k) {
    const glm::vec3 t =
        glm::normalize(points[std::min(k + 1, points.size() - 1)] - points[k > 0 ? k - 1 : 0]);
    const glm::vec3 ref = std::fabs(t.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
    const glm::vec3 s = glm::normalize(glm::cross(t, ref)), u = glm::cross(s, t);
    if (k > 0) along += glm::length(points[k] - points[k - 1]);
    for (int j = 0; j < sides; ++j) {
      const float a = glm::two_pi<float>() * (float(j) + 0.5f) / float(sides);
      const glm::vec3 n = s * std::cos(a) + u * std::sin(a);
      vertex(points[k] + n * radius, n, {float(j) / float(sides), along});
    }
  }
  const uint32_t ns = uint32_t(sides);
  for (uint32_t k = 0; k + 1 < points.size(); ++k)
    for (uint32_t j = 0; j < ns; ++j) {
      const uint32_t a = base + k * ns + j, b = base + k * ns + (j + 1) % ns;
      triangle(a, a + ns, b);
      triangle(b, a + ns, b + ns);
    }
}

int MeshBuilder::finish() {
  Mesh mesh;
  mesh.name = name_;
  const int32_t offset = int32_t(scene_.vertices.size());
  if (!vertices_.empty()) {
    mesh.boundsMin = mesh.boundsMax = vertices_[0].position;
    for (const Vertex& v : vertices_) {
      mesh.boundsMin = glm::min(mesh.boundsMin, v.position);
      mesh.boundsMax = glm::max(mesh.boundsMax, v.position);
    }
  }
  scene_.vertices.insert(scene_.vertices.end(), vertices_.begin(), vertices_.end());
  for (const Batch& b : batches_) {
    if (b.indices.empty()) continue;
    mesh.primitives.push_back(
        {uint32_t(scene_.indices.size()), uint32_t(b.indices.size()), offset, b.material});
    scene_.indices.insert(scene_.indices.end(), b.indices.begin(), b.indices.end());
  }
  scene_.meshes.push_back(std::move(mesh));
  vertices_.clear();
  batches_.clear();
  current_ = -1;
  return int(scene_.meshes.size()) - 1;
}

Model flatModel(const Scene& scene, std::string name, const std::vector<int>& meshes) {
  Model model;
  model.name = std::move(name);
  for (int m : meshes) {
    Node node;
    node.name = scene.meshes[size_t(m)].name;
    node.mesh = m;
    model.nodes.push_back(std::move(node));
  }
  return model;
}

int addMaterial(Scene& scene, const glm::vec4& color, int texture, AlphaMode mode,
                bool doubleSided) {
  Material m;
  m.baseColorFactor = color;
  m.baseColorTexture = texture;
  m.alphaMode = mode;
  m.doubleSided = doubleSided;
  scene.materials.push_back(m);
  return int(scene.materials.size()) - 1;
}

int addTexture(Scene& scene, Texture texture) {
  scene.textures.push_back(std::move(texture));
  return int(scene.textures.size()) - 1;
}

}  // namespace taa::scene
