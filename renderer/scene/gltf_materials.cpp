// The glTF converter's materials: base colour, alpha, sidedness, emission, the normal,
// emissive and occlusion textures with their UV sets and KHR_texture_transform, and
// KHR_materials_unlit. Textures (and their samplers) and meshes are gltf_convert.cpp's.
#include <cmath>

#include "scene/gltf_convert.h"
#include "scene/gltf_converter.h"

namespace taa::scene::gltf_detail {

// Each UV set's transform is baked into the primitive's coordinates (gltf_convert.cpp), so
// the textures of one material that sample one set must agree on its transform.
int Converter::textureRef(int material, int index, int texCoord,
                          const tinygltf::ExtensionMap& extensions, const std::string& what,
                          bool linear, int& uvSet) {
  const GltfTextureTransform t = gltfTextureTransform(file_, extensions, what);
  uvSet = t.texCoord >= 0 ? t.texCoord : texCoord;
  if (uvSet != 0 && uvSet != 1)
    fail(what + " samples TEXCOORD_" + std::to_string(uvSet) +
         "; TEXCOORD_0 and TEXCOORD_1 are supported, re-export with at most two UV sets");
  UvTransforms& sets = uvTransforms_[material];
  if (!sets.given[size_t(uvSet)]) {
    sets.given[size_t(uvSet)] = true;
    sets.uv[size_t(uvSet)] = t.uv;
  } else if (sets.uv[size_t(uvSet)] != t.uv) {
    fail(what + " has another KHR_texture_transform than the material's other textures on "
                "TEXCOORD_" + std::to_string(uvSet) +
         "; textures sharing a UV set share its transform here, give them the same one or "
         "move one to its own UV set");
  }
  return texture(index, what, linear);
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
    if (const auto& t = pbr.baseColorTexture; t.index >= 0)
      m.baseColorTexture = textureRef(index, t.index, t.texCoord, t.extensions,
                                      name + ".pbrMetallicRoughness.baseColorTexture", false,
                                      m.baseColorUv);
    if (gm.alphaMode == "MASK")
      m.alphaMode = AlphaMode::Mask;
    else if (gm.alphaMode == "BLEND")
      m.alphaMode = AlphaMode::Blend;
    else if (gm.alphaMode != "OPAQUE" && !gm.alphaMode.empty())
      fail(name + ".alphaMode '" + gm.alphaMode + "' is not OPAQUE, MASK or BLEND");
    m.alphaCutoff = float(gm.alphaCutoff);
    m.doubleSided = gm.doubleSided;
    m.unlit = gm.extensions.count("KHR_materials_unlit") > 0;
    if (const auto& t = gm.normalTexture; t.index >= 0) {
      if (!std::isfinite(t.scale))
        fail(name + ".normalTexture.scale is not a finite number; give a number such as 1");
      m.normalTexture = textureRef(index, t.index, t.texCoord, t.extensions,
                                   name + ".normalTexture", true, m.normalUv);
      m.normalScale = float(t.scale);
    }
    m.emissive = gltfEmissive(file_, gm, name);
    // Without an emissive factor the texture multiplies nothing: it is not loaded.
    if (const auto& t = gm.emissiveTexture; t.index >= 0 && m.emissive != glm::vec3(0.0f))
      m.emissiveTexture = textureRef(index, t.index, t.texCoord, t.extensions,
                                     name + ".emissiveTexture", false, m.emissiveUv);
    if (const auto& t = gm.occlusionTexture; t.index >= 0) {
      if (!(t.strength >= 0.0 && t.strength <= 1.0))
        fail(name + ".occlusionTexture.strength must lie in [0, 1]");
      m.occlusionTexture = textureRef(index, t.index, t.texCoord, t.extensions,
                                      name + ".occlusionTexture", true, m.occlusionUv);
      m.occlusionStrength = float(t.strength);
    }
  }
  s_.materials.push_back(m);
  return materials_[index] = int(s_.materials.size()) - 1;
}

}  // namespace taa::scene::gltf_detail
