// Internal to the glTF loader: turns a parsed tinygltf::Model into scene data.
#pragma once

#include <tiny_gltf.h>

#include <nlohmann/json.hpp>

#include <filesystem>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <map>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace taa::scene {

// A glTF node as the loader keeps it (tinygltf never reads the node array): TRS with a
// matrix already decomposed, -1 for an absent index, and its EXT_mesh_gpu_instancing object
// (null without one).
struct GltfNode {
  std::string name;
  std::vector<int> children;
  int mesh = -1, camera = -1, skin = -1;
  std::vector<float> weights;
  glm::vec3 translation{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 scale{1.0f};
  nlohmann::json instancing;
};

// Takes the "nodes" array out of a document that checkGltfDocument accepted (gltf_node_list.cpp),
// freeing each entry as it is read.
std::vector<GltfNode> takeGltfNodes(nlohmann::json& doc);

// `nodes` are the file's (takeGltfNodes); `warnings` are tinygltf's, quoted when an image it
// could not read is needed.
Model convertGltf(const std::filesystem::path& file, const tinygltf::Model& gltf,
                  const std::vector<GltfNode>& nodes, const std::string& warnings, Scene& scene);

// What normaliseSkinWeights changed: vertices whose weights summed to other than one by more
// than kSkinWeightNoteTolerance (scaled to one, the sums' range kept for the note) and those
// with no weight at all.
struct SkinWeightFixes {
  size_t scaled = 0, unweighted = 0;
  float lowest = 1.0f, highest = 1.0f;  // of the scaled vertices' sums
  void add(const SkinWeightFixes& o);
};

// Scales each vertex's four weights (4 per vertex) to sum to one, as engines and viewers do:
// a file whose weights sum to less (CesiumMan's 0.18 to 0.999) would otherwise pull those
// vertices towards the origin. A vertex whose weights sum to zero or less keeps its bind pose
// (its weights become zero). Sums within kSkinWeightTolerance of one are left as they are, so
// a well-formed file's weights keep their every bit; those within kSkinWeightNoteTolerance
// are scaled without a note (a quantised file's rounding: Draco's, 16-bit weights'), so the
// note counts only vertices whose weights were wrong.
inline constexpr float kSkinWeightTolerance = 1e-5f;
inline constexpr float kSkinWeightNoteTolerance = 1e-3f;
SkinWeightFixes normaliseSkinWeights(std::vector<float>& weights);

// A primitive's morph targets and skin attributes, per vertex of the primitive.
struct GltfDeform {
  std::vector<std::vector<float>> positions, normals;  // per target: xyz per vertex (may be empty)
  std::vector<float> joints, weights;                  // 4 per vertex; empty: not skinned
  SkinWeightFixes weightFixes;                         // what reading the weights normalised
};
GltfDeform readGltfDeform(const std::filesystem::path& file, const tinygltf::Model& gltf,
                          const tinygltf::Primitive& prim, const std::string& what, size_t count);

// Appends a primitive's deformation data to `mesh` for the vertices it emitted
// (`source[i]`: the primitive vertex emitted vertex i copies); `before` vertices of
// the mesh came earlier, and get zero offsets and weights where they had none.
void appendGltfDeform(const GltfDeform& d, const std::vector<uint32_t>& source, size_t before,
                      Mesh& mesh);

// Every skin of the file, joints mapped through `nodes` (glTF node -> model node, -1: not in
// the default scene).
std::vector<Skin> readGltfSkins(const std::filesystem::path& file, const tinygltf::Model& gltf,
                                const std::vector<int>& nodes);

// The KHR_texture_transform of a texture reference (identity without one) as a UV
// matrix, and the UV set it selects in place of the reference's texCoord (-1: none);
// throws SceneError for a malformed one.
struct GltfTextureTransform {
  glm::mat3 uv{1.0f};
  int texCoord = -1;
};
GltfTextureTransform gltfTextureTransform(const std::filesystem::path& file,
                                          const tinygltf::ExtensionMap& extensions,
                                          const std::string& what);

// A material's emission (gltf_emissive.cpp): emissiveFactor times
// KHR_materials_emissive_strength (an emissiveTexture multiplies it per texel). Throws
// SceneError for malformed values.
glm::vec3 gltfEmissive(const std::filesystem::path& file, const tinygltf::Material& material,
                       const std::string& what);

// EXT_meshopt_compression (gltf_meshopt.cpp). Before tinygltf: gives every fallback
// buffer without a uri an all-zero data URI of its byteLength; returns whether it
// changed `doc`. glbWithJson replaces a GLB's JSON chunk. After tinygltf: decodes every
// compressed buffer view into its place; throws SceneError naming the view.
bool fillMeshoptFallbacks(nlohmann::json& doc);
std::vector<uint8_t> glbWithJson(const std::vector<uint8_t>& glb, std::string json);
void decodeMeshopt(const std::filesystem::path& file, tinygltf::Model& gltf);

// KHR_draco_mesh_compression (gltf_draco.cpp). Before tinygltf: takes the "indices" key
// out of each compressed primitive whose indices accessor has no bufferView (tinygltf
// refuses those) and returns every compressed primitive's indices accessor, by (mesh,
// primitive), -1 for none; sets `changed` when it took a key out. After tinygltf: decodes each compressed primitive into new
// accessors and points the primitive at them; throws SceneError naming the primitive.
using DracoIndices = std::map<std::pair<int, int>, int>;
DracoIndices detachDracoIndices(nlohmann::json& doc, bool& changed);
void decodeDraco(const std::filesystem::path& file, tinygltf::Model& gltf,
                 const DracoIndices& indices);

// Splits a node matrix (column-major, no shear as glTF requires) into TRS. A negative
// determinant becomes a negative x scale.
void decomposeTrs(const glm::mat4& m, glm::vec3& t, glm::quat& r, glm::vec3& s);

}  // namespace taa::scene
