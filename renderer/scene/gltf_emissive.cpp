// A glTF material's emission: emissiveFactor times KHR_materials_emissive_strength,
// added to the shaded colour by the raster, the deferred lighting pass and the adaptive
// tracer alike; an emissiveTexture (Material::emissiveTexture) multiplies it per texel.
#include <cmath>

#include "scene/gltf_convert.h"
#include "scene/scene_error.h"

namespace taa::scene {

glm::vec3 gltfEmissive(const std::filesystem::path& file, const tinygltf::Material& m,
                       const std::string& what) {
  glm::vec3 factor(0.0f);
  if (m.emissiveFactor.size() == 3)
    factor = glm::vec3(float(m.emissiveFactor[0]), float(m.emissiveFactor[1]),
                       float(m.emissiveFactor[2]));
  else if (!m.emissiveFactor.empty())
    throw SceneError(file, what + ".emissiveFactor must be an array of 3 numbers");
  for (int c = 0; c < 3; ++c)
    if (!(factor[c] >= 0.0f && factor[c] <= 1.0f))
      throw SceneError(file, what + ".emissiveFactor[" + std::to_string(c) +
                                 "] must lie in [0, 1]; scale brighter emission with "
                                 "KHR_materials_emissive_strength");
  float strength = 1.0f;
  if (const auto it = m.extensions.find("KHR_materials_emissive_strength");
      it != m.extensions.end()) {
    const std::string key = what + ".extensions.KHR_materials_emissive_strength.emissiveStrength";
    if (it->second.Has("emissiveStrength")) {
      const tinygltf::Value& v = it->second.Get("emissiveStrength");
      if (!v.IsNumber() && !v.IsInt() && !v.IsReal())
        throw SceneError(file, key + " must be a number");
      strength = float(v.GetNumberAsDouble());
      if (!(strength >= 0.0f && std::isfinite(strength)))
        throw SceneError(file, key + " must be a finite number >= 0");
    }
  }
  if (factor == glm::vec3(0.0f) || strength == 0.0f) return glm::vec3(0.0f);
  return factor * strength;
}

}  // namespace taa::scene
