// The glTF converter's scene graph: the default scene's roots, nodes (parents first),
// cameras, skins and animations. Textures, materials and meshes are gltf_convert.cpp's.
#include <cstdint>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>

#include "scene/gltf_convert.h"
#include "scene/gltf_converter.h"

namespace taa::scene::gltf_detail {

// Depth-first with an explicit stack, parents before children in file order: a chain of
// 100,000 nodes must not exhaust the call stack.
void Converter::addNode(int root, Model& model) {
  std::vector<std::pair<int, int>> pending{{root, -1}};  // (glTF index, parent's model index)
  while (!pending.empty()) {
    const auto [index, parent] = pending.back();
    pending.pop_back();
    addOneNode(index, parent, model);
    const std::vector<int>& children = gltfNodes_[size_t(index)].children;
    const int self = int(model.nodes.size()) - 1;
    for (auto c = children.rbegin(); c != children.rend(); ++c) pending.emplace_back(*c, self);
  }
}

void Converter::addOneNode(int index, int parent, Model& model) {
  if (index < 0 || size_t(index) >= gltfNodes_.size())
    fail("a scene or node refers to missing nodes[" + std::to_string(index) + "]");
  // A node is recorded before its children are visited, so a cycle meets it again too.
  if (nodes_[size_t(index)] >= 0)
    fail("nodes[" + std::to_string(index) +
         "] is reached twice (a cycle or shared child); the hierarchy must be a tree");
  const GltfNode& gn = gltfNodes_[size_t(index)];
  Node n;
  n.name = gn.name.empty() ? "node" + std::to_string(index) : gn.name;
  n.parent = parent;
  n.skin = gn.skin;  // a glTF skin index: every skin is loaded, in file order
  n.weights = gn.weights;
  n.translation = gn.translation;
  n.rotation = gn.rotation;
  n.scale = gn.scale;
  if (gn.mesh >= 0) {
    if (size_t(gn.mesh) >= g_.meshes.size())
      fail("nodes[" + std::to_string(index) + "] refers to a missing mesh");
    n.mesh = mesh(gn.mesh);
  }
  instances(index, gn, n);
  if (gn.camera >= 0) {
    if (size_t(gn.camera) >= g_.cameras.size())
      fail("nodes[" + std::to_string(index) + "] refers to a missing camera");
    n.camera = gn.camera;
  }
  nodes_[size_t(index)] = int(model.nodes.size());
  model.nodes.push_back(std::move(n));
}

// EXT_mesh_gpu_instancing: TRANSLATION, ROTATION and SCALE accessors of one count, each
// instance's transform T * R * S (glTF's node order), missing ones identity.
void Converter::instances(int index, const GltfNode& gn, Node& n) {
  if (gn.instancing.is_null()) return;
  const std::string what = "nodes[" + std::to_string(index) + "].extensions.EXT_mesh_gpu_instancing";
  if (gn.mesh < 0) return;  // nothing to instance
  if (gn.skin >= 0)
    fail(what + " instances a skinned mesh, which the extension leaves undefined; remove the "
                "skin or the instancing");
  const auto attrs = gn.instancing.find("attributes");
  if (!gn.instancing.is_object() || attrs == gn.instancing.end() || !attrs->is_object())
    fail(what + " has no attributes object; give TRANSLATION, ROTATION or SCALE accessors");
  std::vector<float> columns[3];
  const char* keys[3] = {"TRANSLATION", "ROTATION", "SCALE"};
  size_t count = 0;
  bool any = false;
  for (int k = 0; k < 3; ++k) {
    const auto v = attrs->find(keys[k]);
    if (v == attrs->end()) continue;
    if (!v->is_number_integer() || v->get<int64_t>() < INT32_MIN || v->get<int64_t>() > INT32_MAX)
      fail(what + ".attributes." + keys[k] + " must be an accessor index");
    const int comps = k == 1 ? 4 : 3;
    columns[k] = readAccessor(int(v->get<int64_t>()), what + ".attributes." + keys[k], comps);
    const size_t c = columns[k].size() / size_t(comps);
    if (any && c != count)
      fail(what + ".attributes." + keys[k] + " has " + std::to_string(c) +
           " elements where the others have " + std::to_string(count) +
           "; every attribute needs one per instance");
    count = c;
    any = true;
  }
  if (!any) fail(what + ".attributes has none of TRANSLATION, ROTATION and SCALE");
  n.instances.reserve(count);
  for (size_t i = 0; i < count; ++i) {
    glm::mat4 m(1.0f);
    if (!columns[0].empty()) m = glm::translate(m, glm::make_vec3(&columns[0][i * 3]));
    if (!columns[1].empty()) {
      const float* q = &columns[1][i * 4];
      m *= glm::mat4_cast(glm::normalize(glm::quat(q[3], q[0], q[1], q[2])));
    }
    if (!columns[2].empty()) m = glm::scale(m, glm::make_vec3(&columns[2][i * 3]));
    n.instances.push_back(m);
  }
}

void Converter::addAnimation(const tinygltf::Animation& a, size_t index, Model& model) {
  Animation out;
  out.name = a.name.empty() ? "animation" + std::to_string(index) : a.name;
  for (size_t c = 0; c < a.channels.size(); ++c) {
    const tinygltf::AnimationChannel& ch = a.channels[c];
    const std::string what =
        "animations[" + std::to_string(index) + "].channels[" + std::to_string(c) + "]";
    const int node = ch.target_node >= 0 && size_t(ch.target_node) < nodes_.size()
                         ? nodes_[size_t(ch.target_node)]
                         : -1;
    if (node < 0) continue;  // targets a node outside the default scene
    AnimChannel o;
    o.node = node;
    int comps = 3;
    if (ch.target_path == "translation")
      o.path = AnimPath::Translation;
    else if (ch.target_path == "rotation") {
      o.path = AnimPath::Rotation;
      comps = 4;
    } else if (ch.target_path == "scale") {
      o.path = AnimPath::Scale;
    } else if (ch.target_path == "weights") {
      o.path = AnimPath::Weights;
      const int mesh = model.nodes[size_t(o.node)].mesh;
      o.targets = mesh >= 0 ? int(s_.meshes[size_t(mesh)].targets.size()) : 0;
      if (o.targets == 0) continue;  // a node without morph targets: nothing to move
      comps = 1;
    } else {
      fail(what + " targets path '" + ch.target_path + "', which glTF 2.0 does not define");
    }
    if (ch.sampler < 0 || size_t(ch.sampler) >= a.samplers.size())
      fail(what + " refers to a missing sampler");
    const tinygltf::AnimationSampler& s = a.samplers[size_t(ch.sampler)];
    if (s.interpolation == "STEP")
      o.interpolation = Interpolation::Step;
    else if (s.interpolation == "CUBICSPLINE")
      o.interpolation = Interpolation::CubicSpline;
    else if (s.interpolation == "LINEAR" || s.interpolation.empty())
      o.interpolation = Interpolation::Linear;
    else
      fail(what + " interpolation '" + s.interpolation + "' is not LINEAR, STEP or CUBICSPLINE");
    o.times = readAccessor(s.input, what + " input", 1);
    const std::vector<float> values = readAccessor(s.output, what + " output", comps);
    const size_t per = o.interpolation == Interpolation::CubicSpline ? 3 : 1;
    if (o.path == AnimPath::Weights) {
      if (o.times.empty() || values.size() != o.times.size() * per * size_t(o.targets))
        fail(what + " has " + std::to_string(values.size()) + " weights for " +
             std::to_string(o.times.size()) + " keys of " + std::to_string(o.targets) +
             " morph targets; re-export it");
      o.weights = values;
    } else if (o.times.empty() || values.size() != o.times.size() * per * size_t(comps))
      fail(what + " has " + std::to_string(values.size() / size_t(comps)) + " output values for " +
           std::to_string(o.times.size()) + " keys; expected " +
           std::to_string(o.times.size() * per));
    for (size_t k = 1; k < o.times.size(); ++k)
      if (!(o.times[k] > o.times[k - 1])) fail(what + " key times must strictly increase");
    for (size_t i = 0; o.path != AnimPath::Weights && i < values.size() / size_t(comps); ++i)
      o.values.emplace_back(values[i * size_t(comps)], values[i * size_t(comps) + 1],
                            values[i * size_t(comps) + 2],
                            comps == 4 ? values[i * size_t(comps) + 3] : 0.0f);
    out.duration = std::max(out.duration, o.times.back());
    out.channels.push_back(std::move(o));
  }
  model.animations.push_back(std::move(out));
}

Model Converter::run() {
  Model model;
  model.name = file_.stem().string();
  std::vector<int> roots;
  if (!g_.scenes.empty()) {
    const int which =
        g_.defaultScene >= 0 && size_t(g_.defaultScene) < g_.scenes.size() ? g_.defaultScene : 0;
    roots = g_.scenes[size_t(which)].nodes;
  } else {
    // No scene: every node that is nobody's child is a root.
    std::vector<bool> child(gltfNodes_.size(), false);
    for (const GltfNode& n : gltfNodes_)
      for (int c : n.children)
        if (c >= 0 && size_t(c) < child.size()) child[size_t(c)] = true;
    for (size_t i = 0; i < gltfNodes_.size(); ++i)
      if (!child[i]) roots.push_back(int(i));
  }
  for (const tinygltf::Camera& c : g_.cameras) {
    Camera cam;
    cam.perspective = c.type == "perspective";
    if (cam.perspective) {
      cam.yfov = float(c.perspective.yfov);
      cam.znear = float(c.perspective.znear);
      cam.zfar = float(c.perspective.zfar);
    }
    model.cameras.push_back(cam);
  }
  model.nodes.reserve(gltfNodes_.size());  // at most every node, without regrowth copies
  for (int r : roots) addNode(r, model);
  // Without scenes every node belongs to the scene, and one that no root leads to lies on a
  // cycle (each node of it is another's child): refused, as a cycle below a root is.
  if (g_.scenes.empty())
    for (size_t i = 0; i < nodes_.size(); ++i)
      if (nodes_[i] < 0)
        fail(
            "nodes[" + std::to_string(i) +
            "] is on a cycle of children (no root node leads to it); the hierarchy must be a tree");
  if (model.nodes.empty())
    fail("has no nodes in its default scene; nothing would be drawn, add a node with a mesh");
  model.skins = readGltfSkins(file_, g_, nodes_);
  for (const Node& n : model.nodes)
    if (n.skin >= 0 && size_t(n.skin) >= model.skins.size())
      fail("node '" + n.name + "' refers to missing skins[" + std::to_string(n.skin) + "]");
  for (size_t i = 0; i < g_.animations.size(); ++i) addAnimation(g_.animations[i], i, model);
  return model;
}

}  // namespace taa::scene::gltf_detail
