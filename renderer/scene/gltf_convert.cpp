#include "scene/gltf_convert.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <map>

#include "scene/gltf_accessors.h"
#include "scene/scene_error.h"
#include "scene/textures.h"

namespace taa::scene {
namespace {

namespace fs = std::filesystem;

class Converter {
 public:
  Converter(const fs::path& file, const tinygltf::Model& g, const std::string& warnings, Scene& s)
      : file_(file), g_(g), warnings_(warnings), s_(s) {}
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
  int material(int index);
  void normalTexture(int index, const tinygltf::Material& gm, const std::string& name, Material& m);
  int mesh(int index);
  void addNode(int root, Model& model);
  void addOneNode(int index, int parent, Model& model);
  void addAnimation(const tinygltf::Animation& a, size_t index, Model& model);

  const fs::path& file_;
  const tinygltf::Model& g_;
  const std::string& warnings_;
  Scene& s_;
  std::map<int, int> textures_, materials_, meshes_, nodes_;
  std::map<int, glm::mat3> uvTransforms_;  // per glTF material: its base colour's UV transform
};

int Converter::texture(int index, const std::string& what, bool linear) {
  const int key = linear ? -2 - index : index;
  if (auto it = textures_.find(key); it != textures_.end()) return it->second;
  if (index < 0 || size_t(index) >= g_.textures.size()) fail(what + " refers to a missing texture");
  const tinygltf::Texture& t = g_.textures[size_t(index)];
  if (t.source < 0) return textures_[key] = -1;  // only an extension's image (e.g. KTX2)
  const std::string tex = "textures[" + std::to_string(index) + "]";
  if (size_t(t.source) >= g_.images.size())
    fail(tex + ".source " + std::to_string(t.source) + " refers to a missing image (the file has " +
         std::to_string(g_.images.size()) + "); the file is corrupt, re-export it");
  if (t.sampler >= 0 && size_t(t.sampler) >= g_.samplers.size())
    fail(tex + ".sampler " + std::to_string(t.sampler) +
         " refers to a missing sampler (the file has " + std::to_string(g_.samplers.size()) +
         "); the file is corrupt, re-export it");
  const tinygltf::Image& img = g_.images[size_t(t.source)];
  const std::string name =
      "images[" + std::to_string(t.source) + "]" + (img.uri.empty() ? "" : " '" + img.uri + "'");
  if (img.image.empty() || img.width <= 0 || img.height <= 0)
    fail(name + " could not be read or decoded (" + (warnings_.empty() ? "no detail" : warnings_) +
         "); put a PNG or JPEG file inside the glTF's folder or embed it");
  if (img.component != 4 || (img.bits != 8 && img.bits != 16))
    fail(name + " decoded to " + std::to_string(img.component) + " channels of " +
         std::to_string(img.bits) + " bits; convert it to an 8-bit RGB(A) PNG");
  const size_t texels = size_t(img.width) * size_t(img.height) * 4;
  if (img.image.size() < texels * size_t(img.bits / 8))
    fail(name + " decoded to fewer bytes than its size needs; the image is corrupt");
  std::vector<uint8_t> rgba(texels);
  if (img.bits == 8) {
    std::copy_n(img.image.begin(), texels, rgba.begin());
  } else {
    for (size_t i = 0; i < texels; ++i) {
      uint16_t v;
      std::memcpy(&v, img.image.data() + 2 * i, 2);
      rgba[i] = uint8_t((uint32_t(v) * 255u + 32767u) / 65535u);
    }
  }
  bool repeat = true;
  if (t.sampler >= 0) {
    const tinygltf::Sampler& sm = g_.samplers[size_t(t.sampler)];
    // One wrap mode per texture: clamp only when both axes clamp; mirrored repeat repeats.
    repeat = !(sm.wrapS == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE &&
               sm.wrapT == TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE);
  }
  s_.textures.push_back(makeTexture(img.width, img.height, std::move(rgba), repeat, linear));
  return textures_[key] = int(s_.textures.size()) - 1;
}

// The UVs are shared (the base colour's KHR_texture_transform is baked into them), so a
// normal texture must use TEXCOORD_0 and the same transform as the base colour.
void Converter::normalTexture(int index, const tinygltf::Material& gm, const std::string& name,
                              Material& m) {
  const tinygltf::NormalTextureInfo& info = gm.normalTexture;
  if (info.index < 0) return;
  if (info.texCoord != 0)
    fail(name + ".normalTexture uses TEXCOORD_" + std::to_string(info.texCoord) +
         "; only TEXCOORD_0 is supported, re-export with one UV set");
  const glm::mat3 own = gltfTextureTransform(file_, info.extensions, name + ".normalTexture");
  const auto base = uvTransforms_.find(index);
  const glm::mat3 shared = base != uvTransforms_.end() ? base->second : glm::mat3(1.0f);
  if (own != shared)
    fail(name +
         ".normalTexture has another KHR_texture_transform than the base colour; the two share "
         "one set of UVs here, give both the same transform");
  if (base == uvTransforms_.end() && own != glm::mat3(1.0f)) uvTransforms_[index] = own;
  if (!std::isfinite(info.scale))
    fail(name + ".normalTexture.scale is not a finite number; give a number such as 1");
  m.normalTexture = texture(info.index, name + ".normalTexture", true);
  m.normalScale = float(info.scale);
}

int Converter::material(int index) {
  if (auto it = materials_.find(index); it != materials_.end()) return it->second;
  Material m;  // index -1: the glTF default material (white, opaque, single-sided)
  if (index >= 0) {
    if (size_t(index) >= g_.materials.size())
      fail("a primitive refers to missing materials[" + std::to_string(index) + "]");
    const tinygltf::Material& gm = g_.materials[size_t(index)];
    const std::string name = "materials[" + std::to_string(index) + "]";
    const auto& pbr = gm.pbrMetallicRoughness;
    if (pbr.baseColorFactor.size() == 4)
      m.baseColorFactor = glm::vec4(float(pbr.baseColorFactor[0]), float(pbr.baseColorFactor[1]),
                                    float(pbr.baseColorFactor[2]), float(pbr.baseColorFactor[3]));
    if (pbr.baseColorTexture.index >= 0) {
      if (pbr.baseColorTexture.texCoord != 0)
        fail(name + " samples its base colour with TEXCOORD_" +
             std::to_string(pbr.baseColorTexture.texCoord) +
             "; only TEXCOORD_0 is supported, re-export with one UV set");
      m.baseColorTexture = texture(pbr.baseColorTexture.index, name + ".baseColorTexture");
      uvTransforms_[index] = gltfTextureTransform(file_, pbr.baseColorTexture.extensions,
                                                  name + ".pbrMetallicRoughness.baseColorTexture");
    }
    if (gm.alphaMode == "MASK")
      m.alphaMode = AlphaMode::Mask;
    else if (gm.alphaMode == "BLEND")
      m.alphaMode = AlphaMode::Blend;
    else if (gm.alphaMode != "OPAQUE" && !gm.alphaMode.empty())
      fail(name + ".alphaMode '" + gm.alphaMode + "' is not OPAQUE, MASK or BLEND");
    normalTexture(index, gm, name, m);
    m.alphaCutoff = float(gm.alphaCutoff);
    m.doubleSided = gm.doubleSided;
    std::string note;
    m.emissive = gltfEmissive(file_, gm, name, note);
    note = note.empty() ? "" : file_.string() + ": " + note;
    if (!note.empty() && std::find(s_.notes.begin(), s_.notes.end(), note) == s_.notes.end())
      s_.notes.push_back(note);
  }
  s_.materials.push_back(m);
  return materials_[index] = int(s_.materials.size()) - 1;
}

// Triangle-list indices of a primitive in any of the three triangle modes.
std::vector<uint32_t> triangleList(int mode, std::vector<uint32_t> idx) {
  if (mode == TINYGLTF_MODE_TRIANGLES) {
    idx.resize(idx.size() - idx.size() % 3);
    return idx;
  }
  std::vector<uint32_t> out;
  for (size_t i = 2; i < idx.size(); ++i) {
    if (mode == TINYGLTF_MODE_TRIANGLE_FAN)
      out.insert(out.end(), {idx[0], idx[i - 1], idx[i]});
    else if (i % 2 == 0)
      out.insert(out.end(), {idx[i - 2], idx[i - 1], idx[i]});
    else
      out.insert(out.end(), {idx[i - 1], idx[i - 2], idx[i]});  // keep odd strip triangles CCW
  }
  return out;
}

int Converter::mesh(int index) {
  if (auto it = meshes_.find(index); it != meshes_.end()) return it->second;
  const tinygltf::Mesh& gm = g_.meshes[size_t(index)];  // the caller checked the index
  Mesh out;
  out.name = gm.name.empty() ? "mesh" + std::to_string(index) : gm.name;
  out.firstVertex = uint32_t(s_.vertices.size());
  for (double w : gm.weights) out.weights.push_back(float(w));
  bool any = false;
  for (size_t p = 0; p < gm.primitives.size(); ++p) {
    const tinygltf::Primitive& prim = gm.primitives[p];
    const std::string what =
        "meshes[" + std::to_string(index) + "].primitives[" + std::to_string(p) + "]";
    if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != TINYGLTF_MODE_TRIANGLE_STRIP &&
        prim.mode != TINYGLTF_MODE_TRIANGLE_FAN && prim.mode != -1)
      fail(what + " draws points or lines (mode " + std::to_string(prim.mode) +
           "); only triangles are rendered, remove the primitive or triangulate it");
    const auto pos = prim.attributes.find("POSITION");
    if (pos == prim.attributes.end())
      fail(what + " has no POSITION attribute; every primitive needs one");
    const std::vector<float> positions = readAccessor(pos->second, what + " POSITION", 3);
    const size_t count = positions.size() / 3;
    std::vector<float> normals, uvs;
    if (auto n = prim.attributes.find("NORMAL"); n != prim.attributes.end())
      normals = readAccessor(n->second, what + " NORMAL", 3);
    if (auto t = prim.attributes.find("TEXCOORD_0"); t != prim.attributes.end())
      uvs = readAccessor(t->second, what + " TEXCOORD_0", 2);
    material(prim.material);  // loads the material's texture transform, baked into the UVs
    if (auto m = uvTransforms_.find(prim.material); m != uvTransforms_.end())
      for (size_t i = 0; i + 1 < uvs.size(); i += 2) {
        const glm::vec3 uv = m->second * glm::vec3(uvs[i], uvs[i + 1], 1.0f);
        uvs[i] = uv.x;
        uvs[i + 1] = uv.y;
      }
    std::vector<float> colors;
    int colorComps = 4;
    if (auto c = prim.attributes.find("COLOR_0"); c != prim.attributes.end()) {
      if (c->second >= 0 && size_t(c->second) < g_.accessors.size() &&
          g_.accessors[size_t(c->second)].type == TINYGLTF_TYPE_VEC3)
        colorComps = 3;
      colors = readAccessor(c->second, what + " COLOR_0", colorComps);
      out.vertexColors = true;
    }
    if ((!normals.empty() && normals.size() != count * 3) ||
        (!uvs.empty() && uvs.size() != count * 2) ||
        (!colors.empty() && colors.size() != count * size_t(colorComps)))
      fail(what + " has attributes of different lengths; re-export it");
    const GltfDeform deform = readGltfDeform(file_, g_, prim, what, count);
    std::vector<uint32_t> idx;
    if (prim.indices >= 0) {
      idx = readIndices(prim.indices, what);
    } else {
      idx.resize(count);
      for (size_t i = 0; i < count; ++i) idx[i] = uint32_t(i);
    }
    for (uint32_t i : idx)
      if (i >= count) fail(what + " has an index past its vertex count; the file is corrupt");
    idx = triangleList(prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode, std::move(idx));
    auto vertexAt = [&](uint32_t i) {
      Vertex v{};
      v.position = glm::make_vec3(&positions[size_t(i) * 3]);
      if (!normals.empty()) {
        const glm::vec3 n = glm::make_vec3(&normals[size_t(i) * 3]);
        v.normal = glm::dot(n, n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 0.0f, 1.0f);
      }
      if (!uvs.empty()) v.uv = glm::make_vec2(&uvs[size_t(i) * 2]);
      if (!colors.empty()) {
        const float* c = &colors[size_t(i) * size_t(colorComps)];
        v.color = glm::vec4(c[0], c[1], c[2], colorComps == 4 ? c[3] : 1.0f);
      }
      return v;
    };
    std::vector<uint32_t> source;  // the primitive's vertex each emitted vertex copies
    Primitive out_prim;
    out_prim.vertexOffset = int32_t(s_.vertices.size());
    out_prim.firstIndex = uint32_t(s_.indices.size());
    out_prim.material = material(prim.material);
    if (normals.empty()) {
      // The spec asks for flat normals, so every triangle gets its own three vertices.
      for (size_t t = 0; t + 2 < idx.size(); t += 3) {
        Vertex v[3] = {vertexAt(idx[t]), vertexAt(idx[t + 1]), vertexAt(idx[t + 2])};
        glm::vec3 n = glm::cross(v[1].position - v[0].position, v[2].position - v[0].position);
        n = glm::dot(n, n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 0.0f, 1.0f);
        for (int j = 0; j < 3; ++j) source.push_back(idx[t + size_t(j)]);
        for (Vertex& x : v) {
          x.normal = n;
          s_.indices.push_back(uint32_t(s_.vertices.size()) - uint32_t(out_prim.vertexOffset));
          s_.vertices.push_back(x);
        }
      }
    } else {
      for (size_t i = 0; i < count; ++i) {
        s_.vertices.push_back(vertexAt(uint32_t(i)));
        source.push_back(uint32_t(i));
      }
      s_.indices.insert(s_.indices.end(), idx.begin(), idx.end());
    }
    appendGltfDeform(deform, source, s_.vertices.size() - out.firstVertex - source.size(), out);
    out_prim.indexCount = uint32_t(s_.indices.size()) - out_prim.firstIndex;
    for (size_t i = 0; i < count; ++i) {
      const glm::vec3 q = glm::make_vec3(&positions[i * 3]);
      out.boundsMin = any ? glm::min(out.boundsMin, q) : q;
      out.boundsMax = any ? glm::max(out.boundsMax, q) : q;
      any = true;
    }
    out.primitives.push_back(out_prim);
  }
  out.vertexCount = uint32_t(s_.vertices.size()) - out.firstVertex;
  if (!out.targets.empty()) out.weights.resize(out.targets.size(), 0.0f);
  if (std::all_of(out.skin.begin(), out.skin.end(),
                  [](const SkinWeights& w) { return w.weights == glm::vec4(0.0f); }))
    out.skin.clear();
  s_.meshes.push_back(std::move(out));
  return meshes_[index] = int(s_.meshes.size()) - 1;
}

}  // namespace

