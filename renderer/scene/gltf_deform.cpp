// Internal to the glTF loader: morph targets, joints and weights of primitives, and skins.
#include <algorithm>
#include <cmath>
#include <glm/gtc/type_ptr.hpp>

#include "scene/gltf_accessors.h"
#include "scene/gltf_convert.h"
#include "scene/scene_error.h"

namespace taa::scene {

namespace fs = std::filesystem;

GltfDeform readGltfDeform(const fs::path& file, const tinygltf::Model& g,
                          const tinygltf::Primitive& prim, const std::string& what, size_t count) {
  GltfDeform d;
  auto read = [&](int accessor, const std::string& name, int comps) {
    std::vector<float> v = readGltfAccessor(file, g, accessor, what + " " + name, comps);
    if (v.size() != count * size_t(comps))
      throw SceneError(file, what + " " + name + " has " +
                                 std::to_string(v.size() / size_t(comps)) + " elements for " +
                                 std::to_string(count) + " vertices; re-export it");
    return v;
  };
  for (size_t t = 0; t < prim.targets.size(); ++t) {
    const auto& target = prim.targets[t];
    const std::string name = "targets[" + std::to_string(t) + "]";
    std::vector<float> pos, nrm;
    if (auto a = target.find("POSITION"); a != target.end())
      pos = read(a->second, name + ".POSITION", 3);
    if (auto a = target.find("NORMAL"); a != target.end())
      nrm = read(a->second, name + ".NORMAL", 3);
    d.positions.push_back(std::move(pos));
    d.normals.push_back(std::move(nrm));
  }
  for (const char* extra : {"JOINTS_1", "WEIGHTS_1"})
    if (prim.attributes.count(extra))
      throw SceneError(file, what + " has " + extra +
                                 ": more than four joints per vertex are not supported; "
                                 "re-export with at most four influences per vertex");
  const auto j = prim.attributes.find("JOINTS_0");
  const auto w = prim.attributes.find("WEIGHTS_0");
  if ((j == prim.attributes.end()) != (w == prim.attributes.end()))
    throw SceneError(file, what +
                               " has only one of JOINTS_0 and WEIGHTS_0; a skinned primitive "
                               "needs both, re-export it");
  if (j != prim.attributes.end()) {
    d.joints = read(j->second, "JOINTS_0", 4);
    // Joint indices are whole and unsigned only in these types (glTF 2.0, 3.7.3.1): another
    // type gives negative, fractional or huge floats, which no joint index can hold.
    const tinygltf::Accessor& a = g.accessors[size_t(j->second)];
    if ((a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_BYTE &&
         a.componentType != TINYGLTF_COMPONENT_TYPE_UNSIGNED_SHORT) ||
        a.normalized)
      throw SceneError(file, what + " JOINTS_0 (accessors[" + std::to_string(j->second) +
                                 "]) has componentType " + std::to_string(a.componentType) +
                                 (a.normalized ? ", normalized" : "") +
                                 "; joint indices are unsigned bytes (5121) or unsigned shorts "
                                 "(5123), not normalized: re-export it");
    d.weights = read(w->second, "WEIGHTS_0", 4);
    d.weightFixes = normaliseSkinWeights(d.weights);
  }
  return d;
}

void SkinWeightFixes::add(const SkinWeightFixes& o) {
  if (o.scaled > 0) {
    lowest = scaled > 0 ? std::min(lowest, o.lowest) : o.lowest;
    highest = scaled > 0 ? std::max(highest, o.highest) : o.highest;
  }
  scaled += o.scaled;
  unweighted += o.unweighted;
}

SkinWeightFixes normaliseSkinWeights(std::vector<float>& weights) {
  SkinWeightFixes f;
  for (size_t i = 0; i + 3 < weights.size(); i += 4) {
    float* w = &weights[i];
    const float sum = w[0] + w[1] + w[2] + w[3];
    if (std::fabs(sum - 1.0f) <= kSkinWeightTolerance) continue;
    if (!(sum > 0.0f)) {  // none (or a sum no scale can mend): the bind pose, as engines keep it
      if (w[0] != 0.0f || w[1] != 0.0f || w[2] != 0.0f || w[3] != 0.0f || sum != 0.0f)
        std::fill(w, w + 4, 0.0f);
      ++f.unweighted;
      continue;
    }
    for (int k = 0; k < 4; ++k) w[k] /= sum;
    if (std::fabs(sum - 1.0f) <= kSkinWeightNoteTolerance) continue;
    f.lowest = f.scaled > 0 ? std::min(f.lowest, sum) : sum;
    f.highest = f.scaled > 0 ? std::max(f.highest, sum) : sum;
    ++f.scaled;
  }
  return f;
}

void appendGltfDeform(const GltfDeform& d, const std::vector<uint32_t>& source, size_t before,
                      Mesh& mesh) {
  if (d.positions.size() > mesh.targets.size()) mesh.targets.resize(d.positions.size());
  for (size_t t = 0; t < mesh.targets.size(); ++t) {
    MorphTarget& mt = mesh.targets[t];
    const bool pos = t < d.positions.size() && !d.positions[t].empty();
    const bool nrm = t < d.normals.size() && !d.normals[t].empty();
    mt.position.resize(before, glm::vec3(0.0f));
    if (nrm || !mt.normal.empty()) mt.normal.resize(before, glm::vec3(0.0f));
    for (const uint32_t i : source) {
      mt.position.push_back(pos ? glm::make_vec3(&d.positions[t][size_t(i) * 3]) : glm::vec3(0.0f));
      if (nrm || !mt.normal.empty())
        mt.normal.push_back(nrm ? glm::make_vec3(&d.normals[t][size_t(i) * 3]) : glm::vec3(0.0f));
    }
  }
  if (d.joints.empty() && mesh.skin.empty()) return;
  mesh.skin.resize(before);
  for (const uint32_t i : source) {
    SkinWeights sw;
    if (!d.joints.empty()) {
      sw.joints = glm::uvec4(glm::make_vec4(&d.joints[size_t(i) * 4]));
      sw.weights = glm::make_vec4(&d.weights[size_t(i) * 4]);
    }
    mesh.skin.push_back(sw);
  }
}

std::vector<Skin> readGltfSkins(const fs::path& file, const tinygltf::Model& g,
                                const std::vector<int>& nodes) {
  std::vector<Skin> out;
  for (size_t k = 0; k < g.skins.size(); ++k) {
    const tinygltf::Skin& gs = g.skins[k];
    const std::string what = "skins[" + std::to_string(k) + "]";
    Skin skin;
    for (const int joint : gs.joints) {
      const int n = joint >= 0 && size_t(joint) < nodes.size() ? nodes[size_t(joint)] : -1;
      if (n < 0)
        throw SceneError(file, what + " names joint nodes[" + std::to_string(joint) +
                                   "], which is not in the default scene; put the skeleton in "
                                   "the scene");
      skin.joints.push_back(n);
    }
    if (gs.inverseBindMatrices >= 0) {
      const std::vector<float> m =
          readGltfAccessor(file, g, gs.inverseBindMatrices, what + " inverseBindMatrices", 16);
      if (m.size() != skin.joints.size() * 16)
        throw SceneError(file, what + " has " + std::to_string(m.size() / 16) +
                                   " inverse bind matrices for " +
                                   std::to_string(skin.joints.size()) + " joints; re-export it");
      for (size_t j = 0; j < skin.joints.size(); ++j)
        skin.inverseBind.push_back(glm::make_mat4(&m[j * 16]));
    } else {
      skin.inverseBind.assign(skin.joints.size(), glm::mat4(1.0f));
    }
    out.push_back(std::move(skin));
  }
  return out;
}

}  // namespace taa::scene
