// The glTF nodes, read from the checked document instead of by tinygltf. Left to tinygltf, a
// file of 100,000 sibling nodes was held three times while loading (tinygltf's JSON tree, its
// Model's 456-byte nodes, the converted model): about 1.1 KB a node. Here each entry of the
// document's node array is read and freed in turn, and tinygltf never sees the array.
#include <glm/gtc/type_ptr.hpp>
#include <nlohmann/json.hpp>

#include "scene/gltf_convert.h"

namespace taa::scene {
namespace {

using nlohmann::json;

// checkGltfDocument has checked every key read here (indices in range, arrays of their
// length), so an absent or mistyped key is only ever "not given".
int index(const json& node, const char* key) {
  const auto it = node.find(key);
  return it != node.end() && it->is_number_unsigned() ? int(it->get<uint64_t>()) : -1;
}

std::vector<float> numbers(const json& node, const char* key) {
  std::vector<float> out;
  if (const auto it = node.find(key); it != node.end() && it->is_array()) {
    out.reserve(it->size());
    for (const json& v : *it)
      if (v.is_number()) out.push_back(float(v.get<double>()));
  }
  return out;
}

GltfNode readNode(json& node) {
  GltfNode n;
  if (!node.is_object()) return n;
  if (const auto it = node.find("name"); it != node.end() && it->is_string())
    n.name = it->get<std::string>();
  if (const auto it = node.find("children"); it != node.end() && it->is_array()) {
    n.children.reserve(it->size());
    for (const json& c : *it)
      if (c.is_number_unsigned()) n.children.push_back(int(c.get<uint64_t>()));
  }
  n.mesh = index(node, "mesh");
  n.camera = index(node, "camera");
  n.skin = index(node, "skin");
  n.weights = numbers(node, "weights");
  if (const std::vector<float> m = numbers(node, "matrix"); m.size() == 16) {
    decomposeTrs(glm::make_mat4(m.data()), n.translation, n.rotation, n.scale);
  } else {
    if (const std::vector<float> t = numbers(node, "translation"); t.size() == 3)
      n.translation = glm::make_vec3(t.data());
    if (const std::vector<float> r = numbers(node, "rotation"); r.size() == 4)
      n.rotation = glm::quat(r[3], r[0], r[1], r[2]);
    if (const std::vector<float> s = numbers(node, "scale"); s.size() == 3)
      n.scale = glm::make_vec3(s.data());
  }
  if (const auto ext = node.find("extensions"); ext != node.end() && ext->is_object())
    if (const auto inst = ext->find("EXT_mesh_gpu_instancing"); inst != ext->end())
      n.instancing = std::move(*inst);
  return n;
}

}  // namespace

std::vector<GltfNode> takeGltfNodes(json& doc) {
  std::vector<GltfNode> out;
  const auto nodes = doc.find("nodes");
  if (nodes == doc.end()) return out;
  if (nodes->is_array()) {
    out.reserve(nodes->size());
    for (json& node : *nodes) {
      out.push_back(readNode(node));
      node = nullptr;  // this entry's tree is freed before the next is read
    }
  }
  doc.erase(nodes);
  return out;
}

}  // namespace taa::scene
