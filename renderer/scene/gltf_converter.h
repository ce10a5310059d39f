// Internal to the glTF loader: the converter that gltf_convert.cpp (textures, materials,
// meshes) and gltf_nodes.cpp (nodes, cameras, animations) implement together.
#pragma once

#include <tiny_gltf.h>

#include <filesystem>
#include <glm/mat3x3.hpp>
#include <map>
#include <string>
#include <vector>

#include "scene/gltf_accessors.h"
#include "scene/gltf_convert.h"
#include "scene/scene.h"
#include "scene/scene_error.h"

namespace taa::scene::gltf_detail {

class Converter {
 public:
  Converter(const std::filesystem::path& file, const tinygltf::Model& g,
            const std::vector<GltfNode>& nodes, const std::string& warnings, Scene& s)
      : file_(file), g_(g), gltfNodes_(nodes), warnings_(warnings), s_(s),
        nodes_(nodes.size(), -1) {}
  Model run();

 private:
  [[noreturn]] void fail(const std::string& what) const { throw SceneError(file_, what); }
  std::vector<float> readAccessor(int index, const std::string& what, int components) {
    return readGltfAccessor(file_, g_, index, what, components);
  }
  std::vector<uint32_t> readIndices(int index, const std::string& what) {
    return readGltfIndices(file_, g_, index, what);
  }
  // `linear`: data rather than colour (a normal map), cached apart from a colour use.
  int texture(int index, const std::string& what, bool linear = false);
  TextureSampler gltfSampler(int index) const;
  // A material's texture reference: the scene texture, and in `uvSet` the UV set it samples
  // (its texCoord, or its KHR_texture_transform's); records the set's transform.
  int textureRef(int material, int index, int texCoord, const tinygltf::ExtensionMap& extensions,
                 const std::string& what, bool linear, int& uvSet);
  int material(int index);
  int mesh(int index);
  void addNode(int root, Model& model);
  void addOneNode(int index, int parent, Model& model);
  void instances(int index, const GltfNode& gn, Node& n);
  void addAnimation(const tinygltf::Animation& a, size_t index, Model& model);

  const std::filesystem::path& file_;
  const tinygltf::Model& g_;
  const std::vector<GltfNode>& gltfNodes_;
  const std::string& warnings_;
  Scene& s_;
  std::map<int, int> textures_, materials_, meshes_;
  std::vector<int> nodes_;  // per glTF node, its index in the model (-1: not reached yet)
  // Per glTF material: the KHR_texture_transform of each UV set its textures sample,
  // baked into that set of its primitives' coordinates.
  struct UvTransforms {
    bool given[2] = {false, false};
    glm::mat3 uv[2] = {glm::mat3(1.0f), glm::mat3(1.0f)};
  };
  std::map<int, UvTransforms> uvTransforms_;
};

}  // namespace taa::scene::gltf_detail
