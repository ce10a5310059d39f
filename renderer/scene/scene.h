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

#include "core/image.h"

namespace taa::scene {

struct Vertex {
  glm::vec3 position;
  glm::vec3 normal;
  glm::vec2 uv;
  glm::vec4 color{1.0f};  // linear RGBA (glTF COLOR_0), multiplies the base colour
  glm::vec2 uv1{0.0f};    // glTF TEXCOORD_1, for the textures of a material that name it
};
static_assert(sizeof(Vertex) == 56);

// How a texture is sampled: a glTF sampler. Without one glTF repeats on both axes and
// leaves the filters to the viewer; ours are then linear with linear mip blending.
enum class Wrap { Repeat, ClampToEdge, MirroredRepeat };
enum class Filter { Linear, Nearest };
enum class MipFilter { Linear, Nearest, None };  // None: only level 0 (minFilter NEAREST / LINEAR)
struct TextureSampler {
  Wrap wrapS = Wrap::Repeat;  // along u
  Wrap wrapT = Wrap::Repeat;  // along v
  Filter mag = Filter::Linear;
  Filter min = Filter::Linear;
  MipFilter mip = MipFilter::Linear;
  // One small integer per distinct sampler (the GPU scene keeps one VkSampler each).
  int key() const { return ((int(wrapS) * 3 + int(wrapT)) * 2 + int(mag)) * 6 + int(min) * 3 + int(mip); }
};

// RGBA8 texels, sRGB-encoded colour with linear alpha; levels[0] is full size,
// each further level half the size (rounded down, at least 1) down to 1x1.
struct Texture {
  struct Level {
    int width = 0;
    int height = 0;
    std::vector<uint8_t> rgba;
  };
  std::vector<Level> levels;
  TextureSampler sampler;
  // Data, not colour (normal maps): uploaded as UNORM, mips average the stored values.
  bool linear = false;
};

enum class AlphaMode { Opaque, Mask, Blend };

struct Material {
  glm::vec4 baseColorFactor{1.0f};  // linear RGBA
  int baseColorTexture = -1;        // index into Scene::textures, -1 = none
  AlphaMode alphaMode = AlphaMode::Opaque;
  float alphaCutoff = 0.5f;
  bool doubleSided = false;
  // Linear radiance added to the shaded colour: glTF emissiveFactor times
  // KHR_materials_emissive_strength (0 for every material that does not glow).
  glm::vec3 emissive{0.0f};
  // glTF normalTexture (a linear texture, tangent space, +Y towards the image's top) and
  // its scale; -1: none.
  int normalTexture = -1;
  float normalScale = 1.0f;
  // glTF emissiveTexture: its sRGB colour multiplies `emissive` (-1: none, emission is
  // uniform). Meaningful only where `emissive` is not zero.
  int emissiveTexture = -1;
  // glTF occlusionTexture (linear, red channel) and its strength: the ambient term is
  // multiplied by 1 + strength * (red - 1). -1: none.
  int occlusionTexture = -1;
  float occlusionStrength = 1.0f;
  // KHR_materials_unlit: the surface shows its base colour (times vertex colour), no
  // lighting, shadows, emission, occlusion or normal map.
  bool unlit = false;
  // Which UV set (0: Vertex::uv, 1: Vertex::uv1) each texture samples (glTF texCoord).
  int baseColorUv = 0, normalUv = 0, emissiveUv = 0, occlusionUv = 0;
};

// A run of indices drawn with one material.
struct Primitive {
  uint32_t firstIndex = 0;
  uint32_t indexCount = 0;
  int32_t vertexOffset = 0;
  int material = 0;
};

// Per-vertex offsets of one morph target, over the mesh's whole vertex range.
struct MorphTarget {
  std::vector<glm::vec3> position;
  std::vector<glm::vec3> normal;  // empty when the target moves no normals
};

// Up to four joints (indices into the skin's joint list) and their weights.
struct SkinWeights {
  glm::uvec4 joints{0u};
  glm::vec4 weights{0.0f};
};

struct Mesh {
  std::string name;
  std::vector<Primitive> primitives;
  glm::vec3 boundsMin{0.0f};  // object-space bounds of all primitives (at rest)
  glm::vec3 boundsMax{0.0f};
  bool vertexColors = false;  // some primitive has COLOR_0 (Vertex::color is not all white)
  // Deformation data. The mesh's vertices are Scene::vertices[firstVertex, +vertexCount)
  // in primitive order; morph targets and skin weights index the same range.
  uint32_t firstVertex = 0;
  uint32_t vertexCount = 0;
  std::vector<MorphTarget> targets;
  std::vector<float> weights;  // default morph weights, one per target
  std::vector<SkinWeights> skin;  // empty: the mesh carries no joints
};

struct Node {
  std::string name;
  int parent = -1;  // index into the same Model's nodes; parents come before children
  int mesh = -1;    // index into Scene::meshes, -1 = none
  int camera = -1;  // index into the same Model's cameras, -1 = none
  int skin = -1;    // index into the same Model's skins, -1 = none
  std::vector<float> weights;  // morph weights overriding the mesh's; empty: the mesh's
  // EXT_mesh_gpu_instancing: the mesh is drawn once per transform, each applied before the
  // node's own (world * instance); empty: drawn once.
  std::vector<glm::mat4> instances;
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
};

enum class AnimPath { Translation, Rotation, Scale, Weights };
enum class Interpolation { Linear, Step, CubicSpline };

struct AnimChannel {
  int node = 0;
  AnimPath path = AnimPath::Translation;
  Interpolation interpolation = Interpolation::Linear;
  std::vector<float> times;        // seconds, increasing
  std::vector<glm::vec4> values;   // xyz (or quaternion xyzw); cubic: in-tangent, value, out-tangent per key
  std::vector<float> weights;      // Weights path: `targets` floats per value, in place of `values`
  int targets = 0;
};

// Joints (indices into the model's nodes) and their inverse bind matrices.
struct Skin {
  std::vector<int> joints;
  std::vector<glm::mat4> inverseBind;
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

// A node hierarchy: the world, or one mover's object.
struct Model {
  std::string name;
  std::vector<Node> nodes;
  std::vector<Animation> animations;
  std::vector<Camera> cameras;
  std::vector<Skin> skins;
  // Indices of the animations that play together, in this order (a later channel on the
  // same node and path wins); empty: defaultAnimations(). A case may pick some.
  std::vector<int> playing;
};

struct Scene {
  std::vector<Vertex> vertices;
  std::vector<uint32_t> indices;
  std::vector<Material> materials;
  std::vector<Texture> textures;
  std::vector<Mesh> meshes;
  std::vector<Model> models;  // models[0] is the world; movers follow in case order
  // What loading left out, one line per file (e.g. extensions used but not supported);
  // the renderer logs them so the run log and the report show them.
  std::vector<std::string> notes;
  // debug.image: the still image (RGBA, output size) that replaces the rendered colour.
  Image still;
};

// One mesh to draw with its model-space transform. A skinned mesh is posed in model
// space by `joints` (transform is then identity, as glTF ignores the node's own);
// `weights` are the morph weights in force (empty for a mesh without targets).
struct MeshDraw {
  int node = 0;
  int mesh = 0;
  glm::mat4 transform{1.0f};
  std::vector<glm::mat4> joints;  // per skin joint: world(joint) * inverse bind matrix
  std::vector<float> weights;
  bool deformed() const { return !joints.empty() || !weights.empty(); }
};

// The mesh's vertices deformed by the draw's morph weights, then its joints; the
// output has mesh.vertexCount entries. Pure function.
std::vector<Vertex> deformVertices(const Scene& scene, const MeshDraw& draw);

// Evaluates a model's node hierarchy at `time` seconds into its playing animations,
// each looping over its own duration, returning every mesh-bearing node in node
// order (an instanced node once per instance, in instance order). Pure function.
std::vector<MeshDraw> poseModel(const Scene& scene, int model, double time);

// World transform of every node at `time` seconds into the model's playing
// animations, not looped: before the first key and after the last the end values hold.
std::vector<glm::mat4> nodeWorldTransforms(const Model& model, double time);

// Whether any playing animation of the model has keys over a time span (its pose
// changes with time).
bool modelAnimates(const Model& model);

// What plays when a case picks no animations: the first, and every later one that drives
// no (node, property) an animation already chosen drives. Independent clips (one box
// spinning, another rising) play together; alternatives of one rig (Walk, Run, Idle) do
// not overwrite each other: the first plays, as a glTF viewer shows it.
std::vector<int> defaultAnimations(const Model& model);

// The animations that play (Model::playing, else the default).
std::vector<int> playingAnimations(const Model& model);

// One run-log line naming what plays and what is left out, "" for a model without
// animations.
std::string describeAnimations(const Model& model);

// Object-space bounds of a model posed at each of `times` (seconds into its playing
// animations, looped as the renderer plays them): skinned and morphed meshes by their
// deformed vertices, rigid ones by their transformed boxes. For framing a camera.
void modelBounds(const Scene& scene, int model, const std::vector<double>& times, glm::vec3& lo,
                 glm::vec3& hi);
// The same at time 0 alone.
void modelBounds(const Scene& scene, int model, glm::vec3& lo, glm::vec3& hi);

}  // namespace taa::scene
