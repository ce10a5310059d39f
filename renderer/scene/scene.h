// Scene data on the CPU, shared by glTF loading and procedural generation. The
// renderer uploads it once; per frame it only needs poseModel() for animated nodes.
#pragma once

#include <cstdint>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>
#include <string>
#include <vector>

namespace taa::scene {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
};
static_assert(sizeof(Vertex) == 32);

// RGBA8 texels, sRGB-encoded colour with linear alpha; levels[0] is full size,
// each further level half the size (rounded down, at least 1) down to 1x1.
struct Texture {
  struct Level {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;
  };
  std::vector<Level> levels;
  bool repeat = true;  // wrap mode; false clamps to edge
};

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
  glm::vec4 baseColorFactor{1.0f};  // linear RGBA
  int baseColorTexture = -1;        // index into Scene::textures, -1 = none
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
};

// A run of indices drawn with one material.
struct Primitive {
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
  int32_t vertexOffset = 0;
  int material = 0;
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;
  glm::vec3 boundsMin{0.0f};  // object-space bounds of all primitives
  glm::vec3 boundsMax{0.0f};
};

struct Node {
  std::string name;
  int parent = -1;  // index into the same Model's nodes; parents come before children
  int mesh = -1;    // index into Scene::meshes, -1 = none
  int camera = -1;  // index into the same Model's cameras, -1 = none
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
};

enum class AnimPath { Translation, Rotation, Scale };
enum class Interpolation { Linear, Step, CubicSpline };

struct AnimChannel {
  int node = 0;
  AnimPath path = AnimPath::Translation;
  Interpolation interpolation = Interpolation::Linear;
  std::vector<float> times;        // seconds, increasing
  std::vector<glm::vec4> values;   // xyz (or quaternion xyzw); cubic: in-tangent, value, out-tangent per key
};

struct Animation {
  std::string name;
  std::vector<AnimChannel> channels;
  float duration = 0.0f;  // last key time over all channels
};

// A glTF camera. It looks down its node's local -Z with +Y up; only perspective
// cameras are usable (recorded camera tracks import them).
struct Camera {
  bool perspective = true;
  float yfov = 0.8f;   // radians
  float znear = 0.1f;
  float zfar = 0.0f;   // 0: infinite (glTF leaves zfar out)
};

// A node hierarchy: the static world, or one mover's object.
struct Model {
  std::string name;
  std::vector<Node> nodes;
  std::vector<Animation> animations;
  std::vector<Camera> cameras;
};

struct Scene {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Mesh> meshes;
  std::vector<Model> models;  // models[0] is the world; movers follow in case order
};

// One mesh to draw with its model-space transform.
struct MeshDraw {
  int node = 0;
  int mesh = 0;
  glm::mat4 transform{1.0f};
};

// Evaluates a model's node hierarchy at `time` seconds of its first animation
// (looping), returning every mesh-bearing node in node order. Pure function.
std::vector<MeshDraw> poseModel(const Scene& scene, int model, double time);

// World transform of every node at `time` seconds into the model's first animation,
// not looped: before the first key and after the last the end values hold.
std::vector<glm::mat4> nodeWorldTransforms(const Model& model, double time);

// Object-space bounds of a model at rest (time 0), for framing a camera.
void modelBounds(const Scene& scene, int model, glm::vec3& lo, glm::vec3& hi);

}  // namespace taa::scene