namespace {

// Depth-first with an explicit stack, parents before children in file order: a chain of
// 100,000 nodes must not exhaust the call stack.
void Converter::addNode(int root, Model& model) {
  std::vector<std::pair<int, int>> pending{{root, -1}};  // (glTF index, parent's model index)
  while (!pending.empty()) {
    const auto [index, parent] = pending.back();
    pending.pop_back();
    addOneNode(index, parent, model);
    const std::vector<int>& children = g_.nodes[size_t(index)].children;
    const int self = int(model.nodes.size()) - 1;
    for (auto c = children.rbegin(); c != children.rend(); ++c) pending.emplace_back(*c, self);
  }
}

void Converter::addOneNode(int index, int parent, Model& model) {
  if (index < 0 || size_t(index) >= g_.nodes.size())
    fail("a scene or node refers to missing nodes[" + std::to_string(index) + "]");
  // A node is recorded before its children are visited, so a cycle meets it again too.
  if (nodes_.count(index))
    fail("nodes[" + std::to_string(index) +
         "] is reached twice (a cycle or shared child); the hierarchy must be a tree");
  const tinygltf::Node& gn = g_.nodes[size_t(index)];
  Node n;
  n.name = gn.name.empty() ? "node" + std::to_string(index) : gn.name;
  n.parent = parent;
  n.skin = gn.skin;  // a glTF skin index: every skin is loaded, in file order
  for (double w : gn.weights) n.weights.push_back(float(w));
  if (gn.matrix.size() == 16) {
    glm::mat4 m;
    for (int i = 0; i < 16; ++i) m[i / 4][i % 4] = float(gn.matrix[size_t(i)]);
    decomposeTrs(m, n.translation, n.rotation, n.scale);
  } else {
    if (gn.translation.size() == 3)
      n.translation =
          glm::vec3(float(gn.translation[0]), float(gn.translation[1]), float(gn.translation[2]));
    if (gn.rotation.size() == 4)
      n.rotation = glm::quat(float(gn.rotation[3]), float(gn.rotation[0]), float(gn.rotation[1]),
                             float(gn.rotation[2]));
    if (gn.scale.size() == 3)
      n.scale = glm::vec3(float(gn.scale[0]), float(gn.scale[1]), float(gn.scale[2]));
  }
  if (gn.mesh >= 0) {
    if (size_t(gn.mesh) >= g_.meshes.size())
      fail("nodes[" + std::to_string(index) + "] refers to a missing mesh");
    n.mesh = mesh(gn.mesh);
  }
  if (gn.camera >= 0) {
    if (size_t(gn.camera) >= g_.cameras.size())
      fail("nodes[" + std::to_string(index) + "] refers to a missing camera");
    n.camera = gn.camera;
  }
  nodes_[index] = int(model.nodes.size());
  model.nodes.push_back(std::move(n));
}

void Converter::addAnimation(const tinygltf::Animation& a, size_t index, Model& model) {
  Animation out;
  out.name = a.name.empty() ? "animation" + std::to_string(index) : a.name;
  for (size_t c = 0; c < a.channels.size(); ++c) {
    const tinygltf::AnimationChannel& ch = a.channels[c];
    const std::string what =
        "animations[" + std::to_string(index) + "].channels[" + std::to_string(c) + "]";
    const auto node = nodes_.find(ch.target_node);
    if (node == nodes_.end()) continue;  // targets a node outside the default scene
    AnimChannel o;
    o.node = node->second;
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
    std::vector<bool> child(g_.nodes.size(), false);
    for (const auto& n : g_.nodes)
      for (int c : n.children)
        if (c >= 0 && size_t(c) < child.size()) child[size_t(c)] = true;
    for (size_t i = 0; i < g_.nodes.size(); ++i)
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
  for (int r : roots) addNode(r, model);
  if (model.nodes.empty())
    fail("has no nodes in its default scene; nothing would be drawn, add a node with a mesh");
  model.skins = readGltfSkins(file_, g_, nodes_);
  for (const Node& n : model.nodes)
    if (n.skin >= 0 && size_t(n.skin) >= model.skins.size())
      fail("node '" + n.name + "' refers to missing skins[" + std::to_string(n.skin) + "]");
  for (size_t i = 0; i < g_.animations.size(); ++i) addAnimation(g_.animations[i], i, model);
  return model;
}

}  // namespace

void decomposeTrs(const glm::mat4& m, glm::vec3& t, glm::quat& r, glm::vec3& s) {
  t = glm::vec3(m[3]);
  glm::mat3 basis(m);
  s = glm::vec3(glm::length(basis[0]), glm::length(basis[1]), glm::length(basis[2]));
  if (glm::determinant(basis) < 0.0f) s.x = -s.x;
  if (s.x == 0.0f || s.y == 0.0f || s.z == 0.0f) {
    r = glm::quat(1.0f, 0.0f, 0.0f, 0.0f);  // a collapsed axis has no recoverable rotation
    return;
  }
  for (int i = 0; i < 3; ++i) basis[i] /= s[i];
  r = glm::normalize(glm::quat_cast(basis));
}

Model convertGltf(const fs::path& file, const tinygltf::Model& gltf, const std::string& warnings,
                  Scene& scene) {
  return Converter(file, gltf, warnings, scene).run();
}

}  // namespace taa::scene
