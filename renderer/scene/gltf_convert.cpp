#include "scene/gltf_convert.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <glm/geometric.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/matrix.hpp>
#include <map>

#include "scene/gltf_converter.h"
#include "scene/textures.h"

namespace taa::scene::gltf_detail {

namespace fs = std::filesystem;

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
  const TextureSampler sampler =
      t.sampler >= 0 ? gltfSampler(t.sampler) : TextureSampler{};
  s_.textures.push_back(makeTexture(img.width, img.height, std::move(rgba), sampler, linear));
  return textures_[key] = int(s_.textures.size()) - 1;
}

// glTF's sampler enums (WebGL's values) as ours; anything else is refused by name.
TextureSampler Converter::gltfSampler(int index) const {
  const tinygltf::Sampler& sm = g_.samplers[size_t(index)];
  const std::string name = "samplers[" + std::to_string(index) + "]";
  auto wrap = [&](int mode, const char* key) {
    switch (mode) {
      case TINYGLTF_TEXTURE_WRAP_REPEAT:
        return Wrap::Repeat;
      case TINYGLTF_TEXTURE_WRAP_CLAMP_TO_EDGE:
        return Wrap::ClampToEdge;
      case TINYGLTF_TEXTURE_WRAP_MIRRORED_REPEAT:
        return Wrap::MirroredRepeat;
      default:
        fail(name + "." + key + " is " + std::to_string(mode) +
             ", not 10497 (REPEAT), 33071 (CLAMP_TO_EDGE) or 33648 (MIRRORED_REPEAT)");
    }
  };
  TextureSampler out;
  out.wrapS = wrap(sm.wrapS, "wrapS");
  out.wrapT = wrap(sm.wrapT, "wrapT");
  if (sm.magFilter == TINYGLTF_TEXTURE_FILTER_NEAREST)
    out.mag = Filter::Nearest;
  else if (sm.magFilter != TINYGLTF_TEXTURE_FILTER_LINEAR && sm.magFilter != -1)
    fail(name + ".magFilter is " + std::to_string(sm.magFilter) +
         ", not 9728 (NEAREST) or 9729 (LINEAR)");
  switch (sm.minFilter) {
    case -1:  // undefined: the viewer's choice, trilinear here
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_LINEAR:
      break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST:
      out.min = Filter::Nearest;
      out.mip = MipFilter::None;
      break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR:
      out.mip = MipFilter::None;
      break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_NEAREST:
      out.min = Filter::Nearest;
      out.mip = MipFilter::Nearest;
      break;
    case TINYGLTF_TEXTURE_FILTER_LINEAR_MIPMAP_NEAREST:
      out.mip = MipFilter::Nearest;
      break;
    case TINYGLTF_TEXTURE_FILTER_NEAREST_MIPMAP_LINEAR:
      out.min = Filter::Nearest;
      break;
    default:
      fail(name + ".minFilter is " + std::to_string(sm.minFilter) +
           ", not one of glTF's six (9728, 9729, 9984, 9985, 9986, 9987)");
  }
  return out;
}

namespace {

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

// The run log's word on what normaliseSkinWeights did to one mesh, or "" if nothing.
std::string skinWeightNote(const SkinWeightFixes& f, const std::string& name, int index) {
  if (f.scaled == 0 && f.unweighted == 0) return "";
  auto sum = [](float v) {
    char buf[32];
    std::snprintf(buf, sizeof(buf), "%.3g", double(v));
    return std::string(buf);
  };
  std::string out = "mesh '" + name + "' (meshes[" + std::to_string(index) + "]): ";
  if (f.scaled > 0)
    out += std::to_string(f.scaled) + " vertices have skin weights summing to " +
           (f.lowest == f.highest ? sum(f.lowest) : sum(f.lowest) + " to " + sum(f.highest)) +
           ", not one: normalised, as engines do";
  if (f.unweighted > 0)
    out += std::string(f.scaled > 0 ? "; " : "") + std::to_string(f.unweighted) +
           " vertices have no skin weight and keep their bind pose";
  return out;
}

}  // namespace

