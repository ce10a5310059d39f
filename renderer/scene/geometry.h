// Building meshes by hand for the procedural scenes and the built-in movers.
// Conventions (shared with glTF): counter-clockwise front faces, right-handed,
// +Y up, uv (0, 0) at the first texel row of the image (the top of a picture).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace taa::scene {

// Collects one mesh's vertices and triangles, one primitive per material, and appends
// it to a Scene on finish(). Each primitive's indices are relative to its vertexOffset.
class MeshBuilder {
 public:
  MeshBuilder(Scene& scene, std::string name) : scene_(scene), name_(std::move(name)) {}

  // Triangles added from now on use `material` (an index into Scene::materials).
  void setMaterial(int material);
  uint32_t vertex(const glm::vec3& p, const glm::vec3& n, const glm::vec2& uv);
  void triangle(uint32_t a, uint32_t b, uint32_t c);

  // A rectangle centred at `c` spanning +-halfW along unit `right` and +-halfH along
  // unit `up`; it faces cross(right, up). uv runs 0..uvScale.x left to right and
  // 0..uvScale.y top to bottom, so an image appears upright.
  void rect(const glm::vec3& c, const glm::vec3& right, const glm::vec3& up, float halfW,
            float halfH, glm::vec2 uvScale = {1.0f, 1.0f});
  // An axis-aligned box with outward faces. uvPerUnit > 0 tiles the texture by world
  // size (uv = size * uvPerUnit), 0 maps 0..1 onto every face. `bottom` false omits the
  // -Y face of boxes standing on the ground, which is never seen.
  void box(const glm::vec3& lo, const glm::vec3& hi, float uvPerUnit = 0.0f, bool bottom = true);
  // A UV sphere with `segments` around the Y axis and `rings` from pole to pole.
  void sphere(const glm::vec3& c, float radius, int segments, int rings);
  // A prism of `sides` faces along a polyline, circumradius `radius` (its widest
  // cross-section is 2 * radius), smooth radial normals. Rings of `sides` vertices
  // follow each other in point order.
  void tube(const std::vector<glm::vec3>& points, float radius, int sides);

  size_t vertexCount() const { return vertices_.size(); }
  // Appends vertices, indices and the mesh (bounds filled) to the scene; returns its index.
  int finish();

 private:
  struct Batch {
    int material;
    std::vector<uint32_t> indices;
  };
  Scene& scene_;
  std::string name_;
  std::vector<Vertex> vertices_;
  std::vector<Batch> batches_;
  int current_ = -1;
};

// A model with one identity node per mesh, named after the mesh.
Model flatModel(const Scene& scene, std::string name, const std::vector<int>& meshes);

// Appends a material with `color` (linear RGBA) and optional texture; returns its index.
int addMaterial(Scene& scene, const glm::vec4& color, int texture = -1,
                AlphaMode mode = AlphaMode::Opaque, bool doubleSided = false);
int addTexture(Scene& scene, Texture texture);

}  // namespace taa::scene