int Converter::mesh(int index) {
  if (auto it = meshes_.find(index); it != meshes_.end()) return it->second;
  const tinygltf::Mesh& gm = g_.meshes[size_t(index)];  // the caller checked the index
  Mesh out;
  out.name = gm.name.empty() ? "mesh" + std::to_string(index) : gm.name;
  out.firstVertex = uint32_t(s_.vertices.size());
  for (double w : gm.weights) out.weights.push_back(float(w));
  bool any = false;
  SkinWeightFixes weightFixes;
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
    std::vector<float> normals, uvs, uvs1;
    if (auto n = prim.attributes.find("NORMAL"); n != prim.attributes.end())
      normals = readAccessor(n->second, what + " NORMAL", 3);
    if (auto t = prim.attributes.find("TEXCOORD_0"); t != prim.attributes.end())
      uvs = readAccessor(t->second, what + " TEXCOORD_0", 2);
    if (auto t = prim.attributes.find("TEXCOORD_1"); t != prim.attributes.end())
      uvs1 = readAccessor(t->second, what + " TEXCOORD_1", 2);
    // Loads the material's texture transforms, baked into each UV set it samples.
    const Material& mat = s_.materials[size_t(material(prim.material))];
    if (uvs1.empty() && (mat.baseColorUv == 1 || mat.normalUv == 1 || mat.emissiveUv == 1 ||
                         mat.occlusionUv == 1))
      fail(what + " has no TEXCOORD_1, which a texture of materials[" +
           std::to_string(prim.material) + "] samples; add the UV set or use TEXCOORD_0");
    if (auto m = uvTransforms_.find(prim.material); m != uvTransforms_.end())
      for (int set = 0; set < 2; ++set) {
        std::vector<float>& coords = set == 0 ? uvs : uvs1;
        const glm::mat3& t = m->second.uv[set];
        for (size_t i = 0; t != glm::mat3(1.0f) && i + 1 < coords.size(); i += 2) {
          const glm::vec3 uv = t * glm::vec3(coords[i], coords[i + 1], 1.0f);
          coords[i] = uv.x;
          coords[i + 1] = uv.y;
        }
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
        (!uvs1.empty() && uvs1.size() != count * 2) ||
        (!colors.empty() && colors.size() != count * size_t(colorComps)))
      fail(what + " has attributes of different lengths; re-export it");
    const GltfDeform deform = readGltfDeform(file_, g_, prim, what, count);
    weightFixes.add(deform.weightFixes);
    std::vector<uint32_t> idx;
    if (prim.indices >= 0) {
      idx = readIndices(prim.indices, what);
    } else {
      idx.resize(count);
      for (size_t i = 0; i < count; ++i) idx[i] = uint32_t(i);
    }
    for (uint32_t i : idx)
      if (i >= count)
        fail(what + " has index " + std::to_string(i) +
             (prim.indices >= 0 ? " (accessor " + std::to_string(prim.indices) + ")" : "") +
             ", past its " + std::to_string(count) + " vertices; the file is corrupt");
    idx = triangleList(prim.mode < 0 ? TINYGLTF_MODE_TRIANGLES : prim.mode, std::move(idx));
    auto vertexAt = [&](uint32_t i) {
      Vertex v{};
      v.position = glm::make_vec3(&positions[size_t(i) * 3]);
      if (!normals.empty()) {
        const glm::vec3 n = glm::make_vec3(&normals[size_t(i) * 3]);
        v.normal = glm::dot(n, n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 0.0f, 1.0f);
      }
      if (!uvs.empty()) v.uv = glm::make_vec2(&uvs[size_t(i) * 2]);
      if (!uvs1.empty()) v.uv1 = glm::make_vec2(&uvs1[size_t(i) * 2]);
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
  if (const std::string note = skinWeightNote(weightFixes, out.name, index); !note.empty())
    s_.notes.push_back(file_.filename().string() + ": " + note);
  if (!out.targets.empty()) out.weights.resize(out.targets.size(), 0.0f);
  if (std::all_of(out.skin.begin(), out.skin.end(),
                  [](const SkinWeights& w) { return w.weights == glm::vec4(0.0f); }))
    out.skin.clear();
  s_.meshes.push_back(std::move(out));
  return meshes_[index] = int(s_.meshes.size()) - 1;
}

}  // namespace taa::scene::gltf_detail

namespace taa::scene {

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

Model convertGltf(const std::filesystem::path& file, const tinygltf::Model& gltf,
                  const std::vector<GltfNode>& nodes, const std::string& warnings, Scene& scene) {
  return gltf_detail::Converter(file, gltf, nodes, warnings, scene).run();
}

}  // namespace taa::scene
